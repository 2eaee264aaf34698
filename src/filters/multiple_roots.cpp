#include "filters/multiple_roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "algebra/forms.hpp"
#include "algebra/small_factor.hpp"

namespace relpos {
namespace {

using Int = CheckedInt::Int;

// ---------------------------------------------------------------------------------------------
// Exact integer matrices from exact doubles.

using detail::forms::MatrixOf;

/// m scaled by the power of two that makes every entry an integer with an odd entry somewhere
/// (exact: the bits are read directly, no libm call). Returns the largest bit length of an entry,
/// or -1 if an entry needs more than 62 bits.
int integer_matrix(const DoubleMatrix4& m, MatrixOf<long long>& out) {
  std::uint64_t mant[16];
  int low[16];  // entry = +-mant * 2^low, mant odd (or 0)
  int lowest = 1 << 20;
  for (std::size_t i = 0; i < 16; ++i) {
    std::uint64_t b;
    std::memcpy(&b, &m[i], sizeof b);
    const int field = static_cast<int>((b >> 52) & 0x7ff);
    if (field == 0x7ff) return -1;  // not finite (never for validated quadrics)
    std::uint64_t frac = b & ((std::uint64_t{1} << 52) - 1);
    const int e2 = field == 0 ? -1074 : field - 1075;
    if (field != 0) frac |= std::uint64_t{1} << 52;
    if (frac == 0) {
      mant[i] = 0;
      low[i] = 0;
      continue;
    }
    const int tz = __builtin_ctzll(frac);
    mant[i] = frac >> tz;
    low[i] = e2 + tz;
    lowest = std::min(lowest, low[i]);
  }
  int max_bits = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    if (mant[i] == 0) {
      out.a[i] = 0;
      continue;
    }
    const int shift = low[i] - lowest;
    const int bits = 64 - __builtin_clzll(mant[i]) + shift;
    if (bits > 62) return -1;
    max_bits = std::max(max_bits, bits);
    const auto v = static_cast<long long>(mant[i] << shift);
    out.a[i] = m[i] < 0 ? -v : v;
  }
  return max_bits;
}

/// Entries below 2^13 keep f in plain 64-bit arithmetic: a 2x2 minor of the pencil has
/// coefficients below 4 * 2^(2B), a product of two minors below 48 * 2^(4B), and f sums six of
/// them: below 2^(4B+9) <= 2^61 for B = 13 (s is smaller). No check needed, one instruction each.
constexpr int kPlainBits = 13;

template <class NT, class In>
MachinePencil pencil_in(const In& p, const In& e) {
  MatrixOf<NT> pn, en;
  for (std::size_t i = 0; i < 16; ++i) {
    pn.a[i] = NT(p.a[i]);
    en.a[i] = NT(e.a[i]);
  }
  const auto f = characteristic_polynomial<NT>(pn, en);
  const auto s = special_polynomial<NT>(pn, en);
  MachinePencil mp;
  for (std::size_t i = 0; i < 5; ++i) mp.f[i] = CheckedInt(f[i]);
  for (std::size_t i = 0; i < 3; ++i) mp.s[i] = CheckedInt(s[i]);
  return mp;
}

// ---------------------------------------------------------------------------------------------
// Exact polynomial arithmetic on CheckedInt (degree <= 4).

struct Poly {
  CheckedInt c[5];
  int degree = -1;
  double at(double x) const {  // for the numerical search only
    double v = 0;
    for (int i = degree; i >= 0; --i) v = v * x + static_cast<double>(c[i].value());
    return v;
  }
};

/// h = g * (q x - p) exactly, or false. (q x - p) g has x^i coefficient q g_(i-1) - p g_i, so
/// g_(d-1) = h_d / q, g_(i-1) = (h_i + p g_i) / q, and the remainder condition is h_0 + p g_0 = 0.
/// By Gauss's lemma every division is exact when p/q (lowest terms) is a root.
bool divide_linear(const Poly& h, const CheckedInt& p, const CheckedInt& q, Poly& g) {
  const int d = h.degree;
  if (d < 1) return false;
  g.degree = d - 1;
  g.c[d - 1] = exact_quotient(h.c[d], q);
  for (int i = d - 1; i >= 1; --i) g.c[i - 1] = exact_quotient(h.c[i] + p * g.c[i], q);
  const CheckedInt rem = h.c[0] + p * g.c[0];
  return rem.valid() && rem.value() == 0 && g.c[0].valid();
}

Int gcd(Int a, Int b) {
  if (a < 0) a = -a;
  if (b < 0) b = -b;
  while (b != 0) {
    if (a == static_cast<long long>(a) && b == static_cast<long long>(b)) {  // hardware division
      long long x = static_cast<long long>(a), y = static_cast<long long>(b);
      while (y != 0) {
        const long long t = x % y;
        x = y;
        y = t;
      }
      return x;
    }
    const Int t = a % b;
    a = b;
    b = t;
  }
  return a;
}

// ---------------------------------------------------------------------------------------------
// Numerical proposals (never trusted: each is verified exactly).

/// Real roots of c2 x^2 + c1 x + c0 (c2 != 0), stable form.
int quadratic_roots(double c2, double c1, double c0, double* out) {
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (!(disc >= 0)) return 0;
  const double t = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  int n = 0;
  if (t != 0) {
    out[n++] = t / c2;
    out[n++] = c0 / t;
  } else {
    out[n++] = 0;
  }
  return n;
}

/// Real roots of the cubic c (c[3] != 0): the closed form (Numerical Recipes' trigonometric and
/// Cardano branches on the monic cubic), each root then polished by two Newton steps. A proposal
/// only: the exact verification decides.
int cubic_roots(const double* c, double* out) {
  const double a = c[2] / c[3], b = c[1] / c[3], d = c[0] / c[3];
  const double q = (a * a - 3 * b) / 9, r = (2 * a * a * a - 9 * a * b + 27 * d) / 54;
  const double q3 = q * q * q;
  int n = 0;
  if (r * r < q3) {  // three real roots
    const double theta = std::acos(std::clamp(r / std::sqrt(q3), -1.0, 1.0));
    const double m = -2 * std::sqrt(q);
    constexpr double kTwoPi = 6.283185307179586;
    for (int k = 0; k < 3; ++k) out[n++] = m * std::cos((theta + kTwoPi * k) / 3) - a / 3;
  } else {  // one real root (or a multiple one)
    const double big = -std::copysign(std::cbrt(std::fabs(r) + std::sqrt(r * r - q3)), r);
    out[n++] = (big + (big != 0 ? q / big : 0)) - a / 3;
  }
  for (int i = 0; i < n; ++i) {
    double& x = out[i];
    for (int it = 0; it < 2; ++it) {
      const double v = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
      const double dv = (3 * c[3] * x + 2 * c[2]) * x + c[1];
      if (dv == 0 || !std::isfinite(v)) break;
      x -= v / dv;
    }
  }
  return n;
}

// ---------------------------------------------------------------------------------------------
// The certificate.

struct Found {
  CheckedInt p, q;  // the root p/q, q > 0, lowest terms
  int mult_f = 0;
};

struct Search {
  Poly h;  // f with the multiple roots found so far divided out
  Found found[2];
  int count = 0;

