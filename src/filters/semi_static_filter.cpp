#include "filters/semi_static_filter.hpp"

#include <gmp.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "algebra/forms.hpp"
#include "algebra/smallness.hpp"
#include "anysize/gap.hpp"
#include "filters/running_bound.hpp"

namespace relpos {
namespace {

/// RunningBound's value and magnitude in one SSE register (running_bound.hpp); the counts come from
/// counts() below, by running the very same program on RunningBound. evaluate() refuses inputs whose
/// non-zero magnitudes could underflow (see its guards), so every non-zero magnitude product stays
/// above 2^-1000, as RunningBoundLanes requires.
using Lanes = RunningBoundLanes;

template <class NT>
using View = detail::forms::MatrixOf<NT>;

constexpr int kQuantities = 13;              // f0..f4, g2[0..2], g1[0..1], g0, vertex, graeffe
constexpr double kEntryFloor = 0x1p-60;      // smallest non-zero |entry| accepted (degree 4: >= 2^-240)
constexpr double kCoeffFloor = 0x1p-160;     // smallest non-zero scaled |f_i|, |s_i| (degree 6: >= 2^-960)
constexpr double kGapCoeffFloor = 0x1p-120;  // the same for the gap test (degree 8: >= 2^-960)

template <class NT>
bool evaluate(const View<NT>& p, const View<NT>& e, NT out[kQuantities]);

/// The decision quantities in NT. Returns false (nothing certified) when a guard fails: an entry or
/// a scaled coefficient of non-zero magnitude below its floor (the no-underflow argument above).
/// The powers of two are data-dependent, but every scaling adds the same count whatever its value,
/// so the counts stay value-independent.
template <class NT>
bool evaluate(const DoubleMatrix4& pn, const DoubleMatrix4& en, NT out[kQuantities]) {
  for (const DoubleMatrix4* m : {&pn, &en})
    for (double x : *m)
      if (x != 0 && !(std::fabs(x) >= kEntryFloor)) return false;
  return evaluate(detail::forms::converted<NT>(pn), detail::forms::converted<NT>(en), out);
}

/// f and s in NT, balanced (lambda = 2^t mu, |f4| 2^(4t) ~ |f0|) and each brought near 1, by powers
/// of two: every decision quantity (and every gap quantity) is isobaric and homogeneous in f and in
/// s, so its value and its magnitude scale alike; this only keeps the products of degree up to 8
/// clear of under- and overflow. False when a non-zero scaled magnitude is below `floor`.
template <class NT>
bool scaled_pencil(const View<NT>& p, const View<NT>& e, Quartic<NT>& f, Quadratic<NT>& s, double floor) {
  f = characteristic_polynomial<NT>(p, e);
  s = special_polynomial<NT>(p, e);
  double step = 1;
  const double f0 = f[0].value(), f4 = f[4].value();
  if (f0 != 0 && f4 != 0 && std::isfinite(f0) && std::isfinite(f4))  // ilogb of 0, inf, NaN: no balancing
    step = std::ldexp(1.0, (std::ilogb(f0) - std::ilogb(f4)) / 4);
  double w = 1;
  for (std::size_t i = 0; i < 5; ++i, w *= step) {
    f[i] = f[i].times_power_of_two(w);
    if (i < 3) s[i] = s[i].times_power_of_two(w);
  }
  auto into_unit = [floor](NT* c, std::size_t n) {
    double mx = 0;
    for (std::size_t i = 0; i < n; ++i) mx = std::max(mx, c[i].magnitude());
    const double k = (mx > 0 && std::isfinite(mx)) ? std::ldexp(1.0, -std::ilogb(mx) - 1) : 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      c[i] = c[i].times_power_of_two(k);
      const double a = c[i].magnitude();
      if (a != 0 && !(a >= floor && a <= 1)) return false;
    }
    return true;
  };
  return into_unit(f.data(), 5) && into_unit(s.data(), 3);
}

template <class NT>
bool evaluate(const View<NT>& p, const View<NT>& e, NT out[kQuantities]) {
  Quartic<NT> f;
  Quadratic<NT> s;
  if (!scaled_pencil(p, e, f, s, kCoeffFloor)) return false;
  const SturmHabicht<NT> sh(f);
  const SmallnessQuantities<NT> sq(f, s);
  const NT q[kQuantities] = {f[0],     f[1],     f[2],     f[3],     f[4],      sh.g2[0],  sh.g2[1],
                             sh.g2[2], sh.g1[0], sh.g1[1], sh.g0[0], sq.vertex, sq.graeffe};
  std::copy(q, q + kQuantities, out);
  return true;
}

/// The discriminant route's quantities (static_filter_discriminant_signs_normalized): f0..f4,
/// 27 Disc(f) from the invariants, vertex, graeffe.
constexpr int kDiscriminantQuantities = 8;
template <class NT>
bool evaluate_discriminant(const View<NT>& p, const View<NT>& e, NT out[kDiscriminantQuantities]) {
  Quartic<NT> f;
  Quadratic<NT> s;
  if (!scaled_pencil(p, e, f, s, kCoeffFloor)) return false;  // 27 Disc(f) has degree 6, as g0
  const SmallnessQuantities<NT> sq(f, s);
  const NT q[kDiscriminantQuantities] = {f[0], f[1], f[2], f[3], f[4], discriminant_times_27(f), sq.vertex, sq.graeffe};
  std::copy(q, q + kDiscriminantQuantities, out);
  return true;
}

/// The gap test's quantities (anysize/gap.hpp) in NT, in GapQuantities::flatten order.
template <class NT>
bool evaluate_gap(const View<NT>& p, const View<NT>& e, NT out[detail::anysize::kGapSigns]) {
  Quartic<NT> f;
  Quadratic<NT> s;
  if (!scaled_pencil(p, e, f, s, kGapCoeffFloor)) return false;
  detail::anysize::GapQuantities<NT>(f, s).flatten(out);
  return true;
}

/// Operation counts of the gap program, from RunningBound (as counts() below).
const std::array<int, detail::anysize::kGapSigns>& gap_counts() {
  static const std::array<int, detail::anysize::kGapSigns> c = [] {
    DoubleMatrix4 one;
    one.fill(0.5);
    RunningBound q[detail::anysize::kGapSigns];
    std::array<int, detail::anysize::kGapSigns> r{};
    if (!evaluate_gap(detail::forms::converted<RunningBound>(one), detail::forms::converted<RunningBound>(one), q)) {
      r.fill(1 << 20);  // cannot happen for these inputs; if it did, certify nothing
      return r;
    }
    for (int i = 0; i < detail::anysize::kGapSigns; ++i) r[static_cast<std::size_t>(i)] = q[i].count();
    return r;
  }();
  return c;
}

/// The moved ellipsoid's entries in NT (E' = T^T E T, T = [[I, -d], [0, 1]]), scaled by a power of
/// two so the largest magnitude is near 1. False when a non-zero magnitude leaves the range the
/// no-underflow argument needs (e's entries and d in [2^-60, 2^60], scaled entries >= 2^-60).
template <class NT>
bool translate(const View<NT>& e, const std::array<double, 3>& d, View<NT>& out) {
  for (double x : d)
    if (x != 0 && !(std::fabs(x) >= kEntryFloor && std::fabs(x) <= 0x1p60)) return false;
  for (const NT& x : e.a)
    if (x.magnitude() != 0 && !(x.magnitude() >= kEntryFloor && x.magnitude() <= 0x1p60)) return false;
  const NT dv[3] = {NT(d[0]), NT(d[1]), NT(d[2])};
  View<NT> m = e;
  NT e0 = e(3, 3);
  for (int i = 0; i < 3; ++i) {
    const NT md = e(i, 0) * dv[0] + e(i, 1) * dv[1] + e(i, 2) * dv[2];
    m.a[static_cast<std::size_t>(4 * i + 3)] = m.a[static_cast<std::size_t>(12 + i)] = e(i, 3) - md;
    e0 = e0 + dv[i] * (md - NT(2) * e(i, 3));
  }
  m.a[15] = e0;
  double mx = 0;
  for (const NT& x : m.a) mx = std::max(mx, x.magnitude());
  if (!(mx > 0 && std::isfinite(mx))) return false;
  const double k = std::ldexp(1.0, -std::ilogb(mx) - 1);
  for (std::size_t i = 0; i < 16; ++i) {
    out.a[i] = m.a[i].times_power_of_two(k);
    const double a = out.a[i].magnitude();
    if (a != 0 && !(a >= kEntryFloor)) return false;
  }
  return true;
}

/// Operation counts of the program, from RunningBound on any inputs that pass the guards.
const std::array<int, kQuantities>& counts() {
  static const std::array<int, kQuantities> c = [] {
    DoubleMatrix4 one;
    one.fill(0.5);
    RunningBound q[kQuantities];
    std::array<int, kQuantities> r{};
    if (!evaluate(one, one, q)) {  // cannot happen for these inputs; if it did, certify nothing
      r.fill(1 << 20);
      return r;
    }
    for (int i = 0; i < kQuantities; ++i) r[static_cast<std::size_t>(i)] = q[i].count();
    return r;
  }();
  return c;
}

/// Counts of the translated program (translated_entries, then evaluate).
const std::array<int, kQuantities>& counts_translated() {
  static const std::array<int, kQuantities> c = [] {
    DoubleMatrix4 one;
    one.fill(0.5);
    View<RunningBound> moved;
    RunningBound q[kQuantities];
    std::array<int, kQuantities> r{};
    if (!translate(detail::forms::converted<RunningBound>(one), {0.25, 0.25, 0.25}, moved) ||
        !evaluate(detail::forms::converted<RunningBound>(one), moved, q)) {
      r.fill(1 << 20);  // cannot happen for these inputs; if it did, certify nothing
      return r;
    }
    for (int i = 0; i < kQuantities; ++i) r[static_cast<std::size_t>(i)] = q[i].count();
    return r;
  }();
  return c;
}

USign usign(int s) { return s > 0 ? USign(CGAL::POSITIVE) : s < 0 ? USign(CGAL::NEGATIVE) : USign::indeterminate(); }

USign certified(const Lanes& x, int count) {
  return usign(RunningBound::certain_sign(x.value(), x.magnitude(), count));
}

/// How far below its error bound a value must lie for its sign to be called hopeless in doubles.
/// Below 1/64 of the running bound the computed value is rounding noise of the same order as the
/// width an interval evaluation from the same double data would have (the running bound is a
/// worst case over a few hundred operations for Disc(f); the actual error is typically a few dozen
/// times smaller), so the interval stage would only add its cost. Chosen on the near-tangent
/// benchmark (doc/performance.md, "Near tangency"). A heuristic for skipping a stage, never for a
/// sign: skipping a stage is always sound.
constexpr double kHopeless = 0x1p-6;
constexpr int kDisc = 10;  // Disc(f) = g0 in evaluate()'s order

bool hopeless(double value, double magnitude, int count) {
  return std::fabs(value) < kHopeless * RunningBound::error_bound(magnitude, count);
}

DecisionSigns assemble(const USign c[kQuantities]) {
  DecisionSigns out;
  for (int i = 0; i < 5; ++i) out.quartic.f[i] = c[i];
  for (int i = 0; i < 3; ++i) out.quartic.g2[i] = c[5 + i];
  for (int i = 0; i < 2; ++i) out.quartic.g1[i] = c[8 + i];
  out.quartic.g0 = c[10];
  out.vertex = c[11];
  out.graeffe = c[12];
  return out;
}

/// Enclosures of the entries of m scaled by a power of two (largest near 1): GMP's mpq_get_d
/// truncates, |q - v| < ulp(v) <= 2^-52 |v|; the scaling is exact for entries above the floor; the
/// radius 2^-51 |v| also covers the rounding of v -+ radius. False if an entry is out of range.
bool enclosed(const Matrix4& m, View<RunningBound>& out) {
  std::array<double, 16> v;
  double mx = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    v[i] = mpq_get_d(m.a[i].mpq());
    mx = std::max(mx, std::fabs(v[i]));
  }
  if (!(mx > 0 && mx <= 0x1p1000)) return false;
  const double k = std::ldexp(1.0, -std::ilogb(mx) - 1);
  for (std::size_t i = 0; i < 16; ++i) {
    if (CGAL::is_zero(m.a[i])) {
      out.a[i] = RunningBound(0);
      continue;
    }
    // Only a normal v has |q - v| < 2^-52 |v|; a subnormal one can be off by 2^-1074, a far larger
    // relative error, enough to certify a wrong sign for entries near 2^-1000 (doc/testing.md keeps
    // the regression). Such an entry is left to the interval stage.
    if (!(std::fabs(v[i]) >= DBL_MIN)) return false;  // also catches an entry that truncated to 0
    const double x = v[i] * k;
    if (!(std::fabs(x) >= kEntryFloor)) return false;
    const double r = std::fabs(x) * 0x1p-51;
    out.a[i] = RunningBound::enclosing(x - r, x + r);
  }
  return true;
}

