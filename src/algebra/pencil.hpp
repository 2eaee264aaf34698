// The pencil lambda P + E and its two polynomials (math.md §2; paper eq. (1)):
//   characteristic polynomial  f(lambda) = det(lambda P + E)   (quartic, f4 = det P, f0 = det E),
//   special polynomial         s(lambda) = det(lambda A + M)   (A, M the 3x3 blocks; quadratic,
//                                                               because rank A = 2).
// Both are written once, generic over the number type NT (double, intervals, MPFR, GMP integers):
// only ring operations are used, so an integer instantiation is exact and an interval one encloses.
#pragma once

#include <array>
#include <cstring>
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

namespace detail {

/// Two doubles operated on lane by lane (GCC/Clang vector extension; SSE2 on x86-64). Each lane
/// rounds exactly like the scalar operation, and no contraction is allowed (-ffp-contract=off).
typedef double Lanes2 __attribute__((vector_size(16)));

struct LaneQuadratic {
  Lanes2 c[3];
};

inline Lanes2 swap_lanes(Lanes2 x) { return __builtin_shufflevector(x, x, 1, 0); }

/// linear_minor2 in each lane: the same operations in the same order.
inline LaneQuadratic lane_minor2(Lanes2 a0, Lanes2 b0, Lanes2 c0, Lanes2 d0, Lanes2 a1, Lanes2 b1, Lanes2 c1,
                                 Lanes2 d1) {
  LaneQuadratic m{{a0 * d0, a0 * d1, a1 * d1}};
  m.c[0] = m.c[0] - b0 * c0;
  m.c[1] = m.c[1] + a1 * d0;
  m.c[1] = m.c[1] - b0 * c1;
  m.c[1] = m.c[1] - b1 * c0;
  m.c[2] = m.c[2] - b1 * c1;
  return m;
}

/// The rows of a row-major 4x4 double matrix as lane pairs: lo = (m_r0, m_r1), hi = (m_r2, m_r3),
/// and the rearrangements the column pairs below need.
struct LaneRows {
  Lanes2 lo[4], hi[4];
  explicit LaneRows(const std::array<double, 16>& m) {
    for (int r = 0; r < 4; ++r) {
      std::memcpy(&lo[r], &m[static_cast<std::size_t>(4 * r)], sizeof(Lanes2));
      std::memcpy(&hi[r], &m[static_cast<std::size_t>(4 * r + 2)], sizeof(Lanes2));
    }
  }
  Lanes2 even(int r) const { return __builtin_shufflevector(lo[r], hi[r], 0, 2); }  // (m_r0, m_r2)
  Lanes2 odd(int r) const { return __builtin_shufflevector(lo[r], hi[r], 1, 3); }   // (m_r1, m_r3)
  Lanes2 hi_swapped(int r) const { return swap_lanes(hi[r]); }                      // (m_r3, m_r2)
};

/// The 2x2 minors of lambda P + E on rows (r0, r1) for the column pairs of terms k (lane 0) and
/// 5 - k (lane 1) of the Laplace expansion: (0,1)|(2,3) for k = 0, (0,2)|(1,3) for k = 1,
/// (0,3)|(1,2) for k = 2.
inline LaneQuadratic lane_minors(const LaneRows& e, const LaneRows& p, int k, int r0, int r1) {
  auto a = [k](const LaneRows& m, int r) { return k == 0 ? m.even(r) : m.lo[r]; };
  auto b = [k](const LaneRows& m, int r) { return k == 0 ? m.odd(r) : k == 1 ? m.hi[r] : m.hi_swapped(r); };
  return lane_minor2(a(e, r0), b(e, r0), a(e, r1), b(e, r1), a(p, r0), b(p, r0), a(p, r1), b(p, r1));
}

/// Terms k and 5 - k of characteristic_polynomial, u v in lane 0 and lane 1: product() per lane.
inline std::array<Lanes2, 5> lane_terms(const LaneRows& e, const LaneRows& p, int k) {
  const LaneQuadratic u = lane_minors(e, p, k, 0, 1);
  const LaneQuadratic w = lane_minors(e, p, k, 2, 3);  // lane 0: the columns of term k, used by term 5 - k
  const Lanes2 v[3] = {swap_lanes(w.c[0]), swap_lanes(w.c[1]), swap_lanes(w.c[2])};
  std::array<Lanes2, 5> uv{u.c[0] * v[0], u.c[0] * v[1], u.c[0] * v[2], u.c[1] * v[2], u.c[2] * v[2]};
  uv[1] = uv[1] + u.c[1] * v[0];
  uv[2] = uv[2] + u.c[1] * v[1];
  uv[2] = uv[2] + u.c[2] * v[0];
  uv[3] = uv[3] + u.c[2] * v[1];
  return uv;
}

}  // namespace detail

