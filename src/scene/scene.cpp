#include "relpos/scene.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>

#include "algebra/filtered.hpp"
#include "algebra/pencil.hpp"
#include "algebra/smallness.hpp"
#include "base/worker_pool.hpp"
#include "decide/many_pairs.hpp"
#include "filters/running_bound.hpp"
#include "scene/certificates.hpp"
#include "scene/chunk_loop.hpp"
#include "scene/scene_pool.hpp"

namespace relpos {
namespace {

/// The scene view of a core verdict.
SceneVerdict scene_verdict(const Verdict& v) {
  SceneVerdict out;
  out.position = v.position;
  out.rule = v.rule;
  out.stage = v.stage;
  return out;
}

using Interval = CGAL::Interval_nt<false>;  // paraboloid constants only (needs Protect_FPU_rounding)
using RB = RunningBound;                    // the per-body filter (running_bound.hpp)

/// RunningBound without its count: value and magnitude only, as one SSE register (a product is one
/// mulpd, a sum one addpd). The count of each quantity the certificates test depends on the program
/// and on the counts of the inputs, never on their values, so PreparedParaboloid computes it once, by running the
/// same code on RunningBound with exact inputs (count 0), and the hot path for bodies given by
/// doubles carries (v, a) alone. Unlike RunningBound there is no magnitude floor: the fast path is
/// taken only when every non-zero input magnitude lies in [2^-45, 2^40] (kFastLow, kFastHigh), so a
/// product of at most 20 of them (the certificates' largest degree) stays within [2^-900, 2^800]:
/// no magnitude underflows or overflows, and a value's underflow error (below 2^-1075 < u 2^-1000)
/// is absorbed by the count as in RunningBound.
constexpr double kFastLow = 0x1p-45, kFastHigh = 0x1p40;
using Fast = RunningBoundLanes;

/// Is every non-zero magnitude in the fast path's range?
inline bool fast_range(double a) { return a == 0 || (a >= kFastLow && a <= kFastHigh); }

/// The quantities a certificate tests, in the order of Counts::of.
enum Tested { kPn, kOutsideGap, kInsideT, kInsideGap, kRho1, kRho2, kTested };

/// Matrix view for the generic pencil code.
struct RationalView {
  const Matrix4* m;
  const Rational& operator()(int i, int j) const { return (*m)(i, j); }
};

RB bounded(const Rational& q) {
  const auto i = CGAL::to_interval(q);
  return RB::enclosing(i.first, i.second);
}

SymmetricEntries<RB> bounded(const SymmetricEntries<Rational>& s) {
  return {bounded(s.q00), bounded(s.q11), bounded(s.q22), bounded(s.q01), bounded(s.q02),
          bounded(s.q12), bounded(s.q0),  bounded(s.q1),  bounded(s.q2),  bounded(s.q33)};
}

/// Power of two 2^k with the largest |entry| of m times 2^k in [1/2, 1): a positive scaling of P
/// changes no sign the certificates or the core look at (math.md §1).
long balancing_exponent(const Matrix4& m) {
  double mx = 0;
  for (const auto& q : m.a) mx = std::max(mx, std::fabs(CGAL::to_double(q)));
  if (mx == 0 || !std::isfinite(mx)) return 0;
  int e;
  std::frexp(mx, &e);
  return -static_cast<long>(e);
}

Rational times_power_of_two(const Rational& q, long k) {
  Rational out;  // fresh object: Gmpq is reference-counted (never write into a shared one)
  if (k >= 0)
    mpq_mul_2exp(out.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(k));
  else
    mpq_div_2exp(out.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(-k));
  return out;
}

constexpr SceneVerdict kOutside{Position::E, Rule::TwoPositiveRoots, Stage::OutsideCertificate};
constexpr SceneVerdict kInsideSmall{Position::I, Rule::AllRootsNegative, Stage::InsideCertificate};

/// What an early-out proved, in one byte (an optional<SceneVerdict> return cost a store-forwarding
/// stall per body).
enum class Early : unsigned char { None, Outside, InsideSmall };

std::optional<SceneVerdict> verdict_of(Early x) {
  switch (x) {
    case Early::Outside:
      return kOutside;
    case Early::InsideSmall:
      return kInsideSmall;
    case Early::None:
      break;
  }
  return std::nullopt;
}

}  // namespace

/// The paraboloid, scaled by a power of two, as RunningBound enclosures of exact values.
struct Scene::PreparedParaboloid {
  SymmetricEntries<RB> p;      ///< A, p, p0 (exact when the scaled entries are doubles)
  SymmetricEntries<RB> adj_a;  ///< adj(A) (only its 3x3 part is used)
  RB det_p;                    ///< det P (< 0)
  RB lambda_max;               ///< lambda_max(A) = (tr A + sqrt(tr^2 A - 4 sigma2)) / 2, sigma2 = tr adj(A)
  RB rho_factor;               ///< sigma2 lambda_max^2 / |det P|: the rho of a sphere is r^2 times this
  // The same as (value, magnitude), and the counts of the tested quantities for exact inputs.
  SymmetricEntries<Fast> fp, fadj_a;
  Fast fdet_p, flambda_max, frho_factor;
  std::array<int, kTested> sphere_counts{}, general_counts{};
  bool diagonal_a = false;  ///< A diagonal: the certificates skip its zero entries
  bool fast_ok = false;     ///< every non-zero fast constant within [kFastLow, kFastHigh]
  void compute_counts();

