// A short rational strictly inside an open interval: the one choice of an exact sample point, for
// the certificates' multipliers and the motions' sample times.
#pragma once

#include <optional>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// What "short" means to a caller of rational_inside.
enum class Shortest {
  /// The dyadic with the fewest bits (the midpoint rounded to 0, 4, 8, ... fractional bits; the
  /// midpoint itself past 2048): a certificate's multiplier, whose powers of two keep the integer
  /// forms of lambda P + E short and make its exact signs cheap.
  Bits,
  /// The simplest rational, smallest denominator then smallest magnitude (continued fractions, the
  /// Stern-Brocot descent): a motion's sample time, printed in its timeline.
  Denominator,
};

/// A rational in the open interval (lo, hi), lo < hi, short in the given sense. hi empty means
/// +infinity (Shortest::Denominator only).
Rational rational_inside(const Rational& lo, const std::optional<Rational>& hi, Shortest shortest);

}  // namespace relpos::detail
