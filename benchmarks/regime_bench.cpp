// regime_bench: the paper's regime (small spheres and ellipsoids near the cup of an axis-aligned
// elliptic paraboloid, all 32 entries doubles) on the paths a user takes, against the naive double
// pipeline (characteristic quartic + discriminant + sign rule, naive_double.cpp) in the same run:
//
//   naive      the float pipeline on the 32 doubles (no certification)
//   decide     relpos::decide_position on prebuilt objects
//   doubles    32 doubles -> Ellipsoid/Paraboloid::from_doubles -> decide_position
//   onecall    32 doubles -> decide_position(e, p) on the doubles (the same steps in one call)
//   matrix     32 doubles -> exact_rational -> from_matrix -> decide_position (the rational road)
//   full       relpos::classify(e, p) with full evidence (f, s, roots, rho, certificate)
//
//   regime_bench [--n N] [--full N] [--seed S] [--batches B] [--rounds R] [--only POSITION] [--out FILE]
//
// --only POSITION (C, E, I, ...) only repeats full evidence on the pairs in that position (a
// profiling loop for perf record), then exits; --only decide, --only doubles and --only onecall
// repeat those paths.
//
// Prints one line per path: median ns per pair over B batches, and its ratio to the naive pipeline
// timed in the same round, as the median (and range) over R rounds. --out FILE also writes them as
// JSON (benchmarks/tables.py --regime renders it into doc/performance.md: benchmarks/run.sh --regime).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "float_baseline.hpp"
#include "ordinary/regime_matrices.hpp"
#include "relpos/classify.hpp"
#include "relpos/quadric.hpp"

using namespace relpos;
using Clock = std::chrono::steady_clock;