  explicit PreparedParaboloid(const Paraboloid& par) {
    const long k = balancing_exponent(par.matrix());
    Matrix4 m;
    for (std::size_t i = 0; i < 16; ++i) m.a[i] = times_power_of_two(par.matrix().a[i], k);
    const RationalView v{&m};
    const SymmetricEntries<Rational> pe = entries<Rational>(v);
    const SymmetricEntries<Rational> adj = adjugate3(pe);
    // det(l P + P) = (l + 1)^4 det P: the pencil code gives det P as the leading coefficient.
    const Rational det = characteristic_polynomial<Rational>(v, v)[4];
    const Rational tr = pe.q00 + pe.q11 + pe.q22, s2 = adj.q00 + adj.q11 + adj.q22;
    p = bounded(pe);
    diagonal_a = CGAL::is_zero(pe.q01) && CGAL::is_zero(pe.q02) && CGAL::is_zero(pe.q12);
    adj_a = bounded(adj);
    det_p = bounded(det);
    // The two irrational constants, enclosed by intervals once per paraboloid. A >= 0 has the
    // eigenvalues 0, l1, l2, the roots of x^2 - tr x + sigma2; CGAL's interval sqrt clamps a
    // negative lower end of the radicand to 0 (the exact radicand is >= 0).
    std::pair<double, double> lmax, rho;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval ti(CGAL::to_interval(tr)), si(CGAL::to_interval(s2)), di(CGAL::to_interval(det));
      const Interval l = (ti + CGAL::sqrt(ti * ti - Interval(4) * si)) / Interval(2);
      lmax = l.pair();
      rho = (si * (l * l) / -di).pair();
    }
    lambda_max = RB::enclosing(lmax.first, lmax.second);
    rho_factor = RB::enclosing(rho.first, rho.second);
    auto fast = [](const SymmetricEntries<RB>& e) {
      return SymmetricEntries<Fast>{Fast::of(e.q00), Fast::of(e.q11), Fast::of(e.q22), Fast::of(e.q01),
                                    Fast::of(e.q02), Fast::of(e.q12), Fast::of(e.q0),  Fast::of(e.q1),
                                    Fast::of(e.q2),  Fast::of(e.q33)};
    };
    fp = fast(p);
    fadj_a = fast(adj_a);
    fdet_p = Fast::of(det_p);
    flambda_max = Fast::of(lambda_max);
    frho_factor = Fast::of(rho_factor);
    fast_ok = true;
    for (const auto* e : {&fp, &fadj_a})
      for (const Fast* c : {&e->q00, &e->q11, &e->q22, &e->q01, &e->q02, &e->q12, &e->q0, &e->q1, &e->q2, &e->q33})
        fast_ok = fast_ok && fast_range(c->magnitude());
    for (const Fast* c : {&fdet_p, &flambda_max, &frho_factor}) fast_ok = fast_ok && fast_range(c->magnitude());
    compute_counts();
  }
};