/// The same from certified enclosures [lo, hi]: scaled by the power of two that brings the largest
/// bound near 1 (exact while the scaled bounds stay above the entry floor, checked; up to 2^1020 the
/// factor is a normal double: the fast reader's matrices scaled by 10^300, fast_quadric.hpp).
bool enclosed(const detail::EnclosureMatrix4& m, View<RunningBound>& out) {
  double mx = 0;
  for (std::size_t i = 0; i < 16; ++i) mx = std::max({mx, std::fabs(m.lo[i]), std::fabs(m.hi[i])});
  if (!(mx > 0 && mx <= 0x1p1020)) return false;
  const double k = std::ldexp(1.0, -std::ilogb(mx) - 1);
  for (std::size_t i = 0; i < 16; ++i) {
    const double lo = m.lo[i] * k, hi = m.hi[i] * k;
    if (m.lo[i] == 0 && m.hi[i] == 0) {
      out.a[i] = RunningBound(0);
      continue;
    }
    const double small = std::min(std::fabs(lo), std::fabs(hi));
    if (!(small >= kEntryFloor) || (lo < 0) != (hi < 0)) return false;  // no exact scaling, or a sign change
    out.a[i] = RunningBound::enclosing(lo, hi);
  }
  return true;
}

}  // namespace

