// The smallness hypothesis of the paper (section 2.2; math.md §5): the ellipsoid cannot be
// tangent to the paraboloid at two points. In the paper's normalized frame (sphere of radius r,
// paraboloid x^2/a^2 + y^2/b^2 = z, a <= b) it reads 2r <= a^2; coordinate-free,
//
//   rho = (det E / det P) / (s(0) / s2) / l^2 <= 1,
//
// with s2 the leading coefficient of s and l the root of s nearest to 0 (l = -a^2 in the normal
// frame, so rho = 4 r^2 / a^4). l may be a quadratic irrational; we never compute it. Write u1 <= u2
// for the roots of s(-u) (u1 = a^2, u2 = b^2) and K = (f0/f4)(s2/s0) (= 4 r^2), so rho = K / u1^2.
// The numbers u1^2 <= u2^2 are the roots of the Graeffe square
//   q(v) = v^2 - (sigma^2 - 2 pi) v + pi^2,   sigma = u1 + u2 = s1/s2,  pi = u1 u2 = s0/s2,
// and K <= u1^2 holds iff K is left of the vertex of q and q(K) >= 0. Clearing the positive
// denominators (N = -f0 s2 > 0 and D = -f4 s0 > 0, so K = N / D):
//
//   vertex  = (s1^2 - 2 s0 s2) D - 2 N s2^2       >= 0   (K <= (u1^2 + u2^2) / 2)
//   graeffe = N^2 s2^2 - (s1^2 - 2 s0 s2) N D + s0^2 D^2   (sign of q(K), times s2^4 D^2 / s2^2)
//
// and   rho < 1  <=> vertex >= 0 and graeffe > 0,   rho = 1 <=> vertex >= 0 and graeffe = 0,
//       rho > 1  otherwise.   Both are polynomials in the input entries: generic over NT.
#pragma once

#include <optional>
#include <string>

#include "algebra/pencil.hpp"
#include "algebra/sturm.hpp"

namespace relpos {

template <class NT>
struct SmallnessQuantities {
  NT vertex, graeffe;
  SmallnessQuantities(const Quartic<NT>& f, const Quadratic<NT>& s) {
    const NT n = -f[0] * s[2];
    const NT d = -f[4] * s[0];
    const NT w = s[1] * s[1] - NT(2) * s[0] * s[2];
    vertex = w * d - NT(2) * n * s[2] * s[2];
    graeffe = n * n * s[2] * s[2] - w * n * d + s[0] * s[0] * d * d;
  }
};

/// Comparison of rho with 1 from the signs of the two quantities: -1 (rho < 1), 0 (rho = 1),
/// +1 (rho > 1); nullopt if a needed sign is uncertain. The ellipsoid is small iff the result is <= 0.
inline std::optional<int> compare_rho_with_one(const USign& vertex, const USign& graeffe) {
  auto v = detail::certain(vertex);
  if (!v) return std::nullopt;
  if (*v < 0) return 1;
  auto g = detail::certain(graeffe);
  if (!g) return std::nullopt;
  return -*g;
}

template <class NT>
std::optional<int> compare_rho_with_one(const Quartic<NT>& f, const Quadratic<NT>& s) {
  SmallnessQuantities<NT> q(f, s);
  return compare_rho_with_one(sign_of(q.vertex), sign_of(q.graeffe));
}

}  // namespace relpos