namespace {

Early inside_verdict(int rho_sign) {
  // Interior: the core's table gives I with the rule AllRootsNegative when rho < 1. A body that is
  // not small is interior too (p < 0 on it), but the core names its rule from math.md §8's root
  // location (RootsAboveLambdaS or OddGapRoot): the core decides, so a scene and batch agree.
  if (rho_sign < 0) return Early::InsideSmall;
  return Early::None;  // not small, rho = 1 or too close to tell: the core decides
}

USign usign(int s) { return s == 0 ? USign::indeterminate() : USign(s > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE); }

/// The certificates for a sphere (M = m I), written once for every filter type: sign(x, i) is the
/// certified sign of the Tested quantity i (0 when uncertain).
template <class NT, class Sign>
Early certify_sphere(const SymmetricEntries<NT>& x, const SymmetricEntries<NT>& p, bool diagonal_a,
                     const NT& lambda_max, const NT& rho_factor, Sign sign) {
  const SphereQuantities<NT> q =
      diagonal_a ? SphereQuantities<NT>(x, p, typename SphereQuantities<NT>::DiagonalA{}) : SphereQuantities<NT>(x, p);
  if (sign(q.Pnp, kPn) > 0 && sign(q.outside_gap(), kOutsideGap) > 0) return Early::Outside;
  if (!(sign(q.inside_t(lambda_max), kInsideT) < 0 && sign(q.inside_gap(lambda_max), kInsideGap) > 0))
    return Early::None;
  // rho = (K/D) S2 mu_max^2 / |det P| (smallness.hpp's number) is (K'/m^2) rho_factor for M = m I,
  // so rho - 1 has the sign of K' rho_factor - m^2.
  return inside_verdict(sign(q.Kp * rho_factor - q.m * q.m, kRho1));
}

/// The certificates for a general ellipsoid.
template <class NT, class Sign>
Early certify_general(const SymmetricEntries<NT>& x, const SymmetricEntries<NT>& p, bool diagonal_a,
                      const SymmetricEntries<NT>& adj_a, const NT& det_p, Sign sign) {
  using Q = ContainmentQuantities<NT>;
  const Q q = diagonal_a ? Q(x, p, adj_a, typename Q::DiagonalA{}) : Q(x, p, adj_a);
  if (sign(q.Pn, kPn) > 0 && sign(q.outside_gap(), kOutsideGap) > 0) return Early::Outside;
  if (!(sign(q.inside_t(), kInsideT) < 0 && sign(q.inside_gap(), kInsideGap) > 0)) return Early::None;
  // rho against 1 with the core's two smallness polynomials (smallness.hpp), f0 = det E = -K,
  // f4 = det P, s = (D, S1, S2).
  const SmallnessQuantities<NT> sm(Quartic<NT>{-q.K, NT(0), NT(0), NT(0), det_p}, Quadratic<NT>{q.D, q.S1, q.S2});
  const auto rho = compare_rho_with_one(usign(sign(sm.vertex, kRho1)), usign(sign(sm.graeffe, kRho2)));
  return inside_verdict(rho ? *rho : 0);
}

/// A probe that visits every tested quantity (the sign pattern it returns steers past each
/// short-circuit) and records its count.
struct CountProbe {
  std::array<int, kTested>* counts;
  int operator()(const RB& x, int i) const {
    (*counts)[static_cast<std::size_t>(i)] = x.count();
    return i == kPn || i == kInsideGap ? 1 : (i == kOutsideGap || i == kInsideT ? -1 : 0);
  }
};

}  // namespace

void Scene::PreparedParaboloid::compute_counts() {
  const RB one(1);  // any exact input: the counts do not depend on the values
  const SymmetricEntries<RB> x{one, one, one, one, one, one, one, one, one, one};
  certify_sphere(x, p, diagonal_a, lambda_max, rho_factor, CountProbe{&sphere_counts});
  certify_general(x, p, diagonal_a, adj_a, det_p, CountProbe{&general_counts});
}