namespace {

struct Raw {
  DoubleMatrix4 e{}, p{};
};

/// z = x^2/a^2 + y^2/b^2 (a, b in [0.5, 2]) and an ellipsoid with semi-axes in [0.02, 0.3] (a
/// sphere half the time, else rotated by a random rotation), centred near the cup: within 0.6 of
/// the axis, height in [-0.2, 0.8]. Every entry is the double the formulas round to.
std::vector<Raw> make_regime(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> uab(0.5, 2), ur(0.02, 0.3), uxy(-0.6, 0.6), uz(-0.2, 0.8), u11(-1, 1);
  std::vector<Raw> out;
  while (static_cast<int>(out.size()) < n) {
    Raw r;
    const double a = uab(rng), b = uab(rng);
    regime::set(r.p, 0, 0, 1 / (a * a));
    regime::set(r.p, 1, 1, 1 / (b * b));
    regime::set(r.p, 2, 3, -0.5);
    const double c[3] = {uxy(rng) * a, uxy(rng) * b, uz(rng)};
    double m[3][3] = {};
    if (rng() % 2) {
      const double rad = ur(rng);
      for (int i = 0; i < 3; ++i) m[i][i] = 1 / (rad * rad);
    } else {
      double q[4];
      for (double& x : q) x = u11(rng);
      const double ax[3] = {ur(rng), ur(rng), ur(rng)};
      regime::rotated_block(q, ax, m);
    }
    regime::ellipsoid_matrix(m, c, r.e);
    out.push_back(r);
  }
  return out;
}

Matrix4 exact_matrix(const DoubleMatrix4& d) {
  Matrix4 m;
  for (std::size_t i = 0; i < 16; ++i) m.a[i] = exact_rational(d[i]);
  return m;
}

volatile int sink = 0;

/// Median over `batches` of the time per item of body(i) for i in [0, n).
template <class F>
double median_ns(int n, int batches, F body) {
  std::vector<double> t;
  for (int b = 0; b < batches; ++b) {
    const auto t0 = Clock::now();
    int acc = 0;
    for (int i = 0; i < n; ++i) acc += body(i);
    const auto t1 = Clock::now();
    sink = sink + acc;
    t.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / n);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

/// Per-pair median of single calls (for the slow full-evidence path: the pairs differ in cost).
template <class F>
double per_call_median_ns(int n, F body) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) {
    const auto t0 = Clock::now();
    sink = sink + body(i);
    const auto t1 = Clock::now();
    t.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int n = 20000, n_full = 400, batches = 7, rounds = 5;
  unsigned long seed = 20261124;
  std::string only, out_path;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--n") n = std::atoi(argv[i + 1]);
    if (a == "--full") n_full = std::atoi(argv[i + 1]);
    if (a == "--seed") seed = std::strtoul(argv[i + 1], nullptr, 10);
    if (a == "--batches") batches = std::atoi(argv[i + 1]);
    if (a == "--only") only = argv[i + 1];
    if (a == "--rounds") rounds = std::max(1, std::atoi(argv[i + 1]));
    if (a == "--out") out_path = argv[i + 1];
  }
  double load_before = -1, load_after = -1;
  getloadavg(&load_before, 1);
  std::mt19937_64 rng(seed);
  const std::vector<Raw> raw = make_regime(rng, n);
  std::vector<Ellipsoid> es;
  std::vector<Paraboloid> ps;
  for (const Raw& r : raw) {
    es.push_back(Ellipsoid::from_doubles(r.e));
    ps.push_back(Paraboloid::from_doubles(r.p));
  }
  std::map<std::string, int> mix;
  int naive_wrong = 0, onecall_differs = 0;
  for (int i = 0; i < n; ++i) {
    const Verdict v = decide_position(es[static_cast<std::size_t>(i)], ps[static_cast<std::size_t>(i)]);
    ++mix[to_string(v.position) + (v.small ? "" : " (not small)")];
    const auto nv = bench::naive_double(raw[static_cast<std::size_t>(i)].p, raw[static_cast<std::size_t>(i)].e);
    if (!nv || *nv != v.position) ++naive_wrong;
    const Verdict one = decide_position(raw[static_cast<std::size_t>(i)].e, raw[static_cast<std::size_t>(i)].p);
    if (one.position != v.position || one.stage != v.stage || one.rule != v.rule) ++onecall_differs;
  }
  std::printf("regime: %d pairs, seed %lu; positions:", n, seed);
  for (const auto& [k, c] : mix) std::printf(" %s %.1f%%", k.c_str(), 100.0 * c / n);
  std::printf("; naive double wrong or undecided on %d\n", naive_wrong);
  if (onecall_differs != 0) {  // the one-call decision must be the two steps' (the bench times both)
    std::printf("decide_position on the doubles differs from the two steps on %d pairs\n", onecall_differs);
    return 1;
  }