DecisionSigns semi_static_filter_signs_normalized(const DoubleMatrix4& pn, const DoubleMatrix4& en) {
  const std::array<int, kQuantities>& d = counts();
  Lanes q[kQuantities];
  if (!evaluate(pn, en, q)) return DecisionSigns{};  // uncertain
  USign c[kQuantities];
  for (int i = 0; i < kQuantities; ++i) c[i] = certified(q[i], d[static_cast<std::size_t>(i)]);
  DecisionSigns out = assemble(c);
  out.disc_hopeless = hopeless(q[kDisc].value(), q[kDisc].magnitude(), d[kDisc]);
  return out;
}

std::optional<bool> semi_static_roots_above_lambda_s(const DoubleMatrix4& pn, const DoubleMatrix4& en) {
  for (const DoubleMatrix4* m : {&pn, &en})
    for (double x : *m)
      if (x != 0 && !(std::fabs(x) >= kEntryFloor)) return std::nullopt;
  const std::array<int, detail::anysize::kGapSigns>& counts = gap_counts();
  Lanes q[detail::anysize::kGapSigns];
  if (!evaluate_gap(detail::forms::converted<Lanes>(pn), detail::forms::converted<Lanes>(en), q)) return std::nullopt;
  std::optional<int> signs[detail::anysize::kGapSigns];
  for (int i = 0; i < detail::anysize::kGapSigns; ++i)
    if (const int c = RunningBound::certain_sign(q[i].value(), q[i].magnitude(), counts[static_cast<std::size_t>(i)]))
      signs[i] = c;
  return detail::anysize::roots_above_lambda_s(signs);
}