namespace {

int tracked_sign(const RB& x, int) { return x.sign(); }

/// Entries of E far from 1 are scaled by a power of two first (exact, and a positive scaling changes
/// no certificate sign): this keeps products of degree <= 13 away from overflow.
double scale_for(double mx) {
  if (!(mx > 0x1p40 || mx < 0x1p-40) || mx == 0) return 1;
  int k;
  std::frexp(mx, &k);
  return std::ldexp(1.0, -k);
}

/// The entries of a body read from text, from its stored enclosures, scaled by a power of two;
/// false when they are beyond 2^1000 or a scaled bound underflows (then no early-out).
bool enclosure_entries(const detail::EnclosureMatrix4& enc, SymmetricEntries<RB>& x, bool& sphere) {
  const auto point = [&](std::size_t i) { return enc.lo[i] == enc.hi[i]; };
  sphere = point(0) && point(1) && point(2) && point(5) && point(6) && point(10) && enc.lo[1] == 0 && enc.lo[2] == 0 &&
           enc.lo[6] == 0 && enc.lo[0] == enc.lo[5] && enc.lo[0] == enc.lo[10];
  double mx = 0;
  for (std::size_t i : {0, 1, 2, 3, 5, 6, 7, 10, 11, 15})
    mx = std::max({mx, std::fabs(enc.lo[i]), std::fabs(enc.hi[i])});
  if (!(mx <= 0x1p1000)) return false;
  const double s = scale_for(mx);
  bool exact_scaling = true;  // no scaled bound underflows (else: no early-out)
  x = entries<RB>([&](int i, int j) {
    const auto k = static_cast<std::size_t>(4 * i + j);
    const double lo = enc.lo[k] * s, hi = enc.hi[k] * s;
    if (lo / s != enc.lo[k] || hi / s != enc.hi[k]) exact_scaling = false;
    return RB::enclosing(lo, hi);
  });
  return exact_scaling;
}

/// The entries of a body given by rationals, enclosed from their truncated doubles and scaled by a
/// power of two; false beyond 2^1000 (not filtered).
bool rational_entries(const Matrix4& m, SymmetricEntries<RB>& x, bool& sphere) {
  sphere = CGAL::is_zero(m(0, 1)) && CGAL::is_zero(m(0, 2)) && CGAL::is_zero(m(1, 2)) && m(0, 0) == m(1, 1) &&
           m(0, 0) == m(2, 2);
  // mpq_get_d truncates towards zero: |q - v| < ulp(v) <= 2^-52 |v| (or one subnormal step), about
  // four times cheaper than CGAL::to_interval. Inputs beyond 2^1000 are not filtered.
  std::array<double, 16> v{};
  double mx = 0;
  for (std::size_t i : {0, 1, 2, 3, 5, 6, 7, 10, 11, 15}) {
    v[i] = mpq_get_d(m.a[i].mpq());
    mx = std::max(mx, std::fabs(v[i]));
  }
  if (!(mx <= 0x1p1000)) return false;
  const double s = scale_for(mx);
  // |q s - v s| <= 2^-52 |v s| + 2^-1074 s, and v s is exact unless it underflows (one more
  // subnormal step).
  x = entries<RB>([&](int i, int j) {
    if (CGAL::is_zero(m(i, j))) return RB(0);
    const double y = v[static_cast<std::size_t>(4 * i + j)] * s;
    const double r = std::fabs(y) * 0x1p-51 + 0x1p-1073 * std::max(s, 1.0);
    return RB::enclosing(y - r, y + r);
  });
  return true;
}

/// The early-outs. Bodies given by exact doubles in range take the fast path (Fast, counts from
/// PreparedParaboloid); the others carry full RunningBounds. Rounding to nearest, no mode switch. A certificate
/// holds only when every sign it needs is certain.
[[gnu::flatten]] Early early_out_filter(const Scene::PreparedParaboloid& f, const Ellipsoid& e) {
  SymmetricEntries<RB> x;
  bool sphere;
  if (const std::optional<DoubleMatrix4> d = e.doubles()) {
    const DoubleMatrix4& m = *d;
    sphere = m[1] == 0 && m[2] == 0 && m[6] == 0 && m[0] == m[5] && m[0] == m[10];
    double mx = 0;
    for (std::size_t i : {0, 1, 2, 3, 5, 6, 7, 10, 11, 15}) mx = std::max(mx, std::fabs(m[i]));
    const double s = scale_for(mx);
    bool fast = s == 1 && f.fast_ok;
    for (std::size_t i : {0, 1, 2, 3, 5, 6, 7, 10, 11, 15}) fast = fast && fast_range(std::fabs(m[i]));
    if (fast) {  // the hot path: exact inputs in range, counts known
      const SymmetricEntries<Fast> fx = entries<Fast>([&](int i, int j) { return Fast(m[4 * i + j]); });
      if (sphere)
        return certify_sphere(fx, f.fp, f.diagonal_a, f.flambda_max, f.frho_factor, [&](const Fast& v, int i) {
          return RB::certain_sign(v.value(), v.magnitude(), f.sphere_counts[static_cast<std::size_t>(i)]);
        });
      return certify_general(fx, f.fp, f.diagonal_a, f.fadj_a, f.fdet_p, [&](const Fast& v, int i) {
        return RB::certain_sign(v.value(), v.magnitude(), f.general_counts[static_cast<std::size_t>(i)]);
      });
    }
    const double inv = 1 / s;  // exact: s is a power of two
    x = entries<RB>([&](int i, int j) {
      const double v = m[static_cast<std::size_t>(4 * i + j)], y = v * s;
      // Exact unless it underflowed; then the true value is within a subnormal step of y.
      return y * inv == v ? RB(y) : RB::enclosing(y - 0x1p-1074, y + 0x1p-1074);
    });
  } else if (const auto& enc = storage_of(e).enclosure()) {  // read from text: the stored enclosures
    if (!enclosure_entries(*enc, x, sphere)) return Early::None;
  } else if (!rational_entries(e.matrix(), x, sphere)) {
    return Early::None;
  }
  if (sphere) return certify_sphere(x, f.p, f.diagonal_a, f.lambda_max, f.rho_factor, tracked_sign);
  return certify_general(x, f.p, f.diagonal_a, f.adj_a, f.det_p, tracked_sign);
}

/// Bodies [lo, hi) into out[lo, hi): the early-outs (unless switched off), then the bodies they
/// leave open through decide_position's verdicts. `pending` and `decided`: the caller's buffers,
/// reused from chunk to chunk.
void classify_chunk(const Scene::PreparedParaboloid& prepared, const Paraboloid& p, const Ellipsoid* bodies,
                    std::size_t lo, std::size_t hi, const SceneOptions& options, SceneVerdict* out,
                    std::vector<std::size_t>& pending, std::vector<Verdict>& decided) {
  pending.clear();
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);  // threads inherit the caller's mode
  if (options.early_outs) {
    for (std::size_t i = lo; i < hi; ++i) {
      // The filter reads the 16 doubles at the start of each body and its flags after them:
      // fetch them a few bodies ahead (measured: about 5 % of the scene time).
      if (i + 8 < hi) {
        const char* ahead = reinterpret_cast<const char*>(&bodies[i + 8]);
        __builtin_prefetch(ahead);
        __builtin_prefetch(ahead + 64);
        __builtin_prefetch(ahead + 128);
      }
      const Early x = early_out_filter(prepared, bodies[i]);
      if (x != Early::None)
        out[i] = *verdict_of(x);
      else
        pending.push_back(i);
    }
  } else {
    for (std::size_t i = lo; i < hi; ++i) pending.push_back(i);
  }
  if (options.size_limit.max_bits != SizeLimit{}.max_bits) {  // a raised limit: one at a time, with it
    for (std::size_t i : pending) out[i] = scene_verdict(decide_position(bodies[i], p, options.size_limit));
  } else {
    // The bodies the early-outs leave open, decided in lanes (decide_positions: decide_position's
    // verdicts).
    decided.resize(pending.size());
    detail::decide_positions_at(bodies, pending.data(), pending.size(), p, decided.data());
    for (std::size_t k = 0; k < pending.size(); ++k) out[pending[k]] = scene_verdict(decided[k]);
  }
}

}  // namespace

