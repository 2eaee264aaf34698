// The certified double filter of a general pair (math.md §17).
#include "general/filter.hpp"

#include <gmp.h>

#include <array>
#include <cfloat>
#include <climits>
#include <cmath>

#include "algebra/sturm_habicht_quartic.hpp"
#include "filters/ball.hpp"
#include "filters/running_bound.hpp"
#include "general/decision.hpp"
#include "general/pencil.hpp"
#include "general/sturm_habicht_low.hpp"

namespace relpos::general {

Structure structure_of(QuadricType type) {
  switch (type) {
    case QuadricType::Ellipsoid:
      return {0, 0, 0, 3, true};
    case QuadricType::HyperboloidOneSheet:
    case QuadricType::HyperboloidTwoSheets:
      return {0, 0, 1, 2, false};
    case QuadricType::Cone:
      return {1, 0, 1, 2, false};
    case QuadricType::EllipticParaboloid:
      return {0, 1, 0, 2, false};
    case QuadricType::HyperbolicParaboloid:
      return {0, 1, 1, 1, false};
    case QuadricType::EllipticCylinder:
      return {1, 1, 0, 2, false};
    case QuadricType::HyperbolicCylinder:
      return {1, 1, 1, 1, false};
    case QuadricType::ParabolicCylinder:
      return {1, 2, 0, 1, false};
    case QuadricType::Slab:
      return {2, 2, 0, 1, false};
    case QuadricType::HalfSpace:
      return {2, 3, 0, 0, false};
  }
  return {0, 0, 0, 0, false};
}

namespace {

using RB = RunningBound;

struct RBMatrix {
  std::array<RB, 16> a;
  const RB& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// The matrix's entries as running bounds, scaled by a power of two (largest entry near 1; exact, a
/// positive scaling changes no sign): the normalized doubles, the stored enclosures, or enclosures of
/// the rationals (mpq_get_d truncates towards zero: the entry lies between it and the next double
/// away from zero). False when an entry would leave the normal range.
bool load(const detail::QuadricMatrix& s, RBMatrix& out) {
  if (const DoubleMatrix4* d = s.filter_doubles()) {
    for (std::size_t i = 0; i < 16; ++i) out.a[i] = RB((*d)[i]);
    return true;
  }
  const Matrix4& m = s.matrix();
  long top = LONG_MIN;
  for (const Rational& x : m.a)
    if (x != 0)
      top = std::max(top, static_cast<long>(mpz_sizeinbase(mpq_numref(x.mpq()), 2)) -
                              static_cast<long>(mpz_sizeinbase(mpq_denref(x.mpq()), 2)));
  if (top == LONG_MIN) return false;
  mpq_t x;
  mpq_init(x);
  bool ok = true;
  for (std::size_t i = 0; i < 16 && ok; ++i) {
    if (m.a[i] == 0) {
      out.a[i] = RB(0.0);
      continue;
    }
    if (top >= 0) {
      mpq_div_2exp(x, m.a[i].mpq(), static_cast<mp_bitcnt_t>(top));
    } else {
      mpq_mul_2exp(x, m.a[i].mpq(), static_cast<mp_bitcnt_t>(-top));
    }
    const double v = mpq_get_d(x);
    if (!(std::fabs(v) >= 0x1p-900)) ok = false;
    const double away = std::nextafter(v, v > 0 ? HUGE_VAL : -HUGE_VAL);
    out.a[i] = v > 0 ? RB::enclosing(v, away) : RB::enclosing(away, v);
  }
  mpq_clear(x);
  return ok;
}

/// A polynomial with ball coefficients (low degree first): the coefficients of f and D, computed
/// with running bounds, become balls (midpoint = the value, radius = its error bound), so that what
/// is computed from them -- the Sturm–Habicht sequence, values at points -- is bounded through the
/// actual values, not the magnitudes of the determinant expansions behind them (filters/ball.hpp).
template <int N>
struct Poly {
  std::array<Ball, N + 1> c;
  int degree = N;
  Ball at(double x) const {
    Ball v = c[static_cast<std::size_t>(degree)];
    for (int i = degree - 1; i >= 0; --i) v = v * Ball(x) + c[static_cast<std::size_t>(i)];
    return v;
  }
};

Ball ball_of(const RB& x) { return Ball(x.value(), x.error_bound()); }

/// Certified sign variations of a sequence of signs; -1 when one is uncertain (0).
int variations(const int* s, int n) {
  int count = 0, last = 0;
  for (int i = 0; i < n; ++i) {
    if (s[i] == 0) return -1;
    if (last != 0 && s[i] != last) ++count;
    last = s[i];
  }
  return count;
}

/// The Sturm–Habicht sequence of f^ (degree 2, 3 or 4), each member with the sign factor a_n^k_j
/// (sturm_habicht_*.hpp; every k_j is 1).
struct SturmSequence {
  std::array<Poly<4>, 5> p;  // p[0] = f^, p[1] = f^', then g_{n-2}, ..., g_0
  std::array<int, 5> factor{1, 1, 1, 1, 1};
  int count = 0;
  /// The sign variations at x (certified), or -1.
  int at(double x) const {
    int s[5];
    for (int i = 0; i < count; ++i)
      s[i] = factor[static_cast<std::size_t>(i)] * p[static_cast<std::size_t>(i)].at(x).sign();
    return variations(s, count);
  }
  /// At +oo (plus) or -oo: the leading coefficients' signs.
  int at_infinity(bool plus) const {
    int s[5];
    for (int i = 0; i < count; ++i) {
      const Poly<4>& q = p[static_cast<std::size_t>(i)];
      const int lead = q.c[static_cast<std::size_t>(q.degree)].sign();
      s[i] = factor[static_cast<std::size_t>(i)] * ((plus || q.degree % 2 == 0) ? lead : -lead);
    }
    return variations(s, count);
  }
};

bool sturm_sequence(const Poly<4>& f, SturmSequence& out) {
  const int n = f.degree;
  const int lead = f.c[static_cast<std::size_t>(n)].sign();
  if (lead == 0) return false;
  out.p[0] = f;
  Poly<4> d;
  d.degree = n - 1;
  for (int i = 1; i <= n; ++i)
    d.c[static_cast<std::size_t>(i - 1)] = f.c[static_cast<std::size_t>(i)] * Ball(static_cast<double>(i));
  out.p[1] = d;
  auto set = [&](int slot, const Ball* g, int degree) {  // g highest power first
    Poly<4> q;
    q.degree = degree;
    for (int i = 0; i <= degree; ++i) q.c[static_cast<std::size_t>(degree - i)] = g[i];
    out.p[static_cast<std::size_t>(slot)] = q;
    out.factor[static_cast<std::size_t>(slot)] = lead;
  };
  const auto& a = f.c;
  if (n == 4) {
    Ball g2[3], g1[2], g0[1];
    detail::sturm_habicht_quartic(a[0], a[1], a[2], a[3], a[4], g2, g1, g0);
    set(2, g2, 2);
    set(3, g1, 1);
    set(4, g0, 0);
  } else if (n == 3) {
    Ball g1[2], g0[1];
    sturm_habicht_cubic(a[0], a[1], a[2], a[3], g1, g0);
    set(2, g1, 1);
    set(3, g0, 0);
  } else if (n == 2) {
    Ball g0[1];
    sturm_habicht_quadratic(a[0], a[1], a[2], g0);
    set(2, g0, 0);
  } else {
    return false;
  }
  out.count = n + 1;
  return true;
}

/// Budan–Fourier count of D^'s roots above x: the sign variations of D^(x), D^'(x), ..., exact for a
/// real-rooted polynomial; -1 when a sign is uncertain.
int roots_above(const Poly<3>& d, double x) {
  int s[4];
  Poly<3> q = d;
  for (int k = 0; k <= d.degree; ++k) {
    s[k] = q.at(x).sign();
    for (int i = 1; i <= q.degree; ++i)
      q.c[static_cast<std::size_t>(i - 1)] = q.c[static_cast<std::size_t>(i)] * Ball(static_cast<double>(i));
    --q.degree;
  }
  return variations(s, d.degree + 1);
}

/// The largest root of a real-rooted polynomial of degree 1..3 with positive leading coefficient,
/// approximately (Newton from above the Samuelson bound: monotone for a real-rooted polynomial).
double largest_root(const Poly<3>& d) {
  const int n = d.degree;
  const double lc = d.c[static_cast<std::size_t>(n)].mid();
  if (n == 1) return -d.c[0].mid() / lc;
  const double s1 = -d.c[static_cast<std::size_t>(n - 1)].mid() / lc;               // sum of the roots
  const double s2 = s1 * s1 - 2 * d.c[static_cast<std::size_t>(n - 2)].mid() / lc;  // sum of squares
  const double mean = s1 / n, var = std::max(0.0, s2 / n - mean * mean);
  double x = mean + std::sqrt(var * (n - 1)) * (1 + 0x1p-20) + std::fabs(mean) * 0x1p-40 + 0x1p-1000;
  for (int i = 0; i < 200; ++i) {
    double v = 0, dv = 0;
    for (int k = n; k >= 0; --k) {
      dv = dv * x + v;
      v = v * x + d.c[static_cast<std::size_t>(k)].mid();
    }
    if (!(dv > 0)) break;
    const double next = x - v / dv;
    if (!(next < x)) break;
    x = next;
  }
  return x;
}

/// The same for the smallest root (the largest of D^(-x), made monic-positive).
double smallest_root(const Poly<3>& d) {
  Poly<3> r = d;
  for (int i = 0; i <= d.degree; ++i) {
    const bool flip = ((d.degree - i) % 2) == 1;  // (-1)^(n-i) keeps the leading coefficient positive
    r.c[static_cast<std::size_t>(i)] = flip ? -d.c[static_cast<std::size_t>(i)] : d.c[static_cast<std::size_t>(i)];
  }
  return -largest_root(r);
}

/// An open bracket (lo, hi) around one extreme root of D^: `largest` says which, checked by the
/// Budan–Fourier counts at its ends, with no root of f^ in [lo, hi] (equal Sturm counts, every sign
/// certified). Returns the Sturm count there, -1 when it cannot certify.
int count_at_root(const SturmSequence& s, const Poly<3>& d, double r, double spread, bool largest) {
  static constexpr double kWidths[] = {0x1p-20, 0x1p-10, 0x1p-34};
  for (double w : kWidths) {
    const double delta = w * std::max(std::fabs(r), spread);
    const double lo = r - delta, hi = r + delta;
    const int above_lo = roots_above(d, lo), above_hi = roots_above(d, hi);
    if (above_lo < 0 || above_hi < 0) continue;
    const bool brackets = largest ? (above_hi == 0 && above_lo >= 1) : (above_lo == d.degree && above_hi < d.degree);
    if (!brackets) continue;
    const int v_lo = s.at(lo), v_hi = s.at(hi);
    if (v_lo < 0 || v_lo != v_hi) continue;
    return v_lo;
  }
  return -1;
}

}  // namespace

std::optional<QuadricVerdict> filtered_decision(const Ellipsoid& e, const Quadric& q) {
  RBMatrix em, qm;
  if (!load(storage_of(e), em) || !load(storage_of(q), qm)) return std::nullopt;
  const Structure st = structure_of(q.type());
  const Quartic<RB> f = pencil_quartic<RB>(em, qm);
  const Cubic<RB> dc = pencil_cubic<RB>(em, qm);
  // f^ = f / t^k and D^ = D / t^j: the structural zeros dropped (math.md §17).
  Poly<4> fh;
  fh.degree = 4 - st.k;
  for (int i = 0; i <= fh.degree; ++i)
    fh.c[static_cast<std::size_t>(i)] = ball_of(f[static_cast<std::size_t>(i + st.k)]);
  Poly<3> dh;
  dh.degree = 3 - st.j;
  for (int i = 0; i <= dh.degree; ++i)
    dh.c[static_cast<std::size_t>(i)] = ball_of(dc[static_cast<std::size_t>(i + st.j)]);
  SturmSequence s;
  if (!sturm_sequence(fh, s)) return std::nullopt;
  const int v_plus = s.at_infinity(true), v_minus = s.at_infinity(false);
  if (v_plus < 0 || v_minus < 0) return std::nullopt;
  // The extreme roots of D^ in doubles (D^ has positive leading coefficient det M).
  double r_small = 0, r_large = 0, spread = 0;
  if (dh.degree >= 1) {
    r_large = largest_root(dh);
    r_small = dh.degree == 1 ? r_large : smallest_root(dh);
    spread = std::max({std::fabs(r_large - r_small), std::fabs(r_large), std::fabs(r_small)});
    if (!std::isfinite(r_large) || !std::isfinite(r_small) || !(spread > 0)) return std::nullopt;
  }
  const int v_zero = s.at(0.0);  // f^(0) != 0 except for a cone with its apex on E (then uncertain)
  // t_hi: the smallest root of D^ when D has negative roots, else 0 (a half-space).
  const int v_hi = st.negative > 0 ? count_at_root(s, dh, r_small, spread, false) : v_zero;
  // t_lo: the largest root of D^ when D has positive roots, else 0; for an ellipsoid Q also r3.
  const bool lo_at_root = st.positive > 0;
  const int v_lo = lo_at_root ? count_at_root(s, dh, r_large, spread, true) : v_zero;
  const int v_r3 = st.ellipsoid ? count_at_root(s, dh, r_large, spread, true) : 0;
  if (v_hi < 0 || v_lo < 0 || v_r3 < 0) return std::nullopt;
  // f^ is square-free (its discriminant certified non-zero through the last member's sign), so every
  // root counted is simple: odd, and no end is a root (the brackets hold none).
  PencilFacts facts;
  facts.ellipsoid = st.ellipsoid;
  facts.min.any = facts.min.odd = v_lo - v_plus > 0;
  facts.max.any = facts.max.odd = v_minus - v_hi > 0;
  if (st.ellipsoid) facts.inner.any = facts.inner.odd = v_r3 - v_zero > 0;
  QuadricVerdict v = decide(facts);
  v.type = q.type();
  v.stage = QuadricStage::Filter;
  return v;
}

}  // namespace relpos::general
