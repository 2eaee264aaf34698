// scene_bench: throughput of relpos::Scene (one paraboloid, many ellipsoids) against per-pair
// decide_position on the same bodies, the fraction settled by each early-out / stage, and the check
// that every answer equals per-pair classify_exact (doc/performance.md, "Scenes").
//
//   scene_bench [--n N] [--seed S] [--wall W] [--repeat R] [--out DIR] [--no-verify]
//
// The scene is relpos::DemoSceneGenerator(S, a = 1, b = 2, W): particles in the container
// x^2 + y^2/4 <= z, a fraction W of them at the wall. Writes DIR/scene.json (DIR/scene-wall-W.json
// when --wall is given) and prints a report.
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "decide/stages.hpp"
#include "relpos/classify.hpp"
#include "relpos/scene.hpp"
#include "scene/demo.hpp"

using namespace relpos;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string json_list(const std::vector<double>& v) {
  std::ostringstream o;
  o << "[";
  for (std::size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "") << v[i];
  o << "]";
  return o.str();
}

double quantile(std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(q * static_cast<double>(sorted.size())))];
}

/// Run f(i) for i in [0, n) on t threads, dynamically (chunks of 256).
template <class F>
void parallel(std::size_t n, unsigned t, F f) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (;;) {
      const std::size_t lo = next.fetch_add(256);
      if (lo >= n) return;
      for (std::size_t i = lo; i < std::min(n, lo + 256); ++i) f(i);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < t; ++w) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
}

struct Run {
  unsigned threads;
  bool early_outs;
  double seconds;      // wall clock, median over repeats
  double cpu_seconds;  // CPU time of the classifying threads, median over repeats
  SceneResult last;
};

