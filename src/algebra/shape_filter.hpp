// The shape of a quadric given as 16 finite doubles, decided as a filtered predicate:
// interval arithmetic certifies the signs of the minors that classify_quadric reads exactly, and the
// one exact zero a paraboloid needs (det Q3 = 0) is tested on floating-point expansions (Shewchuk:
// error-free products and sums), so the whole test runs without GMP and without heap allocation.
// Each function answers only when it is certain the matrix is of the named kind; 0 sends the caller
// to the exact path (classify_quadric), which decides every case and names what the matrix is.
#pragma once

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "algebra/cramer.hpp"
#include "algebra/pencil.hpp"
#include "algebra/rounding.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::shape_filter {

namespace impl {

using I = CGAL::Interval_nt<false>;

/// The entries of d as T, read through m(i, j) by the formulas below.
template <class T>
auto entries(const DoubleMatrix4& d) {
  return [&d](int i, int j) { return T(d[static_cast<std::size_t>(4 * i + j)]); };
}
template <class T>
auto entries(const std::array<T, 16>& d) {
  return [&d](int i, int j) { return d[static_cast<std::size_t>(4 * i + j)]; };
}

/// det of the symmetric 4x4 matrix by the 2x2-minor expansion (Laplace on the first two rows).
template <class T, class M>
T det4(const M& d) {
  const auto m = entries<T>(d);
  const T s0 = m(0, 0) * m(1, 1) - m(1, 0) * m(0, 1);
  const T s1 = m(0, 0) * m(1, 2) - m(1, 0) * m(0, 2);
  const T s2 = m(0, 0) * m(1, 3) - m(1, 0) * m(0, 3);
  const T s3 = m(0, 1) * m(1, 2) - m(1, 1) * m(0, 2);
  const T s4 = m(0, 1) * m(1, 3) - m(1, 1) * m(0, 3);
  const T s5 = m(0, 2) * m(1, 3) - m(1, 2) * m(0, 3);
  const T c5 = m(2, 2) * m(3, 3) - m(3, 2) * m(2, 3);
  const T c4 = m(2, 1) * m(3, 3) - m(3, 1) * m(2, 3);
  const T c3 = m(2, 1) * m(3, 2) - m(3, 1) * m(2, 2);
  const T c2 = m(2, 0) * m(3, 3) - m(3, 0) * m(2, 3);
  const T c1 = m(2, 0) * m(3, 2) - m(3, 0) * m(2, 2);
  const T c0 = m(2, 0) * m(3, 1) - m(3, 0) * m(2, 1);
  return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

template <class T, class M>
T det3(const M& d) {
  return detail::det3<T>(entries<T>(d));
}

/// Magnitudes for a semi-static error bound: a formula evaluated on |entries| with every
/// subtraction turned into an addition is the sum of the absolute values of its terms, which bounds
/// the rounding error of the same formula evaluated in doubles (Shewchuk's "permanent" bounds).
struct Mag {
  double v = 0;
  Mag() = default;
  explicit Mag(double x) : v(std::fabs(x)) {}
  friend Mag operator*(Mag a, Mag b) { return Mag(a.v * b.v); }
  friend Mag operator+(Mag a, Mag b) { return Mag(a.v + b.v); }
  friend Mag operator-(Mag a, Mag b) { return Mag(a.v + b.v); }
};

/// The sign of a formula of at most 12 successive roundings (det4 below has 8, det3 5), evaluated in
/// doubles on a power-of-two normalized matrix (entries below 1 in magnitude, none subnormal):
/// its error is at most 12 eps (1 + 12 eps) times its magnitude, plus underflow in at most a few
/// hundred products of at most 2^-1074 each; the bound 2^-47 magnitude + 2^-1000 covers both with a
/// factor of two to spare (the magnitude's own rounding included). 0 when uncertain.
inline int semi_static_sign(double value, double magnitude) {
  const double bound = 0x1p-47 * magnitude + 0x1p-1000;
  if (value > bound) return 1;
  if (value < -bound) return -1;
  return 0;
}
/// semi_static_sign's bound for the static magnitude `most` (what the formula's magnitude can be at
/// most when every entry is below 1), evaluated by the compiler: constexpr, since -frounding-math
/// keeps it from folding constants otherwise.
constexpr double static_bound(int most) { return 0x1p-47 * most + 0x1p-1000; }
/// The same, trying first the static magnitude `most` (no extra arithmetic), then the actual magnitude.
template <int Most, class MagnitudeOf>
int filtered_sign(double value, MagnitudeOf magnitude) {
  constexpr double bound = static_bound(Most);
  if (value > bound) return 1;
  if (value < -bound) return -1;
  return semi_static_sign(value, magnitude().v);
}

inline std::array<I, 16> interval_entries(const DoubleMatrix4& d) {
  std::array<I, 16> out;
  for (std::size_t k = 0; k < 16; ++k) out[k] = I(d[k]);
  return out;
}

inline int certain_sign(const I& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  return 0;  // uncertain (or zero)
}

/// d == d^T exactly (false for a NaN off the diagonal): the six mirrored pairs as three lane pairs,
/// (d01, d02) against (d10, d20), (d03, d13) against (d30, d31), (d12, d23) against (d21, d32).
inline bool symmetric(const DoubleMatrix4& d) {
  using detail::Lanes2;
  Lanes2 r[8];  // (d[2k], d[2k + 1])
  for (std::size_t k = 0; k < 8; ++k) std::memcpy(&r[k], &d[2 * k], sizeof r[k]);
  const auto same = (__builtin_shufflevector(r[0], r[1], 1, 2) == __builtin_shufflevector(r[2], r[4], 0, 2)) &
                    (__builtin_shufflevector(r[1], r[3], 1, 3) == r[6]) &
                    (__builtin_shufflevector(r[3], r[5], 0, 3) == __builtin_shufflevector(r[4], r[7], 1, 2));
  return same[0] & same[1];
}

/// Whether Q3 of a symmetric matrix is diagonal: then its minors are products of its diagonal, and
/// their signs are the signs of the diagonal entries, without arithmetic.
inline bool diagonal_block(const DoubleMatrix4& n) { return (n[1] == 0) + (n[2] == 0) + (n[6] == 0) == 3; }

/// The numbers of positive and of negative entries on the diagonal of Q3.
struct DiagonalSigns {
  int positive, negative;
};
inline DiagonalSigns diagonal_signs(const DoubleMatrix4& n) {
  return {(n[0] > 0) + (n[5] > 0) + (n[10] > 0), (n[0] < 0) + (n[5] < 0) + (n[10] < 0)};
}

/// A growing floating-point expansion (Shewchuk 1997): the exact sum of its components, which are
/// non-overlapping and increasing in magnitude. Needs round to nearest and no under/overflow.
struct Expansion {
  std::array<double, 24> c{};
  int n = 0;
  void add(double b) {  // Grow-Expansion
    double q = b;
    for (int i = 0; i < n; ++i) {
      const double s = q + c[static_cast<std::size_t>(i)];
      const double bv = s - q;
      const double err = (q - (s - bv)) + (c[static_cast<std::size_t>(i)] - bv);
      c[static_cast<std::size_t>(i)] = err;
      q = s;
    }
    c[static_cast<std::size_t>(n++)] = q;
  }
  /// Adds x*y*z exactly (four components).
  void add_product(double x, double y, double z) {
    const double p = x * y, e = std::fma(x, y, -p);
    const double p1 = p * z, e1 = std::fma(p, z, -p1);
    const double p2 = e * z, e2 = std::fma(e, z, -p2);
    add(e2);
    add(p2);
    add(e1);
    add(p1);
  }
  bool is_zero() const {
    for (int i = 0; i < n; ++i)
      if (c[static_cast<std::size_t>(i)] != 0) return false;
    return true;
  }
};

/// Every term of det Q3 = a d f + 2 b c e - a e^2 - f b^2 - d c^2 ([[a, b, c], [b, d, e], [c, e, f]])
/// has a factor that is exactly zero (axis-aligned paraboloids): det Q3 = 0 without arithmetic.
constexpr bool zero_by_pattern(bool a, bool b, bool c, bool d, bool e, bool f) {
  return (a || d || f) && (b || c || e) && (a || e) && (f || b) && (d || c);
}

/// zero_by_pattern of every combination of the six flags (bit k set: flag k): a table lookup
/// instead of a branch per flag.
constexpr std::uint64_t kZeroPatterns = [] {
  std::uint64_t table = 0;
  for (unsigned z = 0; z < 64; ++z)
    if (zero_by_pattern(z & 1, z & 2, z & 4, z & 8, z & 16, z & 32)) table |= std::uint64_t{1} << z;
  return table;
}();

/// det Q3 == 0 by the expansion below; out of line: only blocks with no zero pattern get here.
[[gnu::noinline]] inline std::optional<bool> det3_is_zero_by_expansion(const DoubleMatrix4& d) {
  if (!detail::rounding_to_nearest()) return std::nullopt;
  double mx = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mx = std::max(mx, std::fabs(d[static_cast<std::size_t>(4 * i + j)]));
  if (mx == 0) return true;
  const int shift = -std::ilogb(mx);
  double q[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double x = d[static_cast<std::size_t>(4 * i + j)];
      // Products of three entries and their error terms stay far above the subnormal range (tested
      // before scaling: a scaled entry must not underflow to zero).
      if (x != 0 && std::ilogb(x) + shift < -250) return std::nullopt;
      q[i][j] = std::ldexp(x, shift);
    }
  // det = a d f + 2 b c e - a e^2 - f b^2 - d c^2 for [[a, b, c], [b, d, e], [c, e, f]]
  const double a = q[0][0], b = q[0][1], c = q[0][2], dd = q[1][1], e = q[1][2], f = q[2][2];
  Expansion x;
  x.add_product(a, dd, f);
  x.add_product(2 * b, c, e);
  x.add_product(-a, e, e);
  x.add_product(-f, b, b);
  x.add_product(-dd, c, c);
  return x.is_zero();
}

/// det Q3 == 0, exactly; nullopt when the entries are outside the range where the expansion is
/// exact (the caller takes the exact path). The block is scaled by a power of two first (exact).
inline std::optional<bool> det3_is_zero(const DoubleMatrix4& d) {
  const unsigned zeros = unsigned{d[0] == 0} | unsigned{d[1] == 0} << 1 | unsigned{d[2] == 0} << 2 |
                         unsigned{d[5] == 0} << 3 | unsigned{d[6] == 0} << 4 | unsigned{d[10] == 0} << 5;
  if ((kZeroPatterns >> zeros) & 1) return true;
  return det3_is_zero_by_expansion(d);
}

}  // namespace impl

/// The interval stage of the shape tests on enclosures of the entries (rounding towards +inf, by
/// the caller): `want` (+1 or -1, the certain sign of the first entry) when the matrix is certainly
/// a real ellipsoid with Q3 of that definiteness, else 0.
inline int certified_ellipsoid_intervals(const std::array<impl::I, 16>& d, int want) {
  using impl::I;
  const I m2 = d[0] * d[5] - d[1] * d[1];
  if (impl::certain_sign(m2) != 1) return 0;
  if (impl::certain_sign(impl::det3<I>(d)) != want) return 0;
  if (impl::certain_sign(impl::det4<I>(d)) != -1) return 0;
  return want;
}

/// The same for an elliptic paraboloid: the sign of the trace of Q3 when E2 > 0, the trace and
/// det Q < 0 are certain (det Q3 = 0 is the caller's exact test), else 0.
inline int certified_paraboloid_intervals(const std::array<impl::I, 16>& d) {
  using impl::I;
  const I e2 = (d[0] * d[5] - d[1] * d[1]) + (d[0] * d[10] - d[2] * d[2]) + (d[5] * d[10] - d[6] * d[6]);
  if (impl::certain_sign(e2) != 1) return 0;
  const int trace_sign = impl::certain_sign(d[0] + d[5] + d[10]);
  if (trace_sign == 0) return 0;
  if (impl::certain_sign(impl::det4<I>(d)) != -1) return 0;
  return trace_sign;
}

namespace impl {

/// det Q < 0 on the normalized doubles (static, then semi-static bound): -1, else the sign or 0.
inline int det4_sign(const DoubleMatrix4& n) {
  return filtered_sign<24>(det4<double>(n), [&] { return det4<Mag>(n); });
}

}  // namespace impl

namespace impl {

using detail::Lanes2;

/// The 2x2 minors of rows a and b (lane pairs (a0, a1), (a2, a3) and (b0, b1), (b2, b3)) on the
/// column pairs ((0, 1), (0, 2)), ((0, 3), (1, 2)), ((1, 3), (2, 3)), each x y - z w (det4's s and c
/// minors: the same operations); with Magnitude, the rows are absolute values and each is x y + z w.
template <bool Magnitude>
std::array<Lanes2, 3> row_minors(Lanes2 alo, Lanes2 ahi, Lanes2 blo, Lanes2 bhi) {
  const Lanes2 x[3] = {__builtin_shufflevector(alo, alo, 0, 0), alo, __builtin_shufflevector(alo, ahi, 1, 2)};
  const Lanes2 y[3] = {__builtin_shufflevector(blo, bhi, 1, 2), __builtin_shufflevector(bhi, bhi, 1, 0),
                       __builtin_shufflevector(bhi, bhi, 1, 1)};
  const Lanes2 z[3] = {__builtin_shufflevector(blo, blo, 0, 0), blo, __builtin_shufflevector(blo, bhi, 1, 2)};
  const Lanes2 w[3] = {__builtin_shufflevector(alo, ahi, 1, 2), __builtin_shufflevector(ahi, ahi, 1, 0),
                       __builtin_shufflevector(ahi, ahi, 1, 1)};
  std::array<Lanes2, 3> m;
  for (std::size_t k = 0; k < 3; ++k) m[k] = Magnitude ? x[k] * y[k] + z[k] * w[k] : x[k] * y[k] - z[k] * w[k];
  return m;
}

/// The three determinants of the ellipsoid test on a symmetric matrix n, from one set of 2x2 minors
/// s of rows 0 and 1 (and c of rows 2 and 3 for det Q): the leading minor s01, det Q3 =
/// (n22 s01 - n21 s02) + n20 s12 (expanded along row 2) and det Q = sum of +-s c over complementary
/// column pairs, two terms per lane. At most 6 successive roundings each; with Magnitude, the same
/// formulas on |n| with every subtraction an addition (their magnitudes, as Mag gives them).
struct EllipsoidDeterminants {
  double minor2, det3, det4;
};
template <bool Magnitude>
[[gnu::always_inline]] inline EllipsoidDeterminants ellipsoid_determinants(const DoubleMatrix4& n, bool with_det4) {
  Lanes2 lo[4], hi[4];
  for (std::size_t r = 0; r < 4; ++r) {
    std::memcpy(&lo[r], &n[4 * r], sizeof lo[r]);
    std::memcpy(&hi[r], &n[4 * r + 2], sizeof hi[r]);
    if (Magnitude) {
      lo[r] = Lanes2{std::fabs(lo[r][0]), std::fabs(lo[r][1])};
      hi[r] = Lanes2{std::fabs(hi[r][0]), std::fabs(hi[r][1])};
    }
  }
  const std::array<Lanes2, 3> sm = row_minors<Magnitude>(lo[0], hi[0], lo[1], hi[1]);
  // sm[0] = (s01, s02), sm[1] = (s03, s12), sm[2] = (s13, s23); n2j = lo[2], hi[2][0]
  const double t = Magnitude ? hi[2][0] * sm[0][0] + lo[2][1] * sm[0][1] : hi[2][0] * sm[0][0] - lo[2][1] * sm[0][1];
  EllipsoidDeterminants d{sm[0][0], t + lo[2][0] * sm[1][1], 0};
  if (with_det4) {
    const std::array<Lanes2, 3> cm = row_minors<Magnitude>(lo[2], hi[2], lo[3], hi[3]);
    auto swap = [](Lanes2 x) { return __builtin_shufflevector(x, x, 1, 0); };
    // u = (s01 c23, s02 c13) with signs (+, -), v = (s03 c12, s12 c03) (+, +), w = (s13 c02, s23 c01) (-, +)
    const Lanes2 u = sm[0] * swap(cm[2]), v = sm[1] * swap(cm[1]), w = sm[2] * swap(cm[0]);
    const Lanes2 sum =
        Magnitude ? (u + w) + v : (__builtin_shufflevector(u, w, 0, 3) - __builtin_shufflevector(w, u, 0, 3)) + v;
    d.det4 = sum[0] + sum[1];
  }
  return d;
}

/// The magnitudes, out of line: read only when a static bound does not decide.
[[gnu::noinline]] inline EllipsoidDeterminants ellipsoid_magnitudes(const DoubleMatrix4& n, bool with_det4) {
  return ellipsoid_determinants<true>(n, with_det4);
}

/// The ellipsoid test's signs on the normalized doubles (round to nearest, the caller's test): the
/// orientation (+1 or -1, the sign of the first entry) when the 2x2 leading minor is positive and
/// det Q3 has the first entry's sign, else 0; with `det`, also det Q's certified sign (0 when
/// uncertain) into *det. Static bounds for entries below 1 (2, 6 and 24: each minor is at most 2 in
/// magnitude), then the magnitudes of this matrix.
inline int ellipsoid_signs(const DoubleMatrix4& n, int* det) {
  const EllipsoidDeterminants v = ellipsoid_determinants<false>(n, det != nullptr);
  bool have = false;
  EllipsoidDeterminants m{};
  auto magnitudes = [&]() -> const EllipsoidDeterminants& {
    if (!have) m = ellipsoid_magnitudes(n, det != nullptr), have = true;
    return m;
  };
  const int want = n[0] > 0 ? 1 : (n[0] < 0 ? -1 : 0);  // normalized entries are finite
  const int s2 = filtered_sign<2>(v.minor2, [&] { return Mag(magnitudes().minor2); });
  const int s3 = filtered_sign<6>(v.det3, [&] { return Mag(magnitudes().det3); });
  if (det) *det = filtered_sign<24>(v.det4, [&] { return Mag(magnitudes().det4); });
  return want != 0 && s2 == 1 && s3 == want ? want : 0;
}

}  // namespace impl

/// Every sign of the ellipsoid test but det Q < 0 (impl::ellipsoid_signs), always 0 without
/// `normalized`: the quadric's filter_doubles() (quadric_matrix.hpp), d scaled by a power of two and
/// symmetric, or null. Without a test of the rounding mode: its answer is sound only in round to
/// nearest, for a caller that uses it only after a later stage has found that mode (the decision on
/// 32 doubles: its pencil stage runs only then, and reads det Q < 0 off the pencil, whose f(0) is
/// det E (math.md §2); otherwise the two steps decide, with their tests).
inline int ellipsoid_before_det_if_nearest(const DoubleMatrix4* normalized) {
  return normalized ? impl::ellipsoid_signs(*normalized, nullptr) : 0;
}

/// The same for an elliptic paraboloid: the sign of the trace of Q3 when E2 > 0 and the trace are
/// certain and det Q3 = 0 exactly; else 0. A diagonal Q3 (an axis-aligned paraboloid, the usual
/// input) is decided by signs alone: semidefinite of rank 2 iff exactly one diagonal entry is zero
/// and the other two share a sign. det Q < 0 is certified_paraboloid_in_doubles's, or the pencil's leading
/// coefficient det P (math.md §2).
inline int paraboloid_before_det(const DoubleMatrix4& d, const DoubleMatrix4* normalized) {
  if (!normalized) return 0;
  const DoubleMatrix4& n = *normalized;
  // Signs and zeros are read from d, which has those of n (n is d times a power of two, exactly),
  // and is already in registers or the cache, where n was just stored.
  if (impl::diagonal_block(d)) {  // one entry zero, the two others of one sign
    const impl::DiagonalSigns s = impl::diagonal_signs(d);
    return s.positive + s.negative != 2 ? 0 : (s.positive == 2 ? 1 : (s.negative == 2 ? -1 : 0));
  }
  if (!detail::rounding_to_nearest()) return 0;
  using impl::Mag;
  const int e2 = impl::filtered_sign<6>(
      (n[0] * n[5] - n[1] * n[1]) + (n[0] * n[10] - n[2] * n[2]) + (n[5] * n[10] - n[6] * n[6]), [&] {
        return (Mag(n[0]) * Mag(n[5]) + Mag(n[1]) * Mag(n[1])) + (Mag(n[0]) * Mag(n[10]) + Mag(n[2]) * Mag(n[2])) +
               (Mag(n[5]) * Mag(n[10]) + Mag(n[6]) * Mag(n[6]));
      });
  const int trace_sign =
      impl::filtered_sign<3>(n[0] + n[5] + n[10], [&] { return Mag(n[0]) + Mag(n[5]) + Mag(n[10]); });
  if (e2 != 1 || trace_sign == 0) return 0;
  const auto zero = impl::det3_is_zero(d);
  return zero && *zero ? trace_sign : 0;
}

namespace impl {

/// det Q < 0 for a matrix paraboloid_before_det accepted. With Q3 diagonal, its entry z zero and the
/// two others of one sign, expanding along row z gives det Q = -(the product of those two) q_z^2
/// (q_z = entry (z, 3)): negative iff q_z != 0, by signs alone. Otherwise det4_sign (the test of
/// the rounding mode was paraboloid_before_det's). d and its normalized n as there (the signs read
/// from d).
inline bool paraboloid_det_negative(const DoubleMatrix4& d, const DoubleMatrix4& n) {
  if (diagonal_block(d)) return d[d[0] == 0 ? 3 : (d[5] == 0 ? 7 : 11)] != 0;
  return det4_sign(n) == -1;
}

}  // namespace impl

// The ellipsoid and paraboloid certification of from_doubles, in two stages: the signs in doubles
// on the normalized matrix, then, when they leave it open, intervals on d itself.

/// +1 when the symmetric matrix is certainly a real ellipsoid with Q3 positive definite, -1 when it
/// is one with Q3 negative definite, 0 when these signs cannot tell (or it is not an ellipsoid): the
/// signs in doubles on `normalized` (as for ellipsoid_before_det_if_nearest, or null), in round to
/// nearest (tested here; 0 in any other mode).
inline int certified_ellipsoid_in_doubles(const DoubleMatrix4* normalized) {
  if (!normalized || !detail::rounding_to_nearest()) return 0;
  int det;
  const int want = impl::ellipsoid_signs(*normalized, &det);
  return det == -1 ? want : 0;
}

/// The same answer by the interval stage on d itself (out of line: rarely run, and kept out of the
/// callers' frames).
[[gnu::noinline]] inline int certified_ellipsoid_by_intervals(const DoubleMatrix4& d) {
  if (!impl::symmetric(d)) return 0;
  const double a = d[0];
  if (!(a > 0) && !(a < 0)) return 0;
  CGAL::Protect_FPU_rounding<true> guard;
  return certified_ellipsoid_intervals(impl::interval_entries(d), a > 0 ? 1 : -1);
}

/// +1 when the symmetric matrix is certainly an elliptic paraboloid with Q3 positive semidefinite,
/// -1 with Q3 negative semidefinite, 0 when these signs cannot tell (or it is not one). Q3 has rank 2
/// and is semidefinite iff det Q3 = 0 (exact) and E2 > 0 (the sum of its 2x2 principal minors: the
/// product of the two other eigenvalues); rank Q = 4 iff det Q != 0. The signs in doubles:
/// paraboloid_before_det and det Q < 0, `normalized` as for certified_ellipsoid_in_doubles.
inline int certified_paraboloid_in_doubles(const DoubleMatrix4& d, const DoubleMatrix4* normalized) {
  const int trace_sign = paraboloid_before_det(d, normalized);
  return trace_sign != 0 && impl::paraboloid_det_negative(d, *normalized) ? trace_sign : 0;
}

/// The same answer by the interval stage, and its exact test of det Q3 = 0, on d itself (out of line,
/// as for the ellipsoid).
[[gnu::noinline]] inline int certified_paraboloid_by_intervals(const DoubleMatrix4& d) {
  if (!impl::symmetric(d)) return 0;
  int trace_sign;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    trace_sign = certified_paraboloid_intervals(impl::interval_entries(d));
  }
  if (trace_sign == 0) return 0;
  const auto zero = impl::det3_is_zero(d);
  return zero && *zero ? trace_sign : 0;
}

}  // namespace relpos::detail::shape_filter