DecisionSigns semi_static_filter_signs_translated(const DoubleMatrix4& pn, const DoubleMatrix4& en,
                                                  const std::array<double, 3>& d) {
  const std::array<int, kQuantities>& counts = counts_translated();
  for (double x : pn)
    if (x != 0 && !(std::fabs(x) >= kEntryFloor)) return DecisionSigns{};
  View<Lanes> moved;
  Lanes q[kQuantities];
  if (!translate(detail::forms::converted<Lanes>(en), d, moved) ||
      !evaluate(detail::forms::converted<Lanes>(pn), moved, q))
    return DecisionSigns{};
  USign c[kQuantities];
  for (int i = 0; i < kQuantities; ++i) c[i] = certified(q[i], counts[static_cast<std::size_t>(i)]);
  return assemble(c);
}

DecisionSigns semi_static_filter_signs_translated(const Matrix4& p, const Matrix4& e, const std::array<double, 3>& d) {
  View<RunningBound> vp, ve, moved;
  RunningBound q[kQuantities];
  if (!enclosed(p, vp) || !enclosed(e, ve) || !translate(ve, d, moved) || !evaluate(vp, moved, q))
    return DecisionSigns{};
  USign c[kQuantities];
  for (int i = 0; i < kQuantities; ++i) c[i] = usign(q[i].sign());
  return assemble(c);
}

namespace {

/// The signs from entries that enter as enclosures (rationals, or stored double enclosures).
template <class M>
DecisionSigns enclosed_signs(const M& p, const M& e) {
  View<RunningBound> vp, ve;
  RunningBound q[kQuantities];
  if (!enclosed(p, vp) || !enclosed(e, ve) || !evaluate(vp, ve, q)) return DecisionSigns{};
  USign c[kQuantities];
  for (int i = 0; i < kQuantities; ++i) c[i] = usign(q[i].sign());
  DecisionSigns out = assemble(c);
  out.disc_hopeless = hopeless(q[kDisc].value(), q[kDisc].magnitude(), q[kDisc].count());
  return out;
}

}  // namespace

DecisionSigns semi_static_filter_signs(const Matrix4& p, const Matrix4& e) { return enclosed_signs(p, e); }

DecisionSigns semi_static_filter_discriminant_signs(const detail::EnclosureMatrix4& p,
                                                    const detail::EnclosureMatrix4& e) {
  View<RunningBound> vp, ve;
  RunningBound q[kDiscriminantQuantities];
  DecisionSigns out;
  if (!enclosed(p, vp) || !enclosed(e, ve) || !evaluate_discriminant(vp, ve, q)) return out;
  for (int i = 0; i < 5; ++i) out.quartic.f[i] = usign(q[i].sign());
  out.quartic.g0 = usign(q[5].sign());  // the sign of 27 Disc(f)
  out.vertex = usign(q[6].sign());
  out.graeffe = usign(q[7].sign());
  return out;
}

DecisionSigns semi_static_filter_signs(const detail::EnclosureMatrix4& p, const detail::EnclosureMatrix4& e) {
  return enclosed_signs(p, e);
}

}  // namespace relpos
