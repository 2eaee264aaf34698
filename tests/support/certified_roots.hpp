// An independent method for the differential tests (doc/testing.md): the roots of the characteristic
// quartic f located by high-precision floating point (Aberth iteration in MPFR at 256 bits) and then
// *certified* by an inclusion theorem evaluated in exact rational arithmetic, plus f, s and the
// smallness test recomputed by other formulas than the library's. Nothing here uses relpos's pencil,
// Sturm-Habicht, smallness or roots code.
//
// Certification (Smith 1970; Braess and Hadeler 1973). Let p be monic of degree n and z_1..z_n
// pairwise distinct points, with the Weierstrass corrections W_k = p(z_k) / prod_{j != k}(z_k - z_j).
// The matrix A = diag(z) - 1 W^T has characteristic polynomial p (matrix determinant lemma:
// det(zI - A) = prod (z - z_i) (1 + sum_j W_j / (z - z_j)), a monic polynomial equal to p at the n
// points z_k). Gerschgorin's theorem on the columns of A: every root of p lies in a disk
// |z - (z_k - W_k)| <= (n - 1)|W_k|, and a union of m of these disks disjoint from the others holds
// exactly m roots (with multiplicity). Each such disk lies in D_k = {|z - z_k| <= n |W_k|}, so the
// same holds for the D_k: a connected component of m disks D_k holds exactly m roots.
// The z_k are MPFR numbers, i.e. exact dyadic rationals, so W_k and |W_k|^2 are computed *exactly*
// over Q (no rounding anywhere in the certificate); disjointness |z_k - z_j| > R_k + R_j with
// R = n |W| is decided exactly by squaring.
// Kind of an isolated root: f has real coefficients, so the conjugate of a root is a root. A disk
// D_k with a real centre is symmetric about the real axis; if it holds exactly one root, that root
// equals its conjugate: it is real, and its sign is that of the centre when 0 is outside the disk. A
// disk that does not meet the real axis holds only non-real roots.
#pragma once

#include <gmp.h>
#include <mpfr.h>

#include <array>
#include <optional>
#include <vector>

#include "support/construct.hpp"

namespace rt {

/// An MPFR number at a fixed precision (RAII), with just the operations Aberth's iteration needs.
class Mp {
 public:
  static constexpr mpfr_prec_t kBits = 256;
  Mp() {
    mpfr_init2(x_, kBits);
    mpfr_set_zero(x_, 1);
  }
  explicit Mp(const Rational& q) : Mp() { mpfr_set_q(x_, q.mpq(), MPFR_RNDN); }
  explicit Mp(double d) : Mp() { mpfr_set_d(x_, d, MPFR_RNDN); }
  Mp(const Mp& o) : Mp() { mpfr_set(x_, o.x_, MPFR_RNDN); }
  Mp& operator=(const Mp& o) {
    mpfr_set(x_, o.x_, MPFR_RNDN);
    return *this;
  }
  ~Mp() { mpfr_clear(x_); }
  friend Mp operator+(const Mp& a, const Mp& b) { return op(mpfr_add, a, b); }
  friend Mp operator-(const Mp& a, const Mp& b) { return op(mpfr_sub, a, b); }
  friend Mp operator*(const Mp& a, const Mp& b) { return op(mpfr_mul, a, b); }
  friend Mp operator/(const Mp& a, const Mp& b) { return op(mpfr_div, a, b); }
  Mp operator-() const {
    Mp r;
    mpfr_neg(r.x_, x_, MPFR_RNDN);
    return r;
  }
  bool is_zero() const { return mpfr_zero_p(x_) != 0; }
  bool finite() const { return mpfr_number_p(x_) != 0; }
  /// Exponent e with |x| in [2^(e-1), 2^e) (x != 0).
  long exponent() const { return static_cast<long>(mpfr_get_exp(x_)); }
  Mp sqrt() const {
    Mp r;
    mpfr_sqrt(r.x_, x_, MPFR_RNDN);
    return r;
  }
  Mp root(unsigned long k) const {
    Mp r;
    mpfr_rootn_ui(r.x_, x_, k, MPFR_RNDN);
    return r;
  }
  static Mp cos_sin(double angle, bool sine) {
    Mp a(angle), r;
    (sine ? mpfr_sin : mpfr_cos)(r.x_, a.x_, MPFR_RNDN);
    return r;
  }
  /// The exact value (a dyadic rational).
  Rational exact() const {
    if (is_zero()) return Rational(0);
    Integer m;  // fresh object: Gmpz is reference-counted
    const mpfr_exp_t e = mpfr_get_z_2exp(m.mpz(), x_);
    Rational q(m);
    Rational out;
    if (e >= 0)
      mpq_mul_2exp(out.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(e));
    else
      mpq_div_2exp(out.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(-e));
    return out;
  }
  bool abs_less(const Mp& o) const { return mpfr_cmpabs(x_, o.x_) < 0; }

