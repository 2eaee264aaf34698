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
#include "filters/spread.hpp"
#include "general/decision.hpp"
#include "general/pencil.hpp"
#include "general/sturm_habicht_low.hpp"

namespace relpos::detail::general {

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
/// positive scaling changes no sign): the normalized doubles, or enclosures of the rationals read
/// from the leading bits of their numerators and denominators (mpz_get_d_2exp truncates towards
/// zero, so |n| lies in [m, m + 2^-53) 2^e), whatever their length: a matrix scaled by 10^300 costs
/// what the unscaled one costs (math.md §17). False when an entry would leave the normal range.
bool load(const detail::QuadricMatrix& s, RBMatrix& out) {
  if (const DoubleMatrix4* d = s.filter_doubles()) {
    for (std::size_t i = 0; i < 16; ++i) out.a[i] = RB((*d)[i]);
    return true;
  }
  const Matrix4& m = s.matrix();
  double lo[16], hi[16];
  long exponent[16], top = LONG_MIN;
  for (std::size_t i = 0; i < 16; ++i) {
    const mpq_srcptr q = m.a[i].mpq();
    if (mpq_sgn(q) == 0) continue;
    long en, ed;
    const double mn = std::fabs(mpz_get_d_2exp(&en, mpq_numref(q))), md = mpz_get_d_2exp(&ed, mpq_denref(q));
    // |q| 2^-(en - ed) lies in (mn / (md + 2^-53), (mn + 2^-53) / md); each quotient rounded, then widened.
    lo[i] = mn / (md + 0x1p-53) * (1 - 0x1p-50);
    hi[i] = (mn + 0x1p-53) / md * (1 + 0x1p-50);
    exponent[i] = en - ed;
    top = std::max(top, exponent[i]);
  }
  if (top == LONG_MIN) return false;
  for (std::size_t i = 0; i < 16; ++i) {
    const int sign = mpq_sgn(m.a[i].mpq());
    if (sign == 0) {
      out.a[i] = RB(0.0);
      continue;
    }
    const long shift = exponent[i] - top;  // <= 0: values in (2^-2, 2] times 2^shift
    if (shift < -900) return false;
    const double l = std::ldexp(lo[i], static_cast<int>(shift)), h = std::ldexp(hi[i], static_cast<int>(shift));
    out.a[i] = sign > 0 ? RB::enclosing(l, h) : RB::enclosing(-h, -l);
  }
  return true;
}

// ---- the sign rule on certified coefficients, generic over the number type ----------------------
//
// NT is Spread (a program's bound from its magnitudes, three lanes of one vector: fast) or Ball
// (midpoint-radius, op by op: slower, but without Spread's range guard); both certify every sign
// they return. The coefficients of f^ and D^ enter as inputs known to within their errors, the
// Sturm–Habicht coefficients computed from them are restarted as inputs of the evaluations at
// points (math.md §17).

Spread input_of(double mid, double radius, const Spread*) { return Spread::input(mid, radius); }
Ball input_of(double mid, double radius, const Ball*) { return Ball(mid, radius); }
template <class NT>
NT input(double mid, double radius) {
  return input_of(mid, radius, static_cast<const NT*>(nullptr));
}
Spread restarted(const Spread& x) { return x.restarted(); }
Ball restarted(const Ball& x) { return x; }
bool usable(double mid, double radius, const Spread*) { return Spread::in_range(mid, radius); }
bool usable(double mid, double radius, const Ball*) { return std::isfinite(mid) && std::isfinite(radius); }
template <class NT>
bool usable(double mid, double radius) {
  return usable(mid, radius, static_cast<const NT*>(nullptr));
}

/// A polynomial with certified coefficients, low degree first.
template <class NT, int N>
struct Poly {
  std::array<NT, N + 1> c;
  int degree = N;
  NT at(double x) const {
    if (x == 0) return c[0];
    NT v = c[static_cast<std::size_t>(degree)];
    for (int i = degree - 1; i >= 0; --i) v = v.times(x) + c[static_cast<std::size_t>(i)];
    return v;
  }
};

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
template <class NT>
struct SturmSequence {
  std::array<Poly<NT, 4>, 5> p;  // p[0] = f^, p[1] = f^', then g_{n-2}, ..., g_0
  std::array<int, 5> factor{1, 1, 1, 1, 1};
  int count = 0;
  /// The sign variations at x (certified), or -1.
  int at(double x) const {
    if (!usable<NT>(x, 0)) return -1;
    int s[5];
    for (int i = 0; i < count; ++i)
      s[i] = factor[static_cast<std::size_t>(i)] * p[static_cast<std::size_t>(i)].at(x).sign();
    return variations(s, count);
  }
  /// At +oo (plus) or -oo: the leading coefficients' signs.
  int at_infinity(bool plus) const {
    int s[5];
    for (int i = 0; i < count; ++i) {
      const Poly<NT, 4>& q = p[static_cast<std::size_t>(i)];
      const int lead = q.c[static_cast<std::size_t>(q.degree)].sign();
      s[i] = factor[static_cast<std::size_t>(i)] * ((plus || q.degree % 2 == 0) ? lead : -lead);
    }
    return variations(s, count);
  }
};

template <class NT>
bool sturm_sequence(const Poly<NT, 4>& f, SturmSequence<NT>& out) {
  const int n = f.degree;
  const int lead = f.c[static_cast<std::size_t>(n)].sign();
  if (lead == 0) return false;
  out.p[0] = f;
  Poly<NT, 4> d;
  d.degree = n - 1;
  for (int i = 1; i <= n; ++i)
    d.c[static_cast<std::size_t>(i - 1)] = f.c[static_cast<std::size_t>(i)].times(static_cast<double>(i));
  out.p[1] = d;
  auto set = [&](int slot, const NT* g, int degree) {  // g highest power first
    Poly<NT, 4> q;
    q.degree = degree;
    for (int i = 0; i <= degree; ++i) q.c[static_cast<std::size_t>(degree - i)] = restarted(g[i]);
    out.p[static_cast<std::size_t>(slot)] = q;
    out.factor[static_cast<std::size_t>(slot)] = lead;
  };
  const auto& a = f.c;
  if (n == 4) {
    NT g2[3], g1[2];
    detail::sturm_habicht_quartic_g2_g1(a[0], a[1], a[2], a[3], a[4], g2, g1);
    // g0 = Disc(f^) through the invariants, 27 Disc = 4 I^3 - J^2 (math.md §11): a positive
    // multiple, a dozen products where the expanded discriminant takes eighty.
    const NT i = NT(12.0) * a[0] * a[4] - NT(3.0) * a[1] * a[3] + a[2] * a[2];
    const NT j = NT(72.0) * a[0] * a[2] * a[4] + NT(9.0) * a[1] * a[2] * a[3] - NT(27.0) * a[0] * a[3] * a[3] -
                 NT(27.0) * a[4] * a[1] * a[1] - NT(2.0) * a[2] * a[2] * a[2];
    const NT g0[1] = {NT(4.0) * i * i * i - j * j};
    set(2, g2, 2);
    set(3, g1, 1);
    set(4, g0, 0);
  } else if (n == 3) {
    NT g1[2], g0[1];
    sturm_habicht_cubic(a[0], a[1], a[2], a[3], g1, g0);
    set(2, g1, 1);
    set(3, g0, 0);
  } else if (n == 2) {
    NT g0[1];
    sturm_habicht_quadratic(a[0], a[1], a[2], g0);
    set(2, g0, 0);
  } else {
    return false;
  }
  out.count = n + 1;
  return true;
}

/// D^ and its derivatives, for Budan–Fourier counts.
template <class NT>
struct Fourier {
  std::array<Poly<NT, 3>, 4> p;  // D^ and its derivatives
  int degree = 0;
  explicit Fourier(const Poly<NT, 3>& d) : degree(d.degree) {
    p[0] = d;
    for (int k = 1; k <= degree; ++k) {
      const Poly<NT, 3>& q = p[static_cast<std::size_t>(k - 1)];
      Poly<NT, 3>& r = p[static_cast<std::size_t>(k)];
      r.degree = q.degree - 1;
      for (int i = 1; i <= q.degree; ++i)
        r.c[static_cast<std::size_t>(i - 1)] = q.c[static_cast<std::size_t>(i)].times(static_cast<double>(i));
    }
  }
  /// Budan–Fourier count of D^'s roots above x: the sign variations of D^(x), D^'(x), ..., exact for a
  /// real-rooted polynomial; -1 when a sign is uncertain.
  int roots_above(double x) const {
    if (!usable<NT>(x, 0)) return -1;
    int s[4];
    for (int k = 0; k <= degree; ++k) s[k] = p[static_cast<std::size_t>(k)].at(x).sign();
    return variations(s, degree + 1);
  }
};

/// The largest root of a real-rooted polynomial of degree 1..3 with positive leading coefficient,
/// approximately (Newton from above the Samuelson bound mean + sigma sqrt(n - 1): monotone for a
/// real-rooted polynomial), from the coefficients' midpoints.
double largest_root(const double* c, int n) {
  const double lc = c[n];
  if (n == 1) return -c[0] / lc;
  const double s1 = -c[n - 1] / lc;               // sum of the roots
  const double s2 = s1 * s1 - 2 * c[n - 2] / lc;  // sum of squares
  const double mean = s1 / n, var = std::max(0.0, s2 / n - mean * mean);
  double x = mean + std::sqrt(var * (n - 1)) * (1 + 0x1p-20) + std::fabs(mean) * 0x1p-40 + 0x1p-1000;
  for (int i = 0; i < 200; ++i) {
    double v = 0, dv = 0;
    for (int k = n; k >= 0; --k) {
      dv = dv * x + v;
      v = v * x + c[k];
    }
    if (!(dv > 0)) break;
    const double step = v / dv;
    if (!(step > 0)) break;  // converged (monotone from above)
    x -= step;
    if (step <= std::fabs(x) * 0x1p-40) break;  // far below the brackets' widths
  }
  return x;
}

/// The same for the smallest root: the largest root of (-1)^n D^(-x).
double smallest_root(const double* c, int n) {
  double r[4];
  for (int i = 0; i <= n; ++i) r[i] = ((n - i) % 2 == 1) ? -c[i] : c[i];
  return -largest_root(r, n);
}

/// The Sturm count of f^ at an extreme root r of D^ (`largest` says which): an open bracket
/// (lo, hi) around r, checked by the Budan–Fourier counts at its ends, with no root of f^ in [lo, hi]
/// (equal Sturm counts, every sign certified). -1 when it cannot certify.
template <class NT>
int count_at_root(const SturmSequence<NT>& s, const Fourier<NT>& d, double r, double spread, bool largest) {
  static constexpr double kWidths[] = {0x1p-20, 0x1p-10, 0x1p-34};
  for (double w : kWidths) {
    const double delta = w * std::max(std::fabs(r), spread);
    const double lo = r - delta, hi = r + delta;
    // The largest root is in (lo, hi) when no root lies above hi (Budan–Fourier at hi) and D^ changes
    // sign on [lo, hi] (one value at lo), or, at a multiple root, when some root lies above lo
    // (Budan–Fourier at lo); the smallest root likewise, mirrored.
    const double outer = largest ? hi : lo, inner = largest ? lo : hi;
    const int beyond = d.roots_above(outer);
    const bool none_beyond = largest ? beyond == 0 : beyond == d.degree;
    if (beyond < 0 || !none_beyond) continue;
    const int outer_sign = d.p[0].at(outer).sign(), inner_sign = d.p[0].at(inner).sign();
    if (outer_sign == 0 || inner_sign != -outer_sign) {
      const int within = d.roots_above(inner);
      if (within < 0 || (largest ? within < 1 : within >= d.degree)) continue;
    }
    const int v_lo = s.at(lo), v_hi = s.at(hi);
    if (v_lo < 0 || v_lo != v_hi) continue;
    return v_lo;
  }
  return -1;
}

/// f^ = f / t^k and D^ = D / t^j as certified polynomials (math.md §17), their coefficients known
/// to within the given errors (`mid`: D^'s midpoints); false when a coefficient is not usable. The
/// facts of math.md §16 follow from them (facts_of), the sides settled in the order of the
/// decision, each only when the previous one has no root.
template <class NT>
bool reduced_polynomials(const Structure& st, const double* f, const double* fe, const double* d, const double* de,
                         Poly<NT, 4>& fh, Poly<NT, 3>& dh, double* mid) {
  fh.degree = 4 - st.k;
  for (int i = 0; i <= fh.degree; ++i) {
    if (!usable<NT>(f[i + st.k], fe[i + st.k])) return false;
    fh.c[static_cast<std::size_t>(i)] = input<NT>(f[i + st.k], fe[i + st.k]);
  }
  dh.degree = 3 - st.j;
  for (int i = 0; i <= dh.degree; ++i) {
    if (!usable<NT>(d[i + st.j], de[i + st.j])) return false;
    dh.c[static_cast<std::size_t>(i)] = input<NT>(d[i + st.j], de[i + st.j]);
    mid[i] = d[i + st.j];
  }
  return true;
}

/// The facts from f^ and D^ (above), or nullopt when a sign is uncertain.
template <class NT>
std::optional<PencilFacts> facts_of(const Structure& st, const double* f, const double* fe, const double* d,
                                    const double* de) {
  Poly<NT, 4> fh;
  Poly<NT, 3> dh;
  double mid[4];
  if (!reduced_polynomials(st, f, fe, d, de, fh, dh, mid)) return std::nullopt;
  SturmSequence<NT> s;
  if (!sturm_sequence(fh, s)) return std::nullopt;
  const int v_plus = s.at_infinity(true), v_minus = s.at_infinity(false);
  if (v_plus < 0 || v_minus < 0) return std::nullopt;
  // f^ is square-free (its discriminant certified non-zero through the last member's sign), so every
  // root counted is simple: odd, and no end is a root (the brackets hold none).
  PencilFacts facts;
  facts.ellipsoid = st.ellipsoid;
  const int v_zero = s.at(0.0);  // f^(0) != 0 except for a cone with its apex on E (then uncertain)
  // t_lo: 0 unless D has positive roots (then the largest root of D^).
  if (st.positive == 0) {
    if (v_zero < 0) return std::nullopt;
    if (v_zero - v_plus > 0) {
      facts.min.any = facts.min.odd = true;
      return facts;
    }
  }
  // The extreme roots of D^ in doubles (D^ has positive leading coefficient det M).
  double r_small = 0, r_large = 0, spread = 0;
  if (dh.degree >= 1) {
    r_large = largest_root(mid, dh.degree);
    r_small = dh.degree == 1 ? r_large : smallest_root(mid, dh.degree);
    spread = std::max({std::fabs(r_large - r_small), std::fabs(r_large), std::fabs(r_small)});
    if (!std::isfinite(r_large) || !std::isfinite(r_small) || !(spread > 0)) return std::nullopt;
  }
  const Fourier<NT> fourier(dh);
  if (st.positive > 0) {
    const int v_lo = count_at_root(s, fourier, r_large, spread, true);
    if (v_lo < 0) return std::nullopt;
    if (v_lo - v_plus > 0) {
      facts.min.any = facts.min.odd = true;
      return facts;
    }
  }
  // t_hi: the smallest root of D^ when D has negative roots, else 0 (a half-space).
  const int v_hi = st.negative > 0 ? count_at_root(s, fourier, r_small, spread, false) : v_zero;
  if (v_hi < 0) return std::nullopt;
  if (v_minus - v_hi > 0) {
    facts.max.any = facts.max.odd = true;
    return facts;
  }
  // For an ellipsoid Q, (r3, 0) with r3 the largest root of D^.
  if (st.ellipsoid) {
    const int v_r3 = count_at_root(s, fourier, r_large, spread, true);
    if (v_r3 < 0 || v_zero < 0) return std::nullopt;
    facts.inner.any = facts.inner.odd = v_r3 - v_zero > 0;
  }
  return facts;
}

/// Spread first, then Ball on the same coefficients.
std::optional<PencilFacts> facts_of(const Structure& st, const double* f, const double* fe, const double* d,
                                    const double* de) {
  if (auto facts = facts_of<Spread>(st, f, fe, d, de)) return facts;
  return facts_of<Ball>(st, f, fe, d, de);
}

struct DoubleView {
  const DoubleMatrix4& a;
  double operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// Static error bounds of f's and D's coefficients computed in doubles from matrices whose entries
/// lie in [-1, 1]: the running bound of the same program on matrices of ones (its magnitudes bound
/// those of any such entries, and its operation counts do not depend on the values), plus 2^-1050
/// for the underflows of the few hundred products.
struct StaticBounds {
  Quartic<double> f;
  Cubic<double> d;
  StaticBounds() {
    RBMatrix ones;
    for (RB& x : ones.a) x = RB(1.0);
    const Quartic<RB> fr = pencil_quartic<RB>(ones, ones);
    const Cubic<RB> dr = pencil_cubic<RB>(ones, ones);
    for (std::size_t i = 0; i < 5; ++i) f[i] = fr[i].error_bound() + 0x1p-1050;
    for (std::size_t i = 0; i < 4; ++i) d[i] = dr[i].error_bound() + 0x1p-1050;
  }
};

}  // namespace

std::optional<QuadricVerdict> filtered_decision(const Ellipsoid& e, const Quadric& q) {
  const Structure st = structure_of(q.type());
  std::optional<PencilFacts> facts;
  const DoubleMatrix4 *ed = storage_of(e).filter_doubles(), *qd = storage_of(q).filter_doubles();
  if (ed && qd) {
    // Static stage: both matrices' normalized doubles (entries in [-1, 1]), f and D in plain doubles
    // (f in vector lanes, bit for bit the generic program) with the bounds derived once.
    static const StaticBounds bounds;
    const Quartic<double> f = characteristic_polynomial_lanes(*ed, *qd);
    const Cubic<double> d = pencil_cubic<double>(DoubleView{*ed}, DoubleView{*qd});
    facts = facts_of(st, f.data(), bounds.f.data(), d.data(), bounds.d.data());
  }
  if (!facts) {
    // Running bounds from the actual magnitudes (and rational entries as enclosures).
    RBMatrix em, qm;
    if (!load(storage_of(e), em) || !load(storage_of(q), qm)) return std::nullopt;
    const Quartic<RB> f = pencil_quartic<RB>(em, qm);
    const Cubic<RB> d = pencil_cubic<RB>(em, qm);
    double fv[5], fe[5], dv[4], de[4];
    for (std::size_t i = 0; i < 5; ++i) fv[i] = f[i].value(), fe[i] = f[i].error_bound();
    for (std::size_t i = 0; i < 4; ++i) dv[i] = d[i].value(), de[i] = d[i].error_bound();
    facts = facts_of(st, fv, fe, dv, de);
  }
  if (!facts) return std::nullopt;
  QuadricVerdict v = decide(*facts);
  v.type = q.type();
  v.stage = QuadricStage::Filter;
  return v;
}

}  // namespace relpos::detail::general
