// The pencil lambda P + E and its two polynomials (math.md §2; paper eq. (1)):
//   characteristic polynomial  f(lambda) = det(lambda P + E)   (quartic, f4 = det P, f0 = det E),
//   special polynomial         s(lambda) = det(lambda A + M)   (A, M the 3x3 blocks; quadratic,
//                                                               because rank A = 2).
// Both are written once, generic over the number type NT (double, intervals, MPFR, GMP integers):
// only ring operations are used, so an integer instantiation is exact and an interval one encloses.
#pragma once

#include <array>
#include <utility>

#include "relpos/polynomials.hpp"

namespace relpos {

namespace detail {

/// acc + x y and acc - x y, rounded as the written sum in a floating-point type (same operations,
/// same order). An exact integer type may overload them (found by argument-dependent lookup) as
/// one fused call without a temporary, as PooledInteger does with GMP's addmul.
template <class NT>
void add_product(NT& acc, const NT& x, const NT& y) {
  acc = acc + x * y;
}
template <class NT>
void sub_product(NT& acc, const NT& x, const NT& y) {
  acc = acc - x * y;
}

/// 2x2 minor of the matrix of linear polynomials m0 + lambda m1 on rows (r0, r1), columns (c0, c1):
/// a quadratic in lambda.
template <class NT, class M>
Quadratic<NT> linear_minor2(const M& m0, const M& m1, int r0, int r1, int c0, int c1) {
  const NT &a0 = m0(r0, c0), &b0 = m0(r0, c1), &c0_ = m0(r1, c0), &d0 = m0(r1, c1);
  const NT &a1 = m1(r0, c0), &b1 = m1(r0, c1), &c1_ = m1(r1, c0), &d1 = m1(r1, c1);
  // {a0 d0 - b0 c0, a0 d1 + a1 d0 - b0 c1 - b1 c0, a1 d1 - b1 c1}, summed left to right.
  Quadratic<NT> m{a0 * d0, a0 * d1, a1 * d1};
  sub_product(m[0], b0, c0_);
  add_product(m[1], a1, d0);
  sub_product(m[1], b0, c1_);
  sub_product(m[1], b1, c0_);
  sub_product(m[2], b1, c1_);
  return m;
}

/// u v for two quadratics, each coefficient summed left to right.
template <class NT>
Quartic<NT> product(const Quadratic<NT>& u, const Quadratic<NT>& v) {
  Quartic<NT> uv{u[0] * v[0], u[0] * v[1], u[0] * v[2], u[1] * v[2], u[2] * v[2]};
  add_product(uv[1], u[1], v[0]);
  add_product(uv[2], u[1], v[1]);
  add_product(uv[2], u[2], v[0]);
  add_product(uv[3], u[2], v[1]);
  return uv;
}

}  // namespace detail

/// f(lambda) = det(lambda P + E) for 4x4 matrices accessed as m(i, j).
/// Laplace expansion along the first two rows: det = sum over column pairs of
/// sign * minor(rows 0,1) * complementary minor(rows 2,3); each minor is a quadratic in lambda.
template <class NT, class M>
Quartic<NT> characteristic_polynomial(const M& p, const M& e) {
  static constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr int kSign[6] = {1, -1, 1, 1, -1, 1};
  Quartic<NT> f{NT(0), NT(0), NT(0), NT(0), NT(0)};
  // Unrolled: the column indices become constants (in doubles, the loop's indexed loads cost more
  // than its arithmetic).
#pragma GCC unroll 6
  for (int k = 0; k < 6; ++k) {
    const int* top = kPairs[k];
    const int* bot = kPairs[5 - k];  // complementary columns
    Quadratic<NT> u = detail::linear_minor2<NT>(e, p, 0, 1, top[0], top[1]);
    Quadratic<NT> v = detail::linear_minor2<NT>(e, p, 2, 3, bot[0], bot[1]);
    const Quartic<NT> uv = detail::product(u, v);
    for (int i = 0; i < 5; ++i) f[i] = kSign[k] > 0 ? std::move(f[i]) + uv[i] : std::move(f[i]) - uv[i];
  }
  return f;
}

/// s(lambda) = det(lambda A + M) with A, M the leading 3x3 blocks of P, E. The lambda^3 coefficient
/// is det A = 0 for an elliptic paraboloid and is not returned.
template <class NT, class M>
Quadratic<NT> special_polynomial(const M& p, const M& e) {
  Quadratic<NT> s{NT(0), NT(0), NT(0)};
#pragma GCC unroll 3
  for (int j = 0; j < 3; ++j) {
    const int c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
    Quadratic<NT> m = detail::linear_minor2<NT>(e, p, 1, 2, c0, c1);
    const NT &x0 = e(0, j), &x1 = p(0, j);             // entry (0, j) = x0 + lambda x1
    Quadratic<NT> t{x0 * m[0], x0 * m[1], x0 * m[2]};  // lambda^3 term dropped
    using detail::add_product;                         // unqualified: a fused overload wins
    add_product(t[1], x1, m[0]);
    add_product(t[2], x1, m[1]);
    for (int i = 0; i < 3; ++i) s[i] = (j == 1) ? std::move(s[i]) - t[i] : std::move(s[i]) + t[i];
  }
  return s;
}

}  // namespace relpos