/// CPU time of the calling thread (1 thread: the scene runs in it) or of the process (all threads):
/// unlike wall time, it does not count the time the threads wait for a core on a shared machine.
double cpu_seconds(bool whole_process) {
  timespec t{};
  clock_gettime(whole_process ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 1000000;
  std::uint64_t seed = 20240601;
  int repeat = 3;
  std::string out_dir;
  bool verify = true;
  double wall = DemoSceneGenerator::kDefaultWall;
  bool wall_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "scene_bench: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--n")
      n = std::stoull(value());
    else if (a == "--seed")
      seed = std::stoull(value());
    else if (a == "--repeat")
      repeat = std::max(1, std::stoi(value()));
    else if (a == "--out")
      out_dir = value();
    else if (a == "--wall") {
      wall = std::stod(value());
      wall_given = true;
    } else if (a == "--no-verify")
      verify = false;
    else {
      std::cerr << "usage: scene_bench [--n N] [--seed S] [--wall W] [--repeat R] [--out DIR] [--no-verify]\n";
      return 2;
    }
  }
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const Rational a(1), b(2);
  const Paraboloid p = Paraboloid::standard({Rational(0), Rational(0), Rational(0)}, a, b);
  std::printf(
      "scene_bench: n = %zu, seed = %llu, wall fraction %g, paraboloid x^2 + y^2/4 = z, hardware threads = %u\n", n,
      static_cast<unsigned long long>(seed), wall, hw);

  // --- the scene -----------------------------------------------------------------------------
  auto t0 = Clock::now();
  std::vector<DemoBody> demo;
  {
    DemoSceneGenerator gen(seed, a, b, wall);
    demo.reserve(n);
    for (std::size_t i = 0; i < n; ++i) demo.push_back(gen.next());
  }
  const double gen_s = seconds_since(t0);
  t0 = Clock::now();
  std::vector<std::optional<Ellipsoid>> built(n);
  parallel(n, hw, [&](std::size_t i) { built[i] = demo[i].ellipsoid(); });
  std::vector<Ellipsoid> bodies;
  bodies.reserve(n);
  std::size_t exact_doubles = 0, spheres = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bodies.push_back(std::move(*built[i]));
    exact_doubles += bodies.back().doubles().has_value();
    spheres += demo[i].kind == DemoBody::Kind::Sphere;
  }
  built.clear();
  built.shrink_to_fit();
  demo.clear();
  demo.shrink_to_fit();
  const double build_s = seconds_since(t0);
  std::printf(
      "generated in %.2f s, Ellipsoid objects built in %.2f s (%u threads); %zu spheres, %zu with "
      "exact-double matrices\n",
      gen_s, build_s, hw, spheres, exact_doubles);

  const Scene scene(p);

  // --- per-pair decide_position, one thread, each call timed ---------------------------------
  std::vector<double> pair_ns(n);
  std::vector<Verdict> pair_verdict(n);
  double timer_ns;
  {
    std::vector<double> empty(10001);
    for (auto& e : empty) {
      const auto s = Clock::now();
      e = std::chrono::duration<double, std::nano>(Clock::now() - s).count();
    }
    timer_ns = median(empty);
  }
  t0 = Clock::now();
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = Clock::now();
    pair_verdict[i] = decide_position(bodies[i], p);
    pair_ns[i] = std::chrono::duration<double, std::nano>(Clock::now() - s).count() - timer_ns;
  }
  const double pair_loop_s = seconds_since(t0);
  std::vector<double> sorted = pair_ns;
  std::sort(sorted.begin(), sorted.end());
  const double pair_median = quantile(sorted, 0.5), pair_p90 = quantile(sorted, 0.9), pair_p99 = quantile(sorted, 0.99);
  const double pair_mean = std::accumulate(pair_ns.begin(), pair_ns.end(), 0.0) / static_cast<double>(n);
  std::printf(
      "per-pair decide_position (1 thread, each call timed, timer overhead %.0f ns subtracted):\n"
      "  median %.0f ns, p90 %.0f ns, p99 %.0f ns, mean %.0f ns (loop %.2f s)\n",
      timer_ns, pair_median, pair_p90, pair_p99, pair_mean, pair_loop_s);
  // Where the per-pair time goes: by the stage of decide_position that decided.
  std::ostringstream by_stage_json;
  {
    std::vector<std::vector<double>> by(kAllStages.size());
    for (std::size_t i = 0; i < n; ++i) by[static_cast<std::size_t>(pair_verdict[i].stage)].push_back(pair_ns[i]);
    for (const Stage stage : detail::kClassifierStages) {
      const std::size_t s = static_cast<std::size_t>(stage);
      const std::string name = to_string(stage);
      const double sum = std::accumulate(by[s].begin(), by[s].end(), 0.0);
      const double mean = by[s].empty() ? 0.0 : sum / static_cast<double>(by[s].size());
      std::printf("  decided by %-21s %8zu pairs (%6.3f %%): median %8.0f ns, mean %8.0f ns, %5.1f %% of the time\n",
                  name.c_str(), by[s].size(), 100.0 * static_cast<double>(by[s].size()) / static_cast<double>(n),
                  median(by[s]), mean, 100.0 * sum / (pair_mean * static_cast<double>(n)));
      by_stage_json << (stage != detail::kClassifierStages.front() ? ", " : "") << "\"" << name
                    << "\": {\"pairs\": " << by[s].size() << ", \"median_ns\": " << median(by[s])
                    << ", \"mean_ns\": " << mean << "}";
    }
  }

  // --- early-outs alone ---------------------------------------------------------------------
  std::vector<std::optional<SceneVerdict>> early(n);
  std::vector<double> eo_runs;
  for (int r = 0; r < repeat; ++r) {
    const double c0 = cpu_seconds(false);
    for (std::size_t i = 0; i < n; ++i) early[i] = scene.early_out(bodies[i]);
    eo_runs.push_back(cpu_seconds(false) - c0);
  }
  const double eo_ns = median(eo_runs) * 1e9 / static_cast<double>(n);
  std::size_t settled = 0;
  std::vector<double> settled_pair_ns, rest_pair_ns;
  for (std::size_t i = 0; i < n; ++i) {
    if (early[i]) {
      ++settled;
      settled_pair_ns.push_back(pair_ns[i]);
    } else {
      rest_pair_ns.push_back(pair_ns[i]);
    }
  }
  std::printf(
      "early-outs alone (Scene::early_out, CPU time): %.0f ns per body; "
      "settle %.2f %%;\n  decide_position median on the bodies they settle %.0f ns, on the others "
      "%.0f ns\n",
      eo_ns, 100.0 * static_cast<double>(settled) / static_cast<double>(n), median(settled_pair_ns),
      median(rest_pair_ns));

  // --- scenes --------------------------------------------------------------------------------
  std::vector<unsigned> thread_counts{1};
  if (hw >= 2) thread_counts.push_back(2);
  if (hw > 2) thread_counts.push_back(hw);
  std::vector<Run> runs;
  for (bool eo : {true, false})
    for (unsigned t : thread_counts) {
      Run run{t, eo, 0, 0, {}};
      std::vector<double> secs, cpu;
      for (int r = 0; r < repeat; ++r) {
        SceneOptions o;
        o.threads = t;
        o.early_outs = eo;
        const double c0 = cpu_seconds(t > 1);
        run.last = scene.classify(bodies, o);
        cpu.push_back(cpu_seconds(t > 1) - c0);
        secs.push_back(run.last.seconds);
      }
      run.seconds = median(secs);
      run.cpu_seconds = median(cpu);
      std::printf("scene %-14s %2u thread(s): wall %.3f s = %.0f ns per body, %.3g bodies/s; CPU %.0f ns per body\n",
                  eo ? "early-outs" : "no early-outs", t, run.seconds, run.seconds * 1e9 / static_cast<double>(n),
                  static_cast<double>(n) / run.seconds, run.cpu_seconds * 1e9 / static_cast<double>(n));
      runs.push_back(std::move(run));
    }
  const SceneResult& main_result = runs.front().last;
  const SceneCounts& c = main_result.counts;
  std::printf("positions: I %zu, TI %zu, C %zu, TE %zu, E %zu\n", c.count(Position::I), c.count(Position::TI),
              c.count(Position::C), c.count(Position::TE), c.count(Position::E));
  std::printf("settled by:");
  for (const Stage s : detail::kSceneStages)
    std::printf(" %s %.3f %%%s", to_string(s).c_str(), 100.0 * static_cast<double>(c.count(s)) / static_cast<double>(n),
                s != detail::kSceneStages.back() ? "," : "\n");

  // Determinism: every run gives the same verdicts.
  bool runs_agree = true;
  for (const Run& r : runs)
    for (std::size_t i = 0; i < n && runs_agree; ++i)
      runs_agree = r.last.verdicts[i].position == main_result.verdicts[i].position &&
                   r.last.verdicts[i].rule == main_result.verdicts[i].rule;
  std::size_t vs_pairs = 0;
  for (std::size_t i = 0; i < n; ++i)
    vs_pairs += main_result.verdicts[i].position != pair_verdict[i].position ||
                main_result.verdicts[i].rule != pair_verdict[i].rule;
  std::printf("all scene runs agree: %s; scene vs per-pair decide_position: %zu differences\n",
              runs_agree ? "yes" : "NO", vs_pairs);

  // --- verification against classify_exact ----------------------------------------------------
  std::size_t mismatches = 0;
  double verify_s = 0;
  if (verify) {
    t0 = Clock::now();
    std::vector<unsigned char> bad(n, 0);
    parallel(n, hw, [&](std::size_t i) {
      const Classification x = classify_exact(bodies[i], p, Evidence::Minimal);
      const SceneVerdict& v = main_result.verdicts[i];
      bad[i] = x.verdict.position != v.position || x.verdict.rule != v.rule;
    });
    verify_s = seconds_since(t0);
    for (std::size_t i = 0; i < n; ++i)
      if (bad[i]) {
        if (++mismatches <= 10)
          std::printf("MISMATCH body %zu: scene %s (%s)\n", i, to_string(main_result.verdicts[i].position).c_str(),
                      to_string(main_result.verdicts[i].stage).c_str());
      }
    std::printf("verification: %zu bodies against classify_exact (%u threads, %.1f s): %zu mismatches\n", n, hw,
                verify_s, mismatches);
  }

  // The bar: the scene's mean cost per body on one thread against the median cost of one
  // decide_position call on the same bodies. On a shared machine both drift with the load, so they
  // are measured in alternation, R rounds (each call timed on a contiguous block of at most 200000
  // bodies -- contiguous like the scene's own pass, so both see the same memory access pattern --
  // then the whole scene on one thread, its CPU time and its wall time), and the ratio is taken
  // per round; the report gives the median round and the range.
  std::vector<double> ratio_cpu, ratio_wall, round_median, round_cpu, round_wall;
  {
    const std::size_t m = std::min<std::size_t>(n, 200000);
    for (int r = 0; r < std::max(repeat, 5); ++r) {
      std::vector<double> ns;
      ns.reserve(m);
      const std::size_t off = (static_cast<std::size_t>(r) * m) % (n - m + 1);
      for (std::size_t i = off; i < off + m; ++i) {
        const auto s = Clock::now();
        const Verdict v = decide_position(bodies[i], p);
        ns.push_back(std::chrono::duration<double, std::nano>(Clock::now() - s).count() - timer_ns);
        if (v.position != pair_verdict[i].position) std::abort();
      }
      SceneOptions o;
      o.threads = 1;
      const double c0 = cpu_seconds(false);
      const SceneResult res = scene.classify(bodies, o);
      const double cpu = (cpu_seconds(false) - c0) * 1e9 / static_cast<double>(n);
      const double wall_ns = res.seconds * 1e9 / static_cast<double>(n);
      round_median.push_back(median(ns));
      round_cpu.push_back(cpu);
      round_wall.push_back(wall_ns);
      ratio_cpu.push_back(cpu / median(ns));
      ratio_wall.push_back(wall_ns / median(ns));
      std::printf(
          "bar round %d: per-pair median %.0f ns; scene on 1 thread %.0f ns CPU, %.0f ns wall per body: "
          "ratio %.2f CPU, %.2f wall\n",
          r + 1, median(ns), cpu, wall_ns, cpu / median(ns), wall_ns / median(ns));
    }
  }
  const double bar_cpu = median(ratio_cpu), bar_wall = median(ratio_wall);
  std::printf(
      "BAR: scene per-body cost on 1 thread / per-pair decide_position median: %.2f CPU (rounds %.2f..%.2f), "
      "%.2f wall (rounds %.2f..%.2f): %s\n",
      bar_cpu, *std::min_element(ratio_cpu.begin(), ratio_cpu.end()),
      *std::max_element(ratio_cpu.begin(), ratio_cpu.end()), bar_wall,
      *std::min_element(ratio_wall.begin(), ratio_wall.end()), *std::max_element(ratio_wall.begin(), ratio_wall.end()),
      bar_cpu <= 1 ? "met" : "NOT met");

  if (!out_dir.empty()) {
    std::ostringstream js;
    js << "{\n  \"n\": " << n << ", \"seed\": " << seed << ", \"wall\": " << wall << ", \"hardware_threads\": " << hw
       << ", \"paraboloid\": \"x^2 + y^2/4 = z\",\n  \"spheres\": " << spheres
       << ", \"exact_double_bodies\": " << exact_doubles << ", \"generate_seconds\": " << gen_s
       << ", \"build_seconds\": " << build_s << ",\n  \"pair_decide_position_ns\": {\"median\": " << pair_median
       << ", \"p90\": " << pair_p90 << ", \"p99\": " << pair_p99 << ", \"mean\": " << pair_mean
       << ", \"timer_overhead\": " << timer_ns << "},\n  \"pair_by_stage\": {" << by_stage_json.str()
       << "},\n  \"early_out_alone_ns\": " << eo_ns
       << ", \"early_out_settled_fraction\": " << static_cast<double>(settled) / static_cast<double>(n)
       << ",\n  \"pair_median_ns_on_settled\": " << median(settled_pair_ns)
       << ", \"pair_median_ns_on_rest\": " << median(rest_pair_ns) << ",\n  \"runs\": [";
    for (std::size_t i = 0; i < runs.size(); ++i)
      js << (i ? ", " : "") << "\n    {\"threads\": " << runs[i].threads
         << ", \"early_outs\": " << (runs[i].early_outs ? "true" : "false") << ", \"seconds\": " << runs[i].seconds
         << ", \"ns_per_body\": " << runs[i].seconds * 1e9 / static_cast<double>(n)
         << ", \"bodies_per_second\": " << static_cast<double>(n) / runs[i].seconds
         << ", \"cpu_ns_per_body\": " << runs[i].cpu_seconds * 1e9 / static_cast<double>(n) << "}";
    js << "\n  ],\n  \"positions\": {\"I\": " << c.count(Position::I) << ", \"TI\": " << c.count(Position::TI)
       << ", \"C\": " << c.count(Position::C) << ", \"TE\": " << c.count(Position::TE)
       << ", \"E\": " << c.count(Position::E) << "},\n  \"stages\": {";
    for (const Stage s : detail::kSceneStages)
      js << (s != detail::kSceneStages.front() ? ", " : "") << "\"" << to_string(s) << "\": " << c.count(s);
    js << "},\n  \"runs_agree\": " << (runs_agree ? "true" : "false") << ", \"differences_vs_pairs\": " << vs_pairs
       << ",\n  \"verified\": " << (verify ? "true" : "false") << ", \"verify_seconds\": " << verify_s
       << ", \"mismatches_vs_classify_exact\": " << mismatches
       << ",\n  \"bar_rounds\": {\"pair_median_ns\": " << json_list(round_median)
       << ", \"scene_cpu_ns_per_body\": " << json_list(round_cpu)
       << ", \"scene_wall_ns_per_body\": " << json_list(round_wall) << "},\n  \"bar_ratio_cpu\": " << bar_cpu
       << ", \"bar_ratio_wall\": " << bar_wall << "\n}\n";
    const std::string name = wall_given ? "/scene-wall-" + std::to_string(wall).substr(0, 6) + ".json" : "/scene.json";
    std::ofstream f(out_dir + name);
    f << js.str();
    if (!f) {
      std::cerr << "scene_bench: cannot write " << out_dir << name << "\n";
      return 3;
    }
  }
  return (mismatches == 0 && vs_pairs == 0 && runs_agree) ? 0 : 1;  // the bar is reported, not enforced
}