  bool known(Int p, Int q) const {
    for (int i = 0; i < count; ++i)
      if (found[i].p.value() == p && found[i].q.value() == q) return true;
    return false;
  }
  /// The cofactor is square-free (degree <= 1, or a quadratic with non-zero discriminant) and at
  /// least one multiple root was found: f is completely split into what the facts need.
  bool complete() const {
    if (count == 0) return false;
    if (h.degree <= 1) return true;
    if (h.degree > 2) return false;
    const CheckedInt d = h.c[1] * h.c[1] - CheckedInt(4) * h.c[2] * h.c[0];
    return d.valid() && d.value() != 0;
  }
  /// Verify the candidate p/q (q > 0, lowest terms) exactly; keep it if it is a multiple root of
  /// the cofactor.
  void try_rational(Int p, Int q) {
    if (count == 2 || known(p, q)) return;
    const CheckedInt cp = CheckedInt::from(p), cq = CheckedInt::from(q);
    Poly cur = h, next;
    int m = 0;
    while (cur.degree >= 1 && divide_linear(cur, cp, cq, next)) {
      cur = next;
      ++m;
    }
    if (m < 2) return;
    h = cur;
    found[count++] = Found{cp, cq, m};
  }
  /// Continued-fraction convergents of x within a relative tolerance of x, each verified exactly.
  void try_double(double x) {
    if (!std::isfinite(x) || std::fabs(x) > 0x1p50) return;
    const double tol = 0x1p-30 * std::max(1.0, std::fabs(x));
    double r = x;
    Int h1 = 1, h2 = 0, k1 = 0, k2 = 1;
    int tried = 0;
    for (int it = 0; it < 40 && tried < 3; ++it) {
      const double a = std::floor(r);
      if (std::fabs(a) > 0x1p52) return;
      const Int ai = static_cast<long long>(a);  // |a| <= 2^52
      const Int hn = ai * h1 + h2, kn = ai * k1 + k2;
      if (kn > (Int{1} << 40) || hn > (Int{1} << 62) || hn < -(Int{1} << 62)) return;
      h2 = h1, h1 = hn, k2 = k1, k1 = kn;
      if (std::fabs(x - static_cast<double>(hn) / static_cast<double>(kn)) <= tol) {
        ++tried;
        try_rational(hn, kn);  // convergents are in lowest terms, with kn > 0
        if (complete()) return;
      }
      const double frac = r - a;
      if (frac < 0x1p-60) return;
      r = 1 / frac;
    }
  }
};

/// Multiplicity of the root p/q as a root of the quadratic s (0, 1 or 2), or -1 on overflow.
int multiplicity_in_s(const Quadratic<CheckedInt>& s, const CheckedInt& p, const CheckedInt& q) {
  const CheckedInt v = s[2] * p * p + s[1] * p * q + s[0] * q * q;  // q^2 s(p/q)
  if (!v.valid()) return -1;
  if (v.value() != 0) return 0;
  const CheckedInt d = CheckedInt(2) * s[2] * p + s[1] * q;  // q s'(p/q)
  if (!d.valid()) return -1;
  return d.value() == 0 ? 2 : 1;
}

/// Common roots of two polynomials of degree <= 2 without multiple common roots of h (h
/// square-free), counted as min of the multiplicities; -1 on overflow.
int common_roots(const Poly& h, const Poly& r) {
  if (h.degree < 1 || r.degree < 1) return 0;
  const Poly& a = h.degree >= r.degree ? h : r;  // a has the larger degree
  const Poly& b = h.degree >= r.degree ? r : h;
  CheckedInt res;
  if (b.degree == 1) {  // b1^2 a(-b0/b1), up to the power of b1 needed to clear denominators
    if (a.degree == 1)
      res = a.c[1] * b.c[0] - a.c[0] * b.c[1];
    else
      res = a.c[2] * b.c[0] * b.c[0] - a.c[1] * b.c[0] * b.c[1] + a.c[0] * b.c[1] * b.c[1];
    if (!res.valid()) return -1;
    return res.value() == 0 ? 1 : 0;
  }
  // Two quadratics: Res = (a2 b0 - a0 b2)^2 - (a2 b1 - a1 b2)(a1 b0 - a0 b1).
  const CheckedInt u = a.c[2] * b.c[0] - a.c[0] * b.c[2], v = a.c[2] * b.c[1] - a.c[1] * b.c[2],
                   w = a.c[1] * b.c[0] - a.c[0] * b.c[1];
  res = u * u - v * w;
  if (!res.valid()) return -1;
  if (res.value() != 0) return 0;
  // Proportional quadratics share both roots; h square-free makes both simple.
  return (v.value() == 0 && u.value() == 0) ? 2 : 1;
}

/// A root of multiplicity m is a simple root of f^(m-1): propose the roots of f' (double roots),
/// then of f'' (triple), then the root -f3 / (4 f4) of f''' (quadruple; exact, no numerics), each
/// verified by exact division. False when they do not account for every multiple root.
bool find_multiple_roots(const Quartic<CheckedInt>& f, Search& search) {
  double fd[5];
  for (int i = 0; i < 5; ++i) fd[i] = static_cast<double>(f[static_cast<std::size_t>(i)].value());
  const double d1[4] = {fd[1], 2 * fd[2], 3 * fd[3], 4 * fd[4]};
  double xs[3];
  const int n1 = cubic_roots(d1, xs);
  for (int i = 0; i < n1 && !search.complete(); ++i) search.try_double(xs[i]);
  if (!search.complete()) {
    const int n2 = quadratic_roots(12 * fd[4], 6 * fd[3], 2 * fd[2], xs);
    for (int i = 0; i < n2 && !search.complete(); ++i) search.try_double(xs[i]);
  }
  if (!search.complete()) {
    CheckedInt p = -f[3], q = CheckedInt(4) * f[4];
    if (p.valid() && q.valid()) {
      Int a = p.value(), b = q.value();
      if (b < 0) a = -a, b = -b;
      const Int g = gcd(a, b);  // b != 0, so g != 0
      search.try_rational(a / g, b / g);
    }
  }
  return search.complete();
}

/// The found multiple roots counted into r (by sign; tangent ones apart: math.md §3, tangency <=>
/// mult_f - mult_s >= 2) and divided out of s_rest; returns their part of deg gcd(f, s), or -1 on
/// overflow.
int count_found_roots(const Search& search, const Quadratic<CheckedInt>& s, RootFacts& r, Poly& s_rest) {
  int gcd_degree = 0;
  for (int i = 0; i < search.count; ++i) {
    const Found& x = search.found[i];
    const int ms = multiplicity_in_s(s, x.p, x.q);
    if (ms < 0) return -1;
    (x.p.value() < 0 ? r.negative : r.positive) += 1;
    if (x.mult_f - ms >= 2) (x.p.value() < 0 ? r.tangent_negative : r.tangent_positive) += 1;
    gcd_degree += std::min(x.mult_f, ms);
    for (int k = 0; k < ms; ++k) {
      Poly next;
      if (!divide_linear(s_rest, x.p, x.q, next)) return -1;  // cannot happen: s(p/q) = 0
      s_rest = next;
    }
  }
  return gcd_degree;
}

/// The square-free cofactor h's roots added to r: its real roots by sign, its non-real pair.
void count_cofactor(const Poly& h, RootFacts& r) {
  int sign_disc_h = 1;
  if (h.degree == 2) sign_disc_h = (h.c[1] * h.c[1] - CheckedInt(4) * h.c[2] * h.c[0]).sign();
  const detail::SmallCount c =
      h.degree >= 1
          ? detail::count_small(h.degree, sign_disc_h, h.degree == 2 ? h.c[2].sign() : 0, h.c[1].sign(), h.c[0].sign())
          : detail::SmallCount{};
  r.negative += c.negative;
  r.positive += c.positive;
  r.nonreal = (h.degree == 2 && sign_disc_h < 0) ? 2 : 0;
}

}  // namespace