 private:
  template <class F>
  static Mp op(F f, const Mp& a, const Mp& b) {
    Mp r;
    f(r.x_, a.x_, b.x_, MPFR_RNDN);
    return r;
  }
  mpfr_t x_;
};

struct Cx {
  Mp re, im;
};
inline Cx operator+(const Cx& a, const Cx& b) { return {a.re + b.re, a.im + b.im}; }
inline Cx operator-(const Cx& a, const Cx& b) { return {a.re - b.re, a.im - b.im}; }
inline Cx operator*(const Cx& a, const Cx& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
inline Cx operator/(const Cx& a, const Cx& b) {
  const Mp d = b.re * b.re + b.im * b.im;
  return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
}
inline Mp abs2(const Cx& a) { return a.re * a.re + a.im * a.im; }

/// Gaussian rationals, for the exact certificate.
struct Qx {
  Rational re, im;
};
inline Qx operator+(const Qx& a, const Qx& b) { return {a.re + b.re, a.im + b.im}; }
inline Qx operator-(const Qx& a, const Qx& b) { return {a.re - b.re, a.im - b.im}; }
inline Qx operator*(const Qx& a, const Qx& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
inline Rational norm2(const Qx& a) { return a.re * a.re + a.im * a.im; }

/// Approximations of the 4 roots of the quartic f (exact coefficients, f[4] != 0) by Aberth's
/// simultaneous iteration in MPFR. Only approximations: nothing is decided from them directly.
inline std::array<Cx, 4> aberth_roots(const Quartic<Rational>& f) {
  std::array<Mp, 5> a;  // monic
  for (std::size_t i = 0; i < 5; ++i) a[i] = Mp(f[i] / f[4]);
  // Start on a circle of the Fujiwara radius 2 max |a_{4-k}|^{1/k}, rotated off the axes.
  Mp radius(0.0);
  for (unsigned k = 1; k <= 4; ++k) {
    const Mp c = a[4 - k];
    Mp m = c.is_zero() ? Mp(0.0) : (c * c).sqrt().root(k);
    if (radius.abs_less(m)) radius = m;
  }
  radius = radius + radius;
  if (radius.is_zero()) radius = Mp(1.0);
  std::array<Cx, 4> z;
  for (int k = 0; k < 4; ++k) {
    const double angle = 0.4 + 2 * 3.141592653589793 * k / 4;
    z[static_cast<std::size_t>(k)] = {radius * Mp::cos_sin(angle, false), radius * Mp::cos_sin(angle, true)};
  }
  auto eval = [&](const Cx& x, Cx& p, Cx& dp) {
    p = {a[4], Mp(0.0)};
    dp = {Mp(0.0), Mp(0.0)};
    for (int i = 3; i >= 0; --i) {
      dp = dp * x + p;
      p = p * x + Cx{a[static_cast<std::size_t>(i)], Mp(0.0)};
    }
  };
  for (int iter = 0; iter < 400; ++iter) {
    bool moved = false;
    for (std::size_t k = 0; k < 4; ++k) {
      Cx p, dp;
      eval(z[k], p, dp);
      if (p.re.is_zero() && p.im.is_zero()) continue;  // exact root
      if (dp.re.is_zero() && dp.im.is_zero()) continue;
      const Cx ratio = p / dp;
      Cx sum{Mp(0.0), Mp(0.0)};
      for (std::size_t j = 0; j < 4; ++j)
        if (j != k) sum = sum + Cx{Mp(1.0), Mp(0.0)} / (z[k] - z[j]);
      const Cx w = ratio / (Cx{Mp(1.0), Mp(0.0)} - ratio * sum);
      if (!w.re.finite() || !w.im.finite()) continue;
      z[k] = z[k] - w;
      // A part below 2^-kBits of the other is noise: dropping it keeps the exact dyadic values small
      // (near-real roots would otherwise get imaginary parts 2^-(2^iterations)).
      if (!z[k].im.is_zero() && !z[k].re.is_zero()) {
        if (z[k].im.exponent() < z[k].re.exponent() - Mp::kBits)
          z[k].im = Mp(0.0);
        else if (z[k].re.exponent() < z[k].im.exponent() - Mp::kBits)
          z[k].re = Mp(0.0);
      }
      // Converged when the correction is below 2^-(kBits - 8) of the root.
      const Mp size = abs2(z[k]), step = abs2(w);
      if (!step.is_zero() && (size.is_zero() || step.exponent() > size.exponent() - 2 * (Mp::kBits - 8))) moved = true;
    }
    if (!moved) break;
  }
  return z;
}

/// What the certificate establishes about the 4 roots of f.
struct RootCertificate {
  struct Disk {
    Qx centre;
    Rational radius2;  ///< (4 |W|)^2
    int cluster = -1;  ///< connected component of overlapping disks
    int cluster_size = 0;
    int kind = 0;  ///< +1 real, -1 non-real, 0 not decided (only for isolated disks)
    int sign = 0;  ///< of a real isolated root: -1, +1; 0 not decided
  };
  bool valid = false;  ///< the centres were pairwise distinct, so the theorem applies
  std::vector<Disk> disks;
  /// Every root isolated with its kind (and sign when real) decided.
  bool complete() const {
    if (!valid) return false;
    for (const auto& d : disks)
      if (d.cluster_size != 1 || d.kind == 0 || (d.kind > 0 && d.sign == 0)) return false;
    return true;
  }
  int count(int kind, int sign = 0) const {
    int n = 0;
    for (const auto& d : disks)
      if (d.cluster_size == 1 && d.kind == kind && (sign == 0 || d.sign == sign)) ++n;
    return n;
  }
  /// Is x within disk k (exactly)?
  bool contains(std::size_t k, const Qx& x) const { return norm2(x - disks[k].centre) <= disks[k].radius2; }
};

namespace detail {

/// t <= R for R = sqrt(r2) >= 0, exactly.
inline bool le_sqrt(const Rational& t, const Rational& r2) { return t <= 0 || t * t <= r2; }

/// Disks k and j disjoint: |z_k - z_j| > R_k + R_j  <=>  d2 - R_k^2 - R_j^2 > 2 R_k R_j.
inline bool disjoint(const RootCertificate::Disk& a, const RootCertificate::Disk& b) {
  const Rational lhs = norm2(a.centre - b.centre) - a.radius2 - b.radius2;
  return lhs > 0 && lhs * lhs > 4 * a.radius2 * b.radius2;
}

/// Exact disks for the given centres (nullopt if two centres coincide).
inline std::optional<std::vector<RootCertificate::Disk>> exact_disks(const Quartic<Rational>& f,
                                                                     const std::array<Qx, 4>& z) {
  std::vector<RootCertificate::Disk> disks(4);
  for (std::size_t k = 0; k < 4; ++k) {
    Qx p{f[4], Rational(0)};  // f / f4 at z_k, by Horner
    for (int i = 3; i >= 0; --i) p = p * z[k] + Qx{f[static_cast<std::size_t>(i)], Rational(0)};
    p = {p.re / f[4], p.im / f[4]};
    Qx den{Rational(1), Rational(0)};
    for (std::size_t j = 0; j < 4; ++j)
      if (j != k) den = den * (z[k] - z[j]);
    const Rational d2 = norm2(den);
    if (d2 == 0) return std::nullopt;
    disks[k].centre = z[k];
    disks[k].radius2 = 16 * norm2(p) / d2;  // (n |W_k|)^2, n = 4
  }
  for (std::size_t k = 0; k < 4; ++k) disks[k].cluster = static_cast<int>(k);
  // Connected components of the overlap graph (4 disks: a few union passes suffice).
  for (int pass = 0; pass < 4; ++pass)
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t j = 0; j < 4; ++j)
        if (k != j && !disjoint(disks[k], disks[j])) {
          const int c = std::min(disks[k].cluster, disks[j].cluster);
          disks[k].cluster = disks[j].cluster = c;
        }
  for (auto& d : disks)
    for (const auto& o : disks)
      if (o.cluster == d.cluster) ++d.cluster_size;
  return disks;
}

}  // namespace detail

/// Certified facts about the roots of f (degree 4 with f[4] != 0), from MPFR approximations.
inline RootCertificate certify_roots(const Quartic<Rational>& f) {
  const std::array<Cx, 4> approx = aberth_roots(f);
  std::array<Qx, 4> z;
  for (std::size_t k = 0; k < 4; ++k) z[k] = {approx[k].re.exact(), approx[k].im.exact()};
  RootCertificate out;
  auto disks = detail::exact_disks(f, z);
  if (!disks) return out;
  // An isolated disk that meets the real axis is re-centred on it (the moved centre stays inside
  // the disk, so it cannot coincide with another centre); then everything is recomputed.
  bool moved = false;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& d = (*disks)[k];
    if (d.cluster_size == 1 && d.centre.im != 0 && d.centre.im * d.centre.im <= d.radius2) {
      z[k].im = 0;
      moved = true;
    }
  }
  if (moved) {
    disks = detail::exact_disks(f, z);
    if (!disks) return out;
  }
  out.valid = true;
  out.disks = *disks;
  for (auto& d : out.disks) {
    if (d.cluster_size != 1) continue;
    if (d.centre.im == 0) {
      d.kind = 1;
      if (d.centre.re * d.centre.re > d.radius2) d.sign = d.centre.re > 0 ? 1 : -1;
    } else if (d.centre.im * d.centre.im > d.radius2) {
      d.kind = -1;
    }
  }
  return out;
}

/// Does the real interval [lo, hi] meet the real segment of disk k?
inline bool interval_meets_disk(const RootCertificate& c, std::size_t k, const Rational& lo, const Rational& hi) {
  const auto& d = c.disks[k];
  // The disk meets the real axis in [x - w, x + w] with w^2 = R^2 - y^2 (if non-negative).
  const Rational w2 = d.radius2 - d.centre.im * d.centre.im;
  if (w2 < 0) return false;
  return detail::le_sqrt(lo - d.centre.re, w2) && detail::le_sqrt(d.centre.re - hi, w2);
}

// ---------------------------------------------------------------------------------------------
// f, s and smallness by other formulas than the library's
// ---------------------------------------------------------------------------------------------

/// f(l) = det(l P + E) by exact Gaussian elimination (det4) at l = 0, +-1, +-2 and Lagrange
/// interpolation (the library expands the determinant symbolically by Laplace).
inline Quartic<Rational> interpolated_f(const Matrix4& e, const Matrix4& p) {
  const long xs[5] = {0, 1, -1, 2, -2};
  Rational ys[5];
  for (int i = 0; i < 5; ++i) {
    Matrix4 m;
    for (std::size_t k = 0; k < 16; ++k) m.a[k] = Q(xs[i]) * p.a[k] + e.a[k];
    ys[i] = det4(m);
  }
  Quartic<Rational> f{};
  for (int i = 0; i < 5; ++i) {
    // basis polynomial prod_{j != i} (l - x_j) / (x_i - x_j)
    std::array<Rational, 5> b{Rational(1), Rational(0), Rational(0), Rational(0), Rational(0)};
    Rational den(1);
    int deg = 0;
    for (int j = 0; j < 5; ++j) {
      if (j == i) continue;
      for (int d = deg + 1; d >= 1; --d)
        b[static_cast<std::size_t>(d)] = b[static_cast<std::size_t>(d - 1)] - Q(xs[j]) * b[static_cast<std::size_t>(d)];
      b[0] = -Q(xs[j]) * b[0];
      ++deg;
      den *= Q(xs[i] - xs[j]);
    }
    for (std::size_t d = 0; d < 5; ++d) f[d] += ys[i] * b[d] / den;
  }
  return f;
}

/// s(l) = det(l A + M) (3x3 blocks) from det3 at l = 0, 1, -1; the l^3 coefficient det A is
/// checked to be 0 at l = 2 (returns nullopt otherwise).
inline std::optional<Quadratic<Rational>> interpolated_s(const Matrix4& e, const Matrix4& p) {
  auto at = [&](long l) {
    Matrix3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = Q(l) * p(i, j) + e(i, j);
    return det3(m);
  };
  const Rational y0 = at(0), y1 = at(1), ym = at(-1);
  const Quadratic<Rational> s{y0, (y1 - ym) / 2, (y1 + ym) / 2 - y0};
  if (at(2) != s[0] + 2 * s[1] + 4 * s[2]) return std::nullopt;
  return s;
}

/// Sign of rho - 1 (math.md §5) from the closed form of the root of s nearest 0:
/// l = (-s1 + sqrt(D)) / (2 s2), D = s1^2 - 4 s0 s2, K = (f0 / f4)(s2 / s0), rho = K / l^2.
/// With sigma = s1/s2 > 0 and pi = s0/s2 > 0 (both roots of s negative), l^2 = (sigma^2 - 2 pi -
/// sigma sqrt(D')) / 2, D' = sigma^2 - 4 pi, so  K <= l^2  <=>  L := 2K - sigma^2 + 2 pi <= -sigma
/// sqrt(D')  <=>  L <= 0 and L^2 >= sigma^2 D'  (the library uses the Graeffe square instead).
inline int rho_vs_one(const Quartic<Rational>& f, const Quadratic<Rational>& s) {
  const Rational sigma = s[1] / s[2], pi = s[0] / s[2];
  const Rational k = (f[0] / f[4]) * (s[2] / s[0]);
  const Rational l = 2 * k - sigma * sigma + 2 * pi, rhs2 = sigma * sigma * (sigma * sigma - 4 * pi);
  if (l > 0 || l * l < rhs2) return 1;  // K > l^2
  return l * l == rhs2 ? 0 : -1;
}

}  // namespace rt
