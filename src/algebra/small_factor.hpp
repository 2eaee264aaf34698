// Real roots of a square-free polynomial of degree 1 or 2 by sign, from signs alone: the closed
// forms every exact stage uses once Disc(f) = 0 has split f into factors of degree <= 2
// (roots.hpp, multiple_roots.hpp).
#pragma once

namespace relpos::detail {

struct SmallCount {
  int negative = 0, positive = 0;
};

/// Distinct real roots of h = h2 x^2 + h1 x + h0 (degree 2, square-free: sign_disc != 0) or of
/// h1 x + h0 (degree 1), split by sign, from the signs of the coefficients and of the discriminant
/// h1^2 - 4 h2 h0. Requires h0 != 0 (0 is never a root of f, so never of a factor of f). Two real
/// roots iff the discriminant is positive; then Descartes' rule of signs is exact.
inline SmallCount count_small(int degree, int sign_disc, int s2, int s1, int s0) {
  SmallCount c;
  if (degree == 1) {
    (s1 * s0 > 0 ? c.negative : c.positive) = 1;  // root -h0/h1
    return c;
  }
  if (degree != 2 || sign_disc <= 0) return c;
  int variations = 0, last = s2;
  for (int x : {s1, s0}) {
    if (x == 0) continue;
    if (x != last) ++variations;
    last = x;
  }
  c.positive = variations;
  c.negative = 2 - variations;
  return c;
}

}  // namespace relpos::detail
