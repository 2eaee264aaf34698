// The margin of a pair (math.md §19): how far an answer is from changing. s* is the factor by which
// the ellipsoid, scaled about its centre, first touches the paraboloid (the ellipsoidal distance from
// the centre to the surface): s* > 1 for I and E, s* = 1 for TI and TE, s* < 1 for C, and s* = 0 when
// the centre lies on the paraboloid. The scaled ellipsoids are nested, so for a centre inside the cup
// the pair scaled by q is I for q < s*, TI at s* and C above; for a centre outside it is E, TE, C.
//
// margin() reports s* exactly -- its minimal polynomial over Z and a rational enclosure [lo, hi] --
// with a double approximation and a proof: certificates (position.hpp) of the pair scaled by lo (I or
// E: no contact below) and by hi (C: contact above), or for a rational s* the TI or TE certificate
// of the pair scaled by s* itself. verify_margin() checks all of it with exact arithmetic.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "relpos/algebraic_real.hpp"
#include "relpos/numbers.hpp"
#include "relpos/position.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

/// The default relative width of a margin's enclosure: hi - lo <= 2^-40 lo.
inline constexpr int kDefaultMarginBits = 40;

/// s* exactly, with its proof (doc/certificates.md, "Margins").
struct Margin {
  /// The minimal polynomial of s* (index = power of t): irreducible over Q, primitive, positive
  /// leading coefficient; den t - num for a rational s*, t for s* = 0.
  std::vector<Integer> polynomial;
  /// lo <= s* <= hi. lo == hi exactly when s* is rational (then both are s*); otherwise
  /// lo < s* < hi, hi - lo <= 2^-bits lo, and s* is the only root of the polynomial in (lo, hi).
  Rational lo, hi;
  /// The double nearest s* (+infinity beyond the double range: JSON null).
  double approx = 0;
  /// lo < hi: certificate of the pair with the ellipsoid scaled by lo about its centre, I or E
  /// (Certificate::Kind::Definite; lambda < 0: I, the centre inside the cup; lambda > 0: E).
  Certificate below;
  /// lo < hi: certificate of the pair scaled by hi, C (Certificate::Kind::Crossing).
  Certificate above;
  /// lo == hi > 0: certificate of the pair scaled by s*, TI or TE (Tangent, or HardTangent for TI):
  /// the family is nested, so a tangency at s* pins s* exactly. None for s* = 0 (the centre on the
  /// paraboloid needs no certificate: anyone can evaluate the paraboloid's form there).
  Certificate at;

  /// s* as an exact algebraic real (the polynomial with the isolating interval (lo, hi)).
  AlgebraicReal value() const;
};

/// s* for the pair, exactly, with an enclosure of relative width 2^-bits at most, 1 <= bits <= 1000
/// (InputError otherwise, and for a pair beyond the size limit, as classify()).
Margin margin(const Ellipsoid& e, const Paraboloid& p, int bits = kDefaultMarginBits);

/// Checks a margin with exact arithmetic: nullopt when it proves s* for the pair, otherwise the
/// reason. The certificates go to verify_certificate() with the pair scaled by lo, hi or s*; the
/// polynomial must be irreducible, change sign on (lo, hi) with exactly one root there (Descartes'
/// rule), and divide the pair's margin polynomial (math.md §19), whose other factors have no root in
/// (lo, hi); approx must lie within one unit in the last place of [lo, hi].
std::optional<std::string> verify_margin(const Ellipsoid& e, const Paraboloid& p, const Margin& m);

}  // namespace relpos