/// characteristic_polynomial<double> for row-major double matrices, bit for bit: every term of the
/// expansion is computed with the same operations (two terms at a time, one per lane) and summed in
/// the same order (two coefficients at a time). The static filter's error bounds, derived on the
/// generic template, hold for it unchanged.
inline Quartic<double> characteristic_polynomial_lanes(const std::array<double, 16>& p,
                                                       const std::array<double, 16>& e) {
  using detail::Lanes2;
  const detail::LaneRows er(e), pr(p);
  // t[j][i]: coefficient i of terms j (lane 0) and 5 - j (lane 1).
  const std::array<Lanes2, 5> t[3] = {detail::lane_terms(er, pr, 0), detail::lane_terms(er, pr, 1),
                                      detail::lane_terms(er, pr, 2)};
  // Coefficients (0, 1) and (2, 3) of term k as lane pairs: f += or -= them in the order k = 0..5
  // with the signs + - + + - +.
  Quartic<double> f;
  for (int i = 0; i < 4; i += 2) {
    auto term = [&](int k) {
      const Lanes2 &x = t[k < 3 ? k : 5 - k][i], &y = t[k < 3 ? k : 5 - k][i + 1];
      return k < 3 ? __builtin_shufflevector(x, y, 0, 2) : __builtin_shufflevector(x, y, 1, 3);
    };
    Lanes2 acc = Lanes2{0.0, 0.0} + term(0);
    acc = acc - term(1);
    acc = acc + term(2);
    acc = acc + term(3);
    acc = acc - term(4);
    acc = acc + term(5);
    f[static_cast<std::size_t>(i)] = acc[0];
    f[static_cast<std::size_t>(i + 1)] = acc[1];
  }
  double f4 = 0.0 + t[0][4][0];
  f4 = f4 - t[1][4][0];
  f4 = f4 + t[2][4][0];
  f4 = f4 + t[2][4][1];
  f4 = f4 - t[1][4][1];
  f4 = f4 + t[0][4][1];
  f[4] = f4;
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

/// special_polynomial<double> for row-major double matrices, bit for bit (as
/// characteristic_polynomial_lanes): the terms j = 0 and j = 2 in the two lanes, j = 1 alone, summed
/// in the order j = 0, 1, 2.
inline Quadratic<double> special_polynomial_lanes(const std::array<double, 16>& p, const std::array<double, 16>& e) {
  using detail::Lanes2;
  const detail::LaneRows er(e), pr(p);
  // Columns (1, 2) in lane 0 (j = 0) and (0, 1) in lane 1 (j = 2): a = (m_r1, m_r0), b = (m_r2, m_r1).
  auto a = [](const detail::LaneRows& m, int r) { return detail::swap_lanes(m.lo[r]); };
  auto b = [](const detail::LaneRows& m, int r) { return __builtin_shufflevector(m.lo[r], m.hi[r], 2, 1); };
  const detail::LaneQuadratic m =
      detail::lane_minor2(a(er, 1), b(er, 1), a(er, 2), b(er, 2), a(pr, 1), b(pr, 1), a(pr, 2), b(pr, 2));
  const Lanes2 x0 = er.even(0), x1 = pr.even(0);  // entries (0, 0) and (0, 2)
  Lanes2 t[3] = {x0 * m.c[0], x0 * m.c[1], x0 * m.c[2]};
  t[1] = t[1] + x1 * m.c[0];
  t[2] = t[2] + x1 * m.c[1];
  // j = 1: columns (0, 2), entry (0, 1).
  struct View {
    const std::array<double, 16>& a;
    const double& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
  };
  const Quadratic<double> m1 = detail::linear_minor2<double>(View{e}, View{p}, 1, 2, 0, 2);
  const double y0 = e[1], y1 = p[1];
  double u[3] = {y0 * m1[0], y0 * m1[1], y0 * m1[2]};
  u[1] = u[1] + y1 * m1[0];
  u[2] = u[2] + y1 * m1[1];
  Quadratic<double> s;
  for (std::size_t i = 0; i < 3; ++i) {
    double acc = 0.0 + t[i][0];
    acc = acc - u[i];
    s[i] = acc + t[i][1];
  }
  return s;
}

}  // namespace relpos
