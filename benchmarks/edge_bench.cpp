// edge_bench: the near-tangent regime (doc/performance.md, "Near tangency"). Spheres at distance
// delta = 2^-k (k = 40, 60, 100, 130) from an exact tangency, in positions known by construction:
//
//   * on the axis of four paraboloids z = a x^2 + b y^2, and off the axis of z = x^2 + y^2 at points
//     (x, y) whose normal n = (-2x, -2y, 1) has a rational length m;
//   * a sphere tangent from inside (radius below the smallest radius of curvature of the surface, so
//     it rolls freely inside) moved by delta n into the cup is strictly inside (I): it lies in the
//     sphere of radius r + delta tangent at the same point, itself inside; moved out of the cup it
//     crosses (C);
//   * a sphere tangent from outside moved away from the cup is separated (E): it lies
//     beyond the tangent plane; moved towards the cup it crosses (C).
//
// Every radius is below the smallest radius of curvature (small pairs, math.md §5), so that the FLINT
// reference, which implements the small-pair table only, decides every pair too.
// 100 tangencies from inside and 100 from outside give 400 spheres per delta: 100 I, 200 C, 100 E.
// Every method's answer is checked against the construction (the exact ones must all agree).
//
// Times: per pair, every method timed back to back (best of 3 loops of at least ~2 us), then the
// median over the pairs of each method; the ratios are of these medians, within the same run.
//
//   edge_bench [--quick] [--out DIR]   (DIR/edge.csv; a table on stdout)
//   edge_bench --profile METHOD K [R]  (METHOD on the pairs at 2^-K, R rounds (default: ~5 s), for perf)
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "certificate/build.hpp"
#include "decide/stages.hpp"
#include "flint_reference.hpp"
#include "float_baseline.hpp"
#include "pair/pair.hpp"
#include "relpos/classify.hpp"
#include "relpos/quadric.hpp"
#include "support/random_pairs.hpp"

using namespace relpos;
using Clock = std::chrono::steady_clock;

