// Crossing witnesses (math.md §18): the minimiser of g over the solid K approached along the pencil
// G + s K, in doubles, then in MPFR with doubling precision, each candidate checked exactly.
#include "general/witness.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "algebra/matrix4.hpp"
#include "general/pencil.hpp"

namespace relpos::detail::general {
namespace {

using detail::form_at;

// ---- an MPFR number at the thread's working precision --------------------------------------------

thread_local mpfr_prec_t working_precision = 128;

class Big {
 public:
  Big() { mpfr_init2(v_, working_precision), mpfr_set_zero(v_, 1); }
  Big(double x) { mpfr_init2(v_, working_precision), mpfr_set_d(v_, x, MPFR_RNDN); }  // NOLINT: implicit
  Big(const Big& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)), mpfr_set(v_, o.v_, MPFR_RNDN); }
  Big(Big&& o) noexcept { mpfr_init2(v_, mpfr_get_prec(o.v_)), mpfr_swap(v_, o.v_); }
  Big& operator=(const Big& o) {
    if (this != &o) mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  Big& operator=(Big&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Big() { mpfr_clear(v_); }
  static Big of(const Rational& q) {
    Big b;
    mpfr_set_q(b.v_, q.mpq(), MPFR_RNDN);
    return b;
  }
  Rational exact() const {
    if (mpfr_zero_p(v_)) return Rational(0);
    Integer m;
    const mpfr_exp_t e = mpfr_get_z_2exp(m.mpz(), v_);
    Rational r(m);
    if (e >= 0) {
      mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(e));
    } else {
      mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-e));
    }
    return r;
  }
  friend Big operator+(const Big& a, const Big& b) { return op(a, b, mpfr_add); }
  friend Big operator-(const Big& a, const Big& b) { return op(a, b, mpfr_sub); }
  friend Big operator*(const Big& a, const Big& b) { return op(a, b, mpfr_mul); }
  friend Big operator/(const Big& a, const Big& b) { return op(a, b, mpfr_div); }
  friend Big operator-(const Big& a) {
    Big r;
    mpfr_neg(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend bool operator<(const Big& a, const Big& b) { return mpfr_less_p(a.v_, b.v_) != 0; }
  friend bool operator>(const Big& a, const Big& b) { return mpfr_greater_p(a.v_, b.v_) != 0; }
  friend bool operator!=(const Big& a, const Big& b) { return mpfr_lessgreater_p(a.v_, b.v_) != 0; }
  friend Big sqrt(const Big& a) {
    Big r;
    mpfr_sqrt(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend Big fabs(const Big& a) {
    Big r;
    mpfr_abs(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend bool isfinite(const Big& a) { return mpfr_number_p(a.v_) != 0; }

 private:
  template <class F>
  static Big op(const Big& a, const Big& b, F f) {
    Big r;
    f(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  mpfr_t v_;
};

// ---- the numeric type's conversions -------------------------------------------------------------

template <class T>
T from_rational(const Rational& q);
template <>
double from_rational<double>(const Rational& q) {
  return mpq_get_d(q.mpq());
}
template <>
Big from_rational<Big>(const Rational& q) {
  return Big::of(q);
}
Rational to_rational(double x) { return Rational(x); }
Rational to_rational(const Big& x) { return x.exact(); }
using std::fabs;
using std::isfinite;
using std::sqrt;

template <class T>
struct View {
  std::array<T, 16> a;
  const T& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// m times the power of two that brings its largest entry near 1 (exact; points are unchanged).
template <class T>
View<T> scaled(const Matrix4& m) {
  long top = LONG_MIN;
  for (const Rational& x : m.a) {
    if (x == 0) continue;
    const long e = static_cast<long>(mpz_sizeinbase(mpq_numref(x.mpq()), 2)) -
                   static_cast<long>(mpz_sizeinbase(mpq_denref(x.mpq()), 2));
    top = std::max(top, e);
  }
  View<T> v;
  for (std::size_t i = 0; i < 16; ++i) {
    Rational x;  // fresh (written through mpq(); a copy of m.a[i] would share its value)
    if (top >= 0) {
      mpq_div_2exp(x.mpq(), m.a[i].mpq(), static_cast<mp_bitcnt_t>(top));
    } else {
      mpq_mul_2exp(x.mpq(), m.a[i].mpq(), static_cast<mp_bitcnt_t>(-top));
    }
    v.a[i] = from_rational<T>(x);
  }
  return v;
}

template <class T, std::size_t N>
T horner(const std::array<T, N>& c, const T& x) {
  T v = c[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) v = v * x + c[i];
  return v;
}

template <class T, std::size_t N>
std::array<T, N - 1> derivative(const std::array<T, N>& c) {
  std::array<T, N - 1> d;
  for (std::size_t i = 1; i < N; ++i) d[i - 1] = c[i] * T(static_cast<double>(i));
  return d;
}

/// The 3x3 system (B + s M) x = -(b + s m) by Cramer's rule; nullopt when singular.
template <class T>
std::optional<std::array<T, 3>> stationary(const View<T>& k, const View<T>& g, const T& s) {
  T a[3][3], r[3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[i][j] = g(i, j) + s * k(i, j);
    r[i] = -(g(i, 3) + s * k(i, 3));
  }
  auto det3 = [](const T m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const T det = det3(a);
  if (!(fabs(det) > T(0)) || !isfinite(det)) return std::nullopt;
  std::array<T, 3> x;
  for (int c = 0; c < 3; ++c) {
    T m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == c ? r[i] : a[i][j];
    x[static_cast<std::size_t>(c)] = det3(m) / det;
  }
  return x;
}

/// The largest root of a cubic with three real roots and a positive leading coefficient: Newton from
/// above the Samuelson bound (mean + sqrt(2) sigma of the roots), monotone for a real-rooted cubic.
template <class T>
T largest_root(const Cubic<T>& d) {
  const T mean = -d[2] / (T(3.0) * d[3]);
  const T sum_sq = (d[2] * d[2] - T(2.0) * d[1] * d[3]) / (d[3] * d[3]);
  T var = sum_sq / T(3.0) - mean * mean;
  if (var < T(0)) var = T(0);
  T x = mean + T(1.5) * sqrt(var) + fabs(mean) * T(1e-6) + T(1e-300);
  const Quadratic<T> dd = derivative(d);
  for (int i = 0; i < 400; ++i) {
    const T v = horner(d, x), dv = horner(dd, x);
    if (!(dv > T(0))) break;
    const T next = x - v / dv;
    if (!(next < x)) break;  // converged (monotone from above)
    x = next;
  }
  return x;
}

template <class T>
T quadratic_form(const View<T>& m, const std::array<T, 3>& x) {
  const T v[4] = {x[0], x[1], x[2], T(1.0)};
  T s(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s = s + v[i] * m(i, j) * v[j];
  return s;
}

/// The secular polynomial S = f' d - f d' of the pencil (degree 6).
template <class T>
std::array<T, 7> secular(const Quartic<T>& f, const Cubic<T>& d) {
  std::array<T, 7> s;
  for (T& c : s) c = T(0.0);
  const Cubic<T> fp = derivative(f);
  const Quadratic<T> dp = derivative(d);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) s[i + j] = s[i + j] + fp[i] * d[j];
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 3; ++j) s[i + j] = s[i + j] - f[i] * dp[j];
  return s;
}

/// The root of S beyond the end lo, where S goes from + to - (safeguarded Newton from lo + probe);
/// nullopt when S is not positive there.
template <class T>
std::optional<T> secular_root(const std::array<T, 7>& s, const T& lo, const T& probe, const T& unit, const T& tol,
                              int bits) {
  const T zero(0.0);
  const std::array<T, 6> sp = derivative(s);
  T a = lo + probe, b = lo + unit;
  if (!(horner(s, a) > zero)) return std::nullopt;
  for (int i = 0; i < 4000 && !(horner(s, b) < zero); ++i) b = b + (b - lo);
  T x = (a + b) * T(0.5);
  for (int i = 0; i < 4 * bits + 200 && b - a > tol * (fabs(x) + T(1.0)); ++i) {
    const T v = horner(s, x);
    if (!(v != zero)) break;
    if (v > zero) a = x;
    if (v < zero) b = x;
    T next = x - v / horner(sp, x);
    if (!(next > a && next < b)) next = (a + b) * T(0.5);
    if (!(fabs(next - x) > zero)) break;
    x = next;
  }
  return x;
}

/// A unit vector spanning (nearly) the kernel of B + at M, by inverse iteration.
template <class T>
std::array<T, 3> kernel_direction(const View<T>& k, const View<T>& g, const T& at) {
  const T zero(0.0);
  std::array<T, 3> w{T(1.0), T(0.7), T(0.3)};
  View<T> none = k;  // the zero pencil: stationary(none, p, 0) solves P3 x = -p
  for (T& x : none.a) x = zero;
  for (int it = 0; it < 6; ++it) {
    // (B + a M) w' = M w: the stationary system of the matrix G + a K with its last column -M w.
    View<T> pencil = g;
    for (std::size_t i = 0; i < 16; ++i) pencil.a[i] = g.a[i] + at * k.a[i];
    for (int i = 0; i < 3; ++i) {
      T mw(0.0);
      for (int j = 0; j < 3; ++j) mw = mw + k(i, j) * w[static_cast<std::size_t>(j)];
      pencil.a[static_cast<std::size_t>(4 * i + 3)] = -mw;
    }
    const auto w2 = stationary(none, pencil, zero);
    if (!w2) break;
    T norm(0.0);
    for (const T& c : *w2) norm = norm + c * c;
    norm = sqrt(norm);
    if (!(norm > zero)) break;
    for (std::size_t i = 0; i < 3; ++i) w[i] = (*w2)[i] / norm;
  }
  return w;
}

/// k(x_hat + sigma w) = k0 + 2 sigma k1 + sigma^2 k2: the points x_hat + sigma w at its roots sigma,
/// on K's surface, where g = optimum - s_lo k is least; appended to `out`.
template <class T>
void surface_points(const View<T>& k, const std::array<T, 3>& x_hat, const std::array<T, 3>& w,
                    std::vector<std::array<T, 3>>& out) {
  const T zero(0.0);
  T k1(0.0), k2(0.0);
  for (int i = 0; i < 3; ++i) {
    T row = k(i, 3), mw(0.0);
    for (int j = 0; j < 3; ++j) {
      row = row + k(i, j) * x_hat[static_cast<std::size_t>(j)];
      mw = mw + k(i, j) * w[static_cast<std::size_t>(j)];
    }
    k1 = k1 + w[static_cast<std::size_t>(i)] * row;
    k2 = k2 + w[static_cast<std::size_t>(i)] * mw;
  }
  const T k0 = quadratic_form(k, x_hat);
  const T disc = k1 * k1 - k0 * k2;
  if (!(disc > zero) || !(k2 > zero)) return;
  for (const T& sigma : {(-k1 + sqrt(disc)) / k2, (-k1 - sqrt(disc)) / k2}) {
    std::array<T, 3> y;
    for (std::size_t i = 0; i < 3; ++i) y[i] = x_hat[i] + sigma * w[i];
    out.push_back(y);
  }
}

/// Approximations of the minimiser of g over K's solid (math.md §18), as candidates: x(0) when the
/// pencil's 3x3 block is definite at 0 (the optimal multiplier may be 0), x(s*) at the root s* of the
/// secular polynomial S = F'D - F D' beyond the end s_lo of the interval, and the hard case's point:
/// lim x(s) (s -> s_lo) moved along the kernel of the block at s_lo onto K's surface. Near s_lo the
/// sign of S is lost in rounding whenever S vanishes there (S = c D^2 for a concentric pair), so no
/// candidate is trusted: the caller checks each exactly.
template <class T>
std::vector<std::array<T, 3>> minimisers(const Matrix4& km, const Matrix4& gm, int bits) {
  std::vector<std::array<T, 3>> out;
  const View<T> k = scaled<T>(km), g = scaled<T>(gm);
  const Quartic<T> f = pencil_quartic<T>(k, g);
  const Cubic<T> d = pencil_cubic<T>(k, g);
  const std::array<T, 7> s = secular(f, d);
  const T zero(0.0);
  const T r3 = largest_root(d);
  const bool end_at_zero = !(r3 > zero);
  const T lo = end_at_zero ? zero : r3;
  if (end_at_zero)
    if (const auto x0 = stationary(k, g, zero)) out.push_back(*x0);
  const T unit = fabs(lo) + T(1.0);
  T eps = unit, probe = unit, tol = unit;
  for (int i = 0; i < bits / 2; ++i) eps = eps * T(0.5);
  for (int i = 0; i < bits / 4; ++i) probe = probe * T(0.5);
  for (int i = 0; i < bits - 2; ++i) tol = tol * T(0.5);
  if (const auto root = secular_root(s, lo, probe, unit, tol, bits))
    if (const auto xs = stationary(k, g, *root)) out.push_back(*xs);
  // The hard case: x_hat = lim x(s), s -> s_lo; w spans the kernel of B + s_lo M.
  const auto x_hat = stationary(k, g, lo + eps);
  if (!x_hat) return out;
  out.push_back(*x_hat);  // at the end 0, a root of D, g equals its optimum on the kernel set
  surface_points(k, *x_hat, kernel_direction(k, g, lo + eps), out);
  return out;
}

/// The centre -M^-1 m of the ellipsoid K, exactly (Cramer).
Vector3 centre_of(const Matrix4& k) {
  auto det3 = [](const Rational m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  Rational a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = k(i, j);
  const Rational det = det3(a);
  Vector3 c;
  for (int col = 0; col < 3; ++col) {
    Rational m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == col ? Rational(-k(i, 3)) : a[i][j];
    c[static_cast<std::size_t>(col)] = det3(m) / det;
  }
  return c;
}

/// A witness with short coordinates: x rounded to 2^-k units of its scale for k = 2, 4, 8, ..., the
/// first that still passes the exact checks (a point deep inside the region needs few bits: (3/4, 0, 0)
/// rather than the 53 bits of a double with its rounding noise), else x itself.
Vector3 shortened(const Matrix4& km, const Matrix4& gm, const Vector3& x) {
  long top = 0;
  for (const Rational& v : x)
    if (v != 0)
      top = std::max(top, static_cast<long>(mpz_sizeinbase(mpq_numref(v.mpq()), 2)) -
                              static_cast<long>(mpz_sizeinbase(mpq_denref(v.mpq()), 2)));
  for (long k = 2; k <= 64; k *= 2) {
    const long bits = k - top;  // fractional bits: 2^-k of the largest coordinate
    Vector3 y;
    for (std::size_t i = 0; i < 3; ++i) {
      Rational scaled;  // fresh (written through mpq())
      if (bits >= 0) {
        mpq_mul_2exp(scaled.mpq(), x[i].mpq(), static_cast<mp_bitcnt_t>(bits));
      } else {
        mpq_div_2exp(scaled.mpq(), x[i].mpq(), static_cast<mp_bitcnt_t>(-bits));
      }
      Integer n;
      mpz_fdiv_q(n.mpz(), (scaled + Rational(1, 2)).numerator().mpz(), (scaled + Rational(1, 2)).denominator().mpz());
      Rational r(n);
      if (bits >= 0) {
        mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(bits));
      } else {
        mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-bits));
      }
      y[i] = r;
    }
    if (form_at(km, y) <= 0 && form_at(gm, y) < 0) return y;
  }
  return x;
}

/// The pull towards the centre: x = c + (1 - 2^-p)(y - c), rounded to the numeric type's rationals,
/// for p along a geometric ladder up to the working precision; the first that passes exactly.
template <class T>
std::optional<Vector3> pulled(const Matrix4& km, const Matrix4& gm, const Vector3& c, const std::array<T, 3>& y,
                              int bits) {
  std::array<Rational, 3> yr;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!isfinite(y[i])) return std::nullopt;
    yr[i] = to_rational(y[i]);
  }
  for (double p = 2; p < bits - 4; p *= 1.5) {
    Rational delta(1);
    mpq_div_2exp(delta.mpq(), delta.mpq(), static_cast<mp_bitcnt_t>(p));
    Vector3 x;
    for (std::size_t i = 0; i < 3; ++i) {
      // Rounded to the working precision, so the numbers stay as long as the approximation.
      const T xi = from_rational<T>(c[i] + (Rational(1) - delta) * (yr[i] - c[i]));
      x[i] = to_rational(xi);
    }
    if (form_at(km, x) <= 0 && form_at(gm, x) < 0) return shortened(km, gm, x);
  }
  return std::nullopt;
}

}  // namespace

Vector3 negative_point(const Matrix4& k, const Matrix4& g) {
  const Vector3 c = centre_of(k);
  if (form_at(g, c) < 0) return shortened(k, g, c);
  for (const auto& y : minimisers<double>(k, g, 53))
    if (const auto x = pulled<double>(k, g, c, y, 53)) return *x;
  const mpfr_prec_t saved = working_precision;
  for (int bits = 128; bits <= 8192; bits *= 2) {
    working_precision = bits;
    for (const auto& y : minimisers<Big>(k, g, bits))
      if (const auto x = pulled<Big>(k, g, c, y, bits)) {
        working_precision = saved;
        return *x;
      }
  }
  working_precision = saved;
  throw std::logic_error("relpos internal error: no crossing witness found within 8192 bits");
}

}  // namespace relpos::detail::general