Scene::Scene(const Paraboloid& p) : p_(p), prepared_(std::make_shared<const PreparedParaboloid>(p)) {}

// The filter's error bounds, like the core's static filter, assume rounding to nearest. A caller may
// be inside a CGAL interval block (rounding upward): then switch to nearest for the call.
std::optional<SceneVerdict> Scene::early_out(const Ellipsoid& e) const {
  return detail::approximate<detail::Rounding::ToNearest>([&] { return verdict_of(early_out_filter(*prepared_, e)); });
}

// The early-out, else decide_position; both in round to nearest (decide_position's double stages
// too), whatever the caller's mode.
SceneVerdict Scene::classify(const Ellipsoid& e) const {
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  return detail::filtered<detail::Rounding::ToNearest>([&] { return verdict_of(early_out_filter(*prepared_, e)); },
                                                       [&] { return scene_verdict(decide_position(e, p_)); });
}

SceneResult Scene::classify(const Ellipsoid* bodies, std::size_t count, const SceneOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  detail::WorkerPool pool(
      detail::scene_threads(options, count));  // fewer threads when one cannot start: the others do its work
  SceneResult result = detail::SceneAccess::classify(*this, bodies, count, options, pool);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

SceneResult detail::SceneAccess::classify(const Scene& scene, const Ellipsoid* bodies, std::size_t count,
                                          const SceneOptions& options, WorkerPool& pool) {
  const auto start = std::chrono::steady_clock::now();
  SceneResult result;
  result.verdicts.resize(count);
  SceneVerdict* out = result.verdicts.data();
  const Scene::PreparedParaboloid& prepared = *scene.prepared_;
  const Paraboloid& p = scene.p_;
  struct State {
    SceneCounts counts;
    std::vector<std::size_t> pending;  // a chunk's bodies the early-outs leave open, kept for the next chunk
    std::vector<Verdict> decided;
  };
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  result.threads =
      classify_in_chunks<State>(pool, count, options, result.counts, [&](State& s, std::size_t lo, std::size_t hi) {
        s.pending.reserve(chunk);
        classify_chunk(prepared, p, bodies, lo, hi, options, out, s.pending, s.decided);
        for (std::size_t i = lo; i < hi; ++i) s.counts.add(out[i]);
      });
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

SceneResult classify_scene(const Paraboloid& p, const std::vector<Ellipsoid>& bodies, const SceneOptions& options) {
  return Scene(p).classify(bodies, options);
}

}  // namespace relpos