namespace {

using bench::float_classify;
using bench::naive_double;
using bench::naive_long_double;

struct Tangency {
  Matrix4 P;
  Vector3 point;  ///< the contact point
  Vector3 n;      ///< inward normal (-2ax, -2by, 1), not normalised
  Rational m;     ///< |n| (rational by choice of the point)
  Rational r;
  bool inside;  ///< tangent from inside (centre = point + (r/m) n), else from outside
};

struct Pair {
  Ellipsoid e;
  Paraboloid p;
  Position truth;
  std::array<double, 16> ed{}, pd{};  // nearest doubles (what a float user has)
  Pair(Ellipsoid e_, Paraboloid p_, Position t) : e(std::move(e_)), p(std::move(p_)), truth(t) {
    for (std::size_t i = 0; i < 16; ++i) {
      ed[i] = CGAL::to_double(e.matrix().a[i]);
      pd[i] = CGAL::to_double(p.matrix().a[i]);
    }
  }
};

/// Every radius is below the smallest radius of curvature (small pairs, math.md §5), so that the FLINT
// reference, which implements the small-pair table only, decides every pair too.
// 100 tangencies from inside and 100 from outside.
std::vector<Tangency> tangencies() {
  std::vector<Tangency> ts;
  // On the axis: 4 paraboloids x (9 inside + 9 outside). Smallest radius of curvature 1/(2 max(a, b)).
  const std::pair<Rational, Rational> ab[4] = {{Rational(1), Rational(1)},
                                               {Rational(1), Rational(1, 2)},
                                               {Rational(1, 4), Rational(1)},
                                               {Rational(2), Rational(3, 2)}};
  for (const auto& [a, b] : ab) {
    const Rational rmin = Rational(1) / (2 * std::max(a, b));
    const Vector3 o{Rational(0), Rational(0), Rational(0)}, n{Rational(0), Rational(0), Rational(1)};
    for (int j = 1; j <= 9; ++j)
      ts.push_back({rt::axis_paraboloid(a, b), o, n, Rational(1), rmin * Rational(j, 10), true});
    for (int j = 1; j <= 9; ++j)
      ts.push_back({rt::axis_paraboloid(a, b), o, n, Rational(1), rmin * Rational(j, 10), false});
  }
  // Off the axis of z = x^2 + y^2 (smallest radius of curvature 1/2): 16 points x (4 inside + 4 outside).
  struct Pt {
    Rational x, y, m;  // 4x^2 + 4y^2 + 1 = m^2
  };
  const Pt pts[4] = {{Rational(1), Rational(1), Rational(3)},
                     {Rational(2), Rational(4), Rational(9)},
                     {Rational(6), Rational(6), Rational(17)},
                     {Rational(0), Rational(3, 8), Rational(5, 4)}};
  for (const Pt& q : pts)
    for (int sx : {1, -1})
      for (int sy : {1, -1}) {
        const Rational x = sx * q.x, y = sy * q.y;
        const Vector3 pt{x, y, x * x + y * y}, n{-2 * x, -2 * y, Rational(1)};
        for (int j = 1; j <= 4; ++j)
          ts.push_back({rt::axis_paraboloid(Rational(1), Rational(1)), pt, n, q.m, Rational(j, 9), true});
        for (int j = 1; j <= 4; ++j)
          ts.push_back({rt::axis_paraboloid(Rational(1), Rational(1)), pt, n, q.m, Rational(j, 9), false});
      }
  return ts;
}

/// The sphere of t moved by delta along the inward unit normal (into the cup) or against it.
std::vector<Pair> family(const std::vector<Tangency>& ts, int k) {
  const Rational delta = Rational(1) / Rational(CGAL::Gmpz(1) << k);
  std::vector<Pair> out;
  for (const Tangency& t : ts) {
    const Rational along = (t.inside ? t.r : -t.r) / t.m;  // centre = point + along n
    for (int side : {1, -1}) {
      const Rational s = along + side * delta / t.m;
      const Vector3 c{t.point[0] + s * t.n[0], t.point[1] + s * t.n[1], t.point[2] + s * t.n[2]};
      const Position truth = t.inside ? (side > 0 ? Position::I : Position::C) : (side > 0 ? Position::C : Position::E);
      out.emplace_back(Ellipsoid::sphere(c, t.r), Paraboloid::from_matrix(t.P), truth);
    }
  }
  return out;
}

using Method = std::function<std::optional<Position>(const Pair&)>;

struct Named {
  std::string name;
  Method run;
  bool exact;  ///< must answer every pair right
};

/// The float methods read the nearest doubles, as a float user would; the exact ones the exact input.
std::vector<Named> methods() {
  std::vector<Named> ms;
  ms.push_back(
      {"decide", [](const Pair& x) { return std::optional<Position>(decide_position(x.e, x.p).position); }, true});
  ms.push_back({"exact",
                [](const Pair& x) {
                  return std::optional<Position>(classify_exact(x.e, x.p, Evidence::Minimal).verdict.position);
                },
                true});
  ms.push_back({"flint",
                [](const Pair& x) {
                  const bench::FlintAnswer a = bench::flint_classify(x.e.matrix(), x.p.matrix());
                  return a.ok ? std::optional<Position>(a.position) : std::nullopt;
                },
                true});
  ms.push_back(
      {"full",
       [](const Pair& x) { return std::optional<Position>(classify(x.e, x.p, Evidence::Full).verdict.position); },
       true});
  ms.push_back({"naive-double", [](const Pair& x) { return naive_double(x.pd, x.ed); }, false});
  ms.push_back({"long-double", [](const Pair& x) { return naive_long_double(x.pd, x.ed); }, false});
#ifdef __SIZEOF_FLOAT128__
  ms.push_back({"float128",
                [](const Pair& x) {
                  return float_classify<__float128>(x.pd, x.ed, [](double d) { return static_cast<__float128>(d); });
                },
                false});
#endif
  return ms;
}

volatile int g_sink = 0;

double time_one(const Method& m, const Pair& x, int reps) {
  int acc = 0;
  const auto s = Clock::now();
  for (int r = 0; r < reps; ++r) {
    const auto a = m(x);
    acc += a ? static_cast<int>(*a) : 7;
  }
  g_sink = g_sink + acc;
  return std::chrono::duration<double, std::nano>(Clock::now() - s).count() / reps;
}

double median(std::vector<double> x) {
  std::nth_element(x.begin(), x.begin() + static_cast<long>(x.size() / 2), x.end());
  return x[x.size() / 2];
}

/// The certificate's share of the full evidence, per pair: certificate::build timed alone on a pair
/// whose evidence classify's way is already built (f, s, S^4 f, the isolated roots, lambda_s), over
/// the time of classify itself.
double certificate_ns(const Pair& x, int reps) {
  const Verdict v = decide_position(x.e, x.p);
  double ns = 0;
  int acc = 0;
  for (int r = 0; r < reps; ++r) {
    detail::PairContext pair(x.e, x.p);
    pair.expect(v.sign_disc_f, v.position != Position::E && v.position != Position::I);
    pair.roots();
    Certificate c;
    const auto s = Clock::now();
    certificate::build(pair, v.position, c);
    ns += std::chrono::duration<double, std::nano>(Clock::now() - s).count();
    acc += static_cast<int>(c.kind);
  }
  g_sink = g_sink + acc;
  return ns / reps;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "benchmarks/results";
  bool quick = false;
  std::string profile;
  int profile_k = 0, profile_rounds = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick")
      quick = true;
    else if (a == "--out" && i + 1 < argc)
      out_dir = argv[++i];
    else if (a == "--profile" && i + 2 < argc) {
      profile = argv[++i], profile_k = std::stoi(argv[++i]);
      if (i + 1 < argc && argv[i + 1][0] != '-') profile_rounds = std::stoi(argv[++i]);
    } else {
      std::cerr << "usage: edge_bench [--quick] [--out DIR] | --profile METHOD K\n";
      return 2;
    }
  }
  const std::vector<Tangency> ts = tangencies();
  const auto ms = methods();
  if (!profile.empty()) {
    const std::vector<Pair> pairs = family(ts, profile_k);
    for (const auto& m : ms)
      if (m.name == profile) {
        const auto start = Clock::now();
        for (int round = 0;
             profile_rounds ? round < profile_rounds : std::chrono::duration<double>(Clock::now() - start).count() < 5;
             ++round)
          for (const auto& x : pairs) g_sink = g_sink + static_cast<int>(m.run(x).value_or(Position::TI));
        return 0;
      }
    std::cerr << "no method " << profile << "\n";
    return 2;
  }
  std::vector<std::string> header{"k"};
  for (const auto& m : ms) header.push_back(m.name + "_ns");
  header.push_back("certificate_ns");
  header.push_back("certificate_share");  // sum over pairs of certificate time / of full evidence time
  for (const auto& m : ms)
    if (!m.exact) header.push_back(m.name + "_error_rate");
  header.push_back("n");
  for (const Stage st : detail::kClassifierStages) header.push_back("stage_" + to_string(st));
  std::ofstream csv(out_dir + "/edge.csv");
  for (std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << header[i];
  csv << "\n";
  bool wrong_exact = false;
  std::printf("%-6s %5s", "delta", "n");
  for (const auto& m : ms) std::printf(" %12s", (m.name + (m.exact ? " us" : " us/err")).c_str());
  std::printf(" %9s %9s %9s %9s\n", "dec/exact", "exact/fl", "full/ex", "cert%");
  for (int k : {40, 60, 100, 130}) {
    std::vector<Pair> pairs = family(ts, k);
    if (quick) pairs.erase(pairs.begin() + static_cast<long>(pairs.size() / 4), pairs.end());
    int hist[5] = {0, 0, 0, 0, 0};
    for (const auto& p : pairs) ++hist[static_cast<int>(p.truth)];
    std::vector<int> errors(ms.size(), 0);
    std::array<int, kAllStages.size()> stages{};  // pairs per stage that decided them (decide_position)
    for (const auto& x : pairs) ++stages[static_cast<std::size_t>(decide_position(x.e, x.p).stage)];
    std::vector<std::vector<double>> t(ms.size() + 1, std::vector<double>(pairs.size()));
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const Pair& x = pairs[i];
      for (std::size_t j = 0; j < ms.size(); ++j) {
        const auto a = ms[j].run(x);
        if (a == x.truth) continue;
        ++errors[j];
        if (ms[j].exact) {
          wrong_exact = true;
          std::cerr << "CRITICAL: " << ms[j].name << " at delta 2^-" << k << ", pair " << i << ": "
                    << (a ? to_string(*a) : std::string("undecided")) << ", by construction " << to_string(x.truth)
                    << "\n";
        }
      }
      double est = 0;
      for (const auto& m : ms) est = std::max(est, time_one(m.run, x, 1));
      std::vector<double> best(ms.size() + 1, 1e300);
      for (int trial = 0; trial < 3; ++trial) {
        for (std::size_t j = 0; j < ms.size(); ++j) {
          const double one = time_one(ms[j].run, x, 1);
          const int reps = std::max(1, static_cast<int>(2000.0 / std::max(one, 1.0)));
          best[j] = std::min(best[j], reps == 1 ? one : time_one(ms[j].run, x, reps));
        }
        best[ms.size()] = std::min(best[ms.size()], certificate_ns(x, 1));
      }
      for (std::size_t j = 0; j <= ms.size(); ++j) t[j][i] = best[j];
    }
    std::vector<double> med(ms.size() + 1);
    for (std::size_t j = 0; j <= ms.size(); ++j) med[j] = median(t[j]);
    std::size_t full = 0;
    while (ms[full].name != "full") ++full;
    double cert_sum = 0, full_sum = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) cert_sum += t[ms.size()][i], full_sum += t[full][i];
    const double cert_share = cert_sum / full_sum;
    auto col = [&](const std::string& name) {
      for (std::size_t j = 0; j < ms.size(); ++j)
        if (ms[j].name == name) return med[j];
      return 0.0;
    };
    const double n = static_cast<double>(pairs.size());
    std::printf("2^-%-3d %5zu", k, pairs.size());
    for (std::size_t j = 0; j < ms.size(); ++j)
      if (ms[j].exact)
        std::printf(" %12.2f", med[j] / 1000);
      else
        std::printf(" %6.3f/%4.0f%%", med[j] / 1000, 100 * errors[j] / n);
    std::printf(" %9.2f %9.2f %9.0f %8.0f%%   (I/C/E %d/%d/%d)\n", col("decide") / col("exact"),
                col("exact") / col("flint"), col("full") / col("exact"), 100 * cert_share, hist[0], hist[2], hist[4]);
    csv << k;
    for (double x : med) csv << "," << x;
    csv << "," << cert_share;
    for (std::size_t j = 0; j < ms.size(); ++j)
      if (!ms[j].exact) csv << "," << errors[j] / n;
    csv << "," << pairs.size();
    for (const Stage st : detail::kClassifierStages) csv << "," << stages[static_cast<std::size_t>(st)];
    csv << "\n";
    std::printf("       decided by:");
    for (const Stage st : detail::kClassifierStages)
      if (stages[static_cast<std::size_t>(st)])
        std::printf(" %s %d", to_string(st).c_str(), stages[static_cast<std::size_t>(st)]);
    std::printf("\n");
    std::fflush(stdout);
  }
  if (wrong_exact) {
    std::cerr << "CRITICAL: an exact method contradicted the construction (see above)\n";
    return 3;
  }
  return 0;
}