std::optional<MachinePencil> machine_pencil(const DoubleMatrix4& p, const DoubleMatrix4& e) {
  MatrixOf<long long> pi, ei;
  const int bp = integer_matrix(p, pi), be = integer_matrix(e, ei);
  if (bp < 0 || be < 0) return std::nullopt;
  if (std::max(bp, be) <= kPlainBits) return pencil_in<long long>(pi, ei);
  MachinePencil mp = pencil_in<CheckedInt>(pi, ei);
  for (const auto& c : mp.f)
    if (!c.valid()) return std::nullopt;
  for (const auto& c : mp.s)
    if (!c.valid()) return std::nullopt;
  return mp;
}

std::optional<RootFacts> rational_multiple_root_facts(const Quartic<CheckedInt>& f, const Quadratic<CheckedInt>& s) {
  Search search;
  search.h.degree = 4;
  for (int i = 0; i < 5; ++i) search.h.c[i] = f[static_cast<std::size_t>(i)];
  if (search.h.c[4].value() == 0 || search.h.c[0].value() == 0) return std::nullopt;
  if (!find_multiple_roots(f, search)) return std::nullopt;
  RootFacts r;
  Poly s_rest;  // s with its roots among the multiple roots of f divided out
  s_rest.degree = 2;
  for (int i = 0; i < 3; ++i) s_rest.c[i] = s[static_cast<std::size_t>(i)];
  const int gcd_degree = count_found_roots(search, s, r, s_rest);
  if (gcd_degree < 0) return std::nullopt;
  const Poly& h = search.h;  // square-free, none of its roots is a found root
  count_cofactor(h, r);
  r.real = r.negative + r.positive;
  r.nonreal_multiple = 0;  // every multiple root found is rational
  r.sign_disc_f = 0;
  // Square-free real polynomial: sign Disc = (-1)^(non-real pairs); f~ keeps f's non-real roots.
  r.sign_disc_ftilde = (r.tangent_negative + r.tangent_positive) ? 0 : ((r.nonreal / 2) % 2 ? -1 : 1);
  const int shared = common_roots(h, s_rest);
  r.degree_ftilde = shared < 0 ? -1 : 4 - gcd_degree - shared;
  return r;
}

}  // namespace relpos