  const auto U = [](int i) { return static_cast<std::size_t>(i); };
  if (only == "decide" || only == "doubles" || only == "onecall") {  // profiling loop: one fast path only
    int acc = 0;
    for (int rep = 0; rep < batches * 20; ++rep)
      for (int i = 0; i < n; ++i) {
        if (only == "decide") {
          acc += static_cast<int>(decide_position(es[U(i)], ps[U(i)]).position);
        } else if (only == "onecall") {
          acc += static_cast<int>(decide_position(raw[U(i)].e, raw[U(i)].p).position);
        } else {
          const Ellipsoid e = Ellipsoid::from_doubles(raw[U(i)].e);
          const Paraboloid p = Paraboloid::from_doubles(raw[U(i)].p);
          acc += static_cast<int>(decide_position(e, p).position);
        }
      }
    std::printf("%s: %d\n", only.c_str(), acc);
    return 0;
  }
  if (!only.empty()) {  // profiling loop: full evidence on one position only
    int count = 0;
    for (int rep = 0; rep < batches; ++rep)
      for (int i = 0; i < std::min(n, n_full); ++i) {
        if (to_string(decide_position(es[U(i)], ps[U(i)]).position) != only) continue;
        const Ellipsoid e = Ellipsoid::from_doubles(raw[U(i)].e);
        const Paraboloid p = Paraboloid::from_doubles(raw[U(i)].p);
        count += classify(e, p, Evidence::Full).certificate.kind != Certificate::Kind::None;
      }
    std::printf("%s: %d certificates\n", only.c_str(), count);
    return 0;
  }
  // Each round times the naive pipeline and every path back to back, and the ratios are taken per
  // round: on a shared machine the speed changes over seconds, and a ratio of two medians taken
  // far apart would mix two speeds. Reported: the median over rounds of each time and ratio.
  const int nf = std::min(n, n_full);
  const int n_matrix = std::min(n, 2000);
  auto naive_ns = [&] {
    return median_ns(n, batches, [&](int i) {
      const auto v = bench::naive_double(raw[U(i)].p, raw[U(i)].e);
      return v ? static_cast<int>(*v) : -1;
    });
  };
  auto full_ns = [&] {
    return per_call_median_ns(nf, [&](int i) {
      const Ellipsoid e = Ellipsoid::from_doubles(raw[U(i)].e);  // fresh objects: nothing cached
      const Paraboloid p = Paraboloid::from_doubles(raw[U(i)].p);
      return static_cast<int>(classify(e, p, Evidence::Full).verdict.position);
    });
  };
  enum { kNaive, kMinimal, kDecide, kDoubles, kOneCall, kMatrix, kFull, kFullCached, kPaths };
  std::vector<std::array<double, kPaths>> time(static_cast<std::size_t>(rounds)), ratio(time.size()),
      ratio_min(time.size());
  for (auto& r : time) {
    r[kNaive] = naive_ns();
    r[kMinimal] =
        median_ns(n, batches, [&](int i) { return static_cast<int>(bench::minimal_double(raw[U(i)].p, raw[U(i)].e)); });
    r[kDecide] =
        median_ns(n, batches, [&](int i) { return static_cast<int>(decide_position(es[U(i)], ps[U(i)]).position); });
    r[kDoubles] = median_ns(n, batches, [&](int i) {
      const Ellipsoid e = Ellipsoid::from_doubles(raw[U(i)].e);
      const Paraboloid p = Paraboloid::from_doubles(raw[U(i)].p);
      return static_cast<int>(decide_position(e, p).position);
    });
    r[kOneCall] = median_ns(
        n, batches, [&](int i) { return static_cast<int>(decide_position(raw[U(i)].e, raw[U(i)].p).position); });
    r[kMatrix] = median_ns(n_matrix, std::min(batches, 3), [&](int i) {
      const Ellipsoid e = Ellipsoid::from_matrix(exact_matrix(raw[U(i)].e));
      const Paraboloid p = Paraboloid::from_matrix(exact_matrix(raw[U(i)].p));
      return static_cast<int>(decide_position(e, p).position);
    });
    r[kFull] = full_ns();
  }
  // The same full evidence with the opt-in GMP block cache of the CLI and the Python module,
  // installed last (it cannot be removed), each round against a naive time of its own.
  relpos::install_gmp_block_cache();
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double base = naive_ns();
    const double base_min =
        median_ns(n, batches, [&](int i) { return static_cast<int>(bench::minimal_double(raw[U(i)].p, raw[U(i)].e)); });
    time[k][kFullCached] = full_ns();
    for (int path = 0; path < kPaths; ++path) {
      const std::size_t q = static_cast<std::size_t>(path);
      ratio[k][q] = time[k][q] / (path == kFullCached ? base : time[k][kNaive]);
      ratio_min[k][q] = time[k][q] / (path == kFullCached ? base_min : time[k][kMinimal]);
    }
  }
  auto median_of = [&](const std::vector<std::array<double, kPaths>>& v, int path) {
    std::vector<double> x;
    for (const auto& r : v) x.push_back(r[static_cast<std::size_t>(path)]);
    std::sort(x.begin(), x.end());
    return x[x.size() / 2];
  };
  auto range_of = [&](int path) {
    double lo = HUGE_VAL, hi = 0;
    for (const auto& r : ratio)
      lo = std::min(lo, r[static_cast<std::size_t>(path)]), hi = std::max(hi, r[static_cast<std::size_t>(path)]);
    return std::pair<double, double>{lo, hi};
  };
  std::string json_positions;
  {  // full evidence by position: where the remaining cost is
    std::map<std::string, std::vector<double>> by;
    for (int i = 0; i < nf; ++i) {
      const Ellipsoid e = Ellipsoid::from_doubles(raw[U(i)].e);
      const Paraboloid p = Paraboloid::from_doubles(raw[U(i)].p);
      const auto t0 = Clock::now();
      const Classification c = classify(e, p, Evidence::Full);
      const auto t1 = Clock::now();
      by[to_string(c.verdict.position)].push_back(std::chrono::duration<double, std::nano>(t1 - t0).count());
    }
    std::printf("full evidence by position (per-pair median, block cache installed):");
    for (auto& [k, v] : by) {
      std::sort(v.begin(), v.end());
      std::printf(" %s %.0f us (%zu)", k.c_str(), v[v.size() / 2] / 1000, v.size());
      json_positions +=
          std::string(json_positions.empty() ? "" : ", ") + "\"" + k + "\": " + std::to_string(v[v.size() / 2]);
    }
    std::printf("\n");
  }
  std::printf("%d rounds; per path: median time, median of the per-round ratios to naive [range]\n", rounds);
  std::string json_rows;
  auto line = [&](const char* name, int path, const char* what) {
    const auto [lo, hi] = range_of(path);
    std::printf("%-8s %10.0f ns  %8.1fx naive [%.1f-%.1f] %8.2fx minimal   %s\n", name, median_of(time, path),
                median_of(ratio, path), lo, hi, median_of(ratio_min, path), what);
    char row[512];
    std::snprintf(row, sizeof row,
                  "%s  {\"key\": \"%s\", \"ns\": %.1f, \"vs_naive\": [%.3f, %.3f, %.3f], \"vs_minimal\": %.3f}",
                  json_rows.empty() ? "" : ",\n", name, median_of(time, path), median_of(ratio, path), lo, hi,
                  median_of(ratio_min, path));
    json_rows += row;
  };
  line("naive", kNaive, "naive double pipeline (characteristic quartic + discriminant + sign rule)");
  line("minimal", kMinimal, "minimal float decision (quartic, its discriminant, sign rule)");
  line("decide", kDecide, "decide_position on prebuilt objects");
  line("doubles", kDoubles, "32 doubles -> from_doubles -> decide_position");
  line("onecall", kOneCall, "32 doubles -> decide_position(e, p) on the doubles, in one call");
  line("matrix", kMatrix, "32 doubles -> exact_rational -> from_matrix -> decide_position");
  line("full", kFull, "classify(e, p), full evidence with certificate (per-pair median)");
  line("full+gc", kFullCached, "the same after relpos::install_gmp_block_cache() (as the CLI and Python)");
  if (!out_path.empty()) {
    std::FILE* f = std::fopen(out_path.c_str(), "w");
    if (!f) {
      std::perror(out_path.c_str());
      return 1;
    }
    getloadavg(&load_after, 1);
    char date[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    std::fprintf(f, "{\"date\": \"%s\", \"load_before\": %.2f, \"load_after\": %.2f,\n", date, load_before, load_after);
    std::string mix_json;
    for (const auto& [k, c] : mix)
      mix_json += std::string(mix_json.empty() ? "" : ", ") + "\"" + k + "\": " + std::to_string(c);
    std::fprintf(f,
                 " \"pairs\": %d, \"full_pairs\": %d, \"seed\": %lu, \"batches\": %d, \"rounds\": %d, "
                 "\"naive_wrong\": %d,\n \"mix\": {%s},\n \"full_by_position_ns\": {%s},\n \"paths\": [\n%s\n]}\n",
                 n, nf, seed, batches, rounds, naive_wrong, mix_json.c_str(), json_positions.c_str(),
                 json_rows.c_str());
    std::fclose(f);
  }
  return 0;
}
