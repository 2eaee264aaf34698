// lanes_bench: the many-pairs decision (decide_positions on 32 doubles a pair) against the scalar
// minimal float decision and the same float decision written in lanes, on 10^6 pairs, ratios taken
// in the same round (doc/performance.md, "Many pairs at once").
//
//   lanes_bench [--n N] [--block B] [--rounds R] [--seed S] [--out FILE]
//
// Two sets of N pairs (default 10^6), all 32 entries doubles: the ordinary benchmark's regime
// (regime::ordinary_pair) and spheres with standard paraboloids whose vertices and sizes vary as a
// user's do (regime::user_pair). Paths, per pair:
//
//   minimal        the minimal float decision, one pair at a time (benchmarks/ordinary/float_decisions.cpp)
//   minimal_lanes  the same float decision in lanes (minimal_float_lanes.inc), AVX-512 or AVX2 as the CPU has
//   many           relpos::decide_positions on the doubles (certified; the copy of its lanes the library chose)
//   many_avx2      the same with the AVX2 copy of the lanes (on a CPU with AVX-512 too, to show both)
//   onecall        relpos::decide_position on the doubles, one pair at a time (certified, scalar)
//
// Modes: "in cache" runs each path on blocks of B pairs (default 4096, 1 MB of doubles: within the
// per-core L2 cache), each block once untimed and then timed; "out of cache" runs it once over the
// whole arrays (512 MB for both sets). Each with one thread and with two (the pairs split in two
// halves). Every round times every path in every mode back to back; a path's ratio is to the scalar
// minimal float decision of the same set, mode and round; printed and written (--out): the median
// over rounds of each time and ratio, with the range of the ratios.
//
// Before timing, every pair is checked: decide_positions (each copy) gives decide_position's position
// and stage on every pair, and the lanes' float decision gives the scalar one's answer on every pair.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <random>
#include <relpos/classify.hpp>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "decide/many_pairs.hpp"
#include "filters/lane_double.hpp"
#include "filters/static_filter_lanes.hpp"
#include "ordinary/float_decisions.hpp"
#include "ordinary/regime_matrices.hpp"

namespace {

namespace baseline {
#include "minimal_float_lanes.inc"
}  // namespace baseline

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#include "minimal_float_lanes.inc"
}  // namespace avx2
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq")
namespace avx512 {
#include "minimal_float_lanes.inc"
}  // namespace avx512
#pragma GCC pop_options
#define LANES_BENCH_X86 1
#else
#define LANES_BENCH_X86 0
#endif

using relpos::DoubleMatrix4;
using Clock = std::chrono::steady_clock;

/// The minimal float decision in lanes, in the widest copy this CPU runs; its name.
using MinimalLanesRun = void (*)(const double*, const double*, std::size_t, std::size_t, signed char*);
std::pair<MinimalLanesRun, const char*> minimal_lanes_copy() {
#if LANES_BENCH_X86
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return {avx512::MinimalLanes<8>::run, "AVX-512"};
  if (__builtin_cpu_supports("avx2")) return {avx2::MinimalLanes<4>::run, "AVX2"};
#endif
  return {baseline::MinimalLanes<4>::run, "baseline"};
}

struct Set {
  std::string name;
  std::vector<double> e, p;  // 16 doubles a pair
  std::size_t size() const { return e.size() / 16; }
};

Set make_set(const std::string& name, std::size_t n, unsigned long seed) {
  std::mt19937_64 rng(seed);
  Set s{name, std::vector<double>(16 * n), std::vector<double>(16 * n)};
  for (std::size_t i = 0; i < n; ++i) {
    DoubleMatrix4 e, p;
    if (name == "user") {
      regime::user_pair(rng, e, p);
    } else {
      regime::ordinary_pair(rng, e, p);
    }
    std::copy(e.begin(), e.end(), s.e.begin() + static_cast<long>(16 * i));
    std::copy(p.begin(), p.end(), s.p.begin() + static_cast<long>(16 * i));
  }
  return s;
}

/// Output buffers of every path (written, so that no path is optimized away).
struct Outputs {
  std::vector<signed char> codes;
  std::vector<relpos::Position> positions;
  std::vector<relpos::PairStatus> status;
  explicit Outputs(std::size_t n) : codes(n), positions(n), status(n) {}
};

enum Path { kMinimal, kMinimalLanes, kMany, kManyAvx2, kOneCall, kPaths };
const char* const kPathKey[kPaths] = {"minimal", "minimal_lanes", "many", "many_avx2", "onecall"};

/// Matrix i of an array of row-major matrices, read in place (std::array<double, 16> is 16 doubles):
/// the scalar paths get the pairs as the lanes do, without a copy.
const DoubleMatrix4& matrix_at(const double* m, std::size_t i) {
  static_assert(sizeof(DoubleMatrix4) == 16 * sizeof(double), "an array of 16 doubles");
  return *reinterpret_cast<const DoubleMatrix4*>(m + 16 * i);
}

/// Path `path` on pairs [begin, end) of set s.
void run_path(int path, const Set& s, std::size_t begin, std::size_t end, Outputs& out, MinimalLanesRun lanes) {
  const double *e = s.e.data(), *p = s.p.data();
  switch (path) {
    case kMinimal:
      for (std::size_t i = begin; i < end; ++i) {
        const auto x = ordinary::minimal_float_decision(matrix_at(p, i), matrix_at(e, i));
        out.codes[i] = x ? static_cast<signed char>(*x) : -1;
      }
      return;
    case kMinimalLanes:
      lanes(e, p, begin, end, out.codes.data());
      return;
    case kMany:
      relpos::decide_positions(e + 16 * begin, p + 16 * begin, end - begin, out.positions.data() + begin,
                               out.status.data() + begin);
      return;
    case kManyAvx2:
      relpos::detail::decide_positions_copy(relpos::detail::FilterCopy::avx2, e + 16 * begin, p + 16 * begin,
                                            end - begin, out.positions.data() + begin, out.status.data() + begin,
                                            nullptr);
      return;
    default:
      for (std::size_t i = begin; i < end; ++i)
        out.positions[i] = relpos::decide_position(matrix_at(e, i), matrix_at(p, i)).position;
  }
}

/// Nanoseconds per pair of `path` on set s: `threads` threads, each on its half; in cache, each thread
/// runs each of its blocks of `block` pairs once untimed and then `repeat` times timed, and adds up the
/// fastest run of each block (a run another process interrupted is not the one kept); out of cache,
/// once over its half. The slowest thread's total over the pairs of the set.
double time_path(int path, const Set& s, bool in_cache, int threads, std::size_t block, int repeat, Outputs& out,
                 MinimalLanesRun lanes) {
  const std::size_t n = s.size();
  std::vector<double> seconds(static_cast<std::size_t>(threads), 0.0);
  auto work = [&](int t) {
    const std::size_t begin = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads);
    const std::size_t end = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(threads);
    double total = 0;
    if (in_cache) {
      for (std::size_t b = begin; b < end; b += block) {
        const std::size_t e = std::min(end, b + block);
        run_path(path, s, b, e, out, lanes);
        double best = 1e30;
        for (int k = 0; k < repeat; ++k) {
          const auto t0 = Clock::now();
          run_path(path, s, b, e, out, lanes);
          best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
        }
        total += best;
      }
    } else {
      const auto t0 = Clock::now();
      run_path(path, s, begin, end, out, lanes);
      total = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    seconds[static_cast<std::size_t>(t)] = total;
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  return 1e9 * *std::max_element(seconds.begin(), seconds.end()) / static_cast<double>(n);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 1000000, user_n = 200000, block = 4096;
  int rounds = 5, repeat = 3;
  unsigned long seed = 20261201;
  std::string out_path;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--n") n = std::strtoul(argv[i + 1], nullptr, 10);
    if (a == "--user-n") user_n = std::strtoul(argv[i + 1], nullptr, 10);
    if (a == "--block") block = std::strtoul(argv[i + 1], nullptr, 10);
    if (a == "--repeat") repeat = std::max(1, std::atoi(argv[i + 1]));
    if (a == "--rounds") rounds = std::max(1, std::atoi(argv[i + 1]));
    if (a == "--seed") seed = std::strtoul(argv[i + 1], nullptr, 10);
    if (a == "--out") out_path = argv[i + 1];
  }
  double load_before = -1, load_after = -1;
  getloadavg(&load_before, 1);
  const auto [lanes, lanes_name] = minimal_lanes_copy();
  const bool avx2 = relpos::detail::static_filter_lanes_copy_runs(relpos::detail::FilterCopy::avx2);
  const char* many_copy = relpos::detail::static_filter_lanes_copy_runs(relpos::detail::FilterCopy::avx512) ? "AVX-512"
                          : avx2                                                                            ? "AVX2"
                                 : "baseline";
  std::vector<Set> sets;
  sets.push_back(make_set("ordinary", n, seed));
  sets.push_back(make_set("user", std::min(n, user_n), seed + 1));

  // Checks: every pair's position and stage from each copy of decide_positions against
  // decide_position, and the lanes' float decision against the scalar one.
  std::map<std::string, std::map<std::string, long>> mix;
  std::map<std::string, long> minimal_wrong, minimal_undecided, static_stage;
  bool ok = true;
  for (const Set& s : sets) {
    const std::size_t size = s.size();
    Outputs want(size), got(size);
    run_path(kOneCall, s, 0, size, want, lanes);
    std::vector<relpos::Stage> want_stage(size), got_stage(size);
    for (std::size_t i = 0; i < size; ++i) {
      DoubleMatrix4 em, pm;
      std::memcpy(em.data(), s.e.data() + 16 * i, sizeof em);
      std::memcpy(pm.data(), s.p.data() + 16 * i, sizeof pm);
      const relpos::Verdict v = relpos::decide_position(em, pm);
      want_stage[i] = v.stage;
      ++mix[s.name][to_string(v.position) + (v.small ? "" : " (not small)")];
      static_stage[s.name] += v.stage == relpos::Stage::StaticDouble;
    }
    for (const auto copy :
         {relpos::detail::FilterCopy::baseline, relpos::detail::FilterCopy::avx2, relpos::detail::FilterCopy::avx512}) {
      if (!relpos::detail::static_filter_lanes_copy_runs(copy)) continue;
      relpos::detail::decide_positions_copy(copy, s.e.data(), s.p.data(), size, got.positions.data(), got.status.data(),
                                            got_stage.data());
      long differ = 0;
      for (std::size_t i = 0; i < size; ++i)
        differ += got.status[i] != relpos::PairStatus::Decided || got.positions[i] != want.positions[i] ||
                  got_stage[i] != want_stage[i];
      if (differ) {
        std::printf("%s: copy %d of decide_positions differs from decide_position on %ld pairs\n", s.name.c_str(),
                    static_cast<int>(copy), differ);
        ok = false;
      }
    }
    relpos::decide_positions(s.e.data(), s.p.data(), size, got.positions.data(), got.status.data());
    if (!std::equal(got.positions.begin(), got.positions.end(), want.positions.begin())) ok = false;
    Outputs scalar(size), vec(size);
    run_path(kMinimal, s, 0, size, scalar, lanes);
    run_path(kMinimalLanes, s, 0, size, vec, lanes);
    if (scalar.codes != vec.codes) {
      std::printf("%s: the float decision in lanes differs from the scalar one\n", s.name.c_str());
      ok = false;
    }
    for (std::size_t i = 0; i < size; ++i) {
      minimal_undecided[s.name] += scalar.codes[i] < 0;
      minimal_wrong[s.name] += scalar.codes[i] >= 0 && scalar.codes[i] != static_cast<int>(want.positions[i]);
    }
  }
  if (!ok) return 1;

  // Rounds: every path in every set, mode and thread count, back to back.
  struct Key {
    std::string set;
    bool in_cache;
    int threads;
    bool operator<(const Key& o) const {
      return std::tie(set, in_cache, threads) < std::tie(o.set, o.in_cache, o.threads);
    }
  };
  std::map<Key, std::vector<std::vector<double>>> times;  // [path][round]
  Outputs scratch(n);
  for (int r = 0; r < rounds; ++r)
    for (const Set& s : sets)
      for (const int threads : {1, 2})
        for (const bool in_cache : {true, false}) {
          auto& t = times[{s.name, in_cache, threads}];
          t.resize(kPaths);
          for (int path = 0; path < kPaths; ++path) {
            if (path == kManyAvx2 && !avx2) continue;
            t[static_cast<std::size_t>(path)].push_back(
                time_path(path, s, in_cache, threads, block, repeat, scratch, lanes));
          }
        }
  getloadavg(&load_after, 1);

  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::string cpu = "unknown";
  {
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);)
      if (line.rfind("model name", 0) == 0) {
        cpu = line.substr(line.find(':') + 2);
        break;
      }
  }
  std::printf(
      "lanes_bench: %zu ordinary and %zu user pairs, blocks of %zu in cache (best of %d), %d rounds; %s; lanes: "
      "many %s, minimal %s\n",
      sets[0].size(), sets[1].size(), block, repeat, rounds, cpu.c_str(), many_copy, lanes_name);
  std::string json = "{\"date\": \"" + std::string(date) + "\", \"cpu\": \"" + cpu +
                     "\", \"pairs\": " + std::to_string(sets[0].size()) +
                     ", \"user_pairs\": " + std::to_string(sets[1].size()) + ", \"block\": " + std::to_string(block) +
                     ", \"repeat\": " + std::to_string(repeat) + ", \"rounds\": " + std::to_string(rounds) +
                     ", \"many_copy\": \"" + many_copy + "\", \"minimal_lanes_copy\": \"" + lanes_name +
                     "\", \"load_before\": " + std::to_string(load_before) +
                     ", \"load_after\": " + std::to_string(load_after) + ", \"sets\": {";
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const std::string& name = sets[k].name;
    json += (k ? ", " : "") + std::string("\"") + name + "\": {\"static\": " + std::to_string(static_stage[name]) +
            ", \"minimal_wrong\": " + std::to_string(minimal_wrong[name]) +
            ", \"minimal_undecided\": " + std::to_string(minimal_undecided[name]) + ", \"mix\": {";
    bool first = true;
    for (const auto& [pos, count] : mix[name]) {
      json += (first ? "" : ", ") + std::string("\"") + pos + "\": " + std::to_string(count);
      first = false;
    }
    json += "}}";
    std::printf("%s: static stage %ld of %zu; minimal float decision wrong on %ld, undecided on %ld\n", name.c_str(),
                static_stage[name], sets[k].size(), minimal_wrong[name], minimal_undecided[name]);
  }
  json += "}, \"results\": [";
  bool first = true;
  for (const auto& [key, t] : times) {
    for (int path = 0; path < kPaths; ++path) {
      const auto& mine = t[static_cast<std::size_t>(path)];
      if (mine.empty()) continue;
      std::vector<double> ratio;
      for (std::size_t r = 0; r < mine.size(); ++r) ratio.push_back(mine[r] / t[kMinimal][r]);
      const double m = median(ratio), lo = *std::min_element(ratio.begin(), ratio.end()),
                   hi = *std::max_element(ratio.begin(), ratio.end());
      std::printf("%-8s %-12s %d thread%s %-14s %8.1f ns  %6.3fx minimal [%5.3f-%5.3f]\n", key.set.c_str(),
                  key.in_cache ? "in cache" : "out of cache", key.threads, key.threads > 1 ? "s" : " ", kPathKey[path],
                  median(mine), m, lo, hi);
      char row[512];
      std::snprintf(row, sizeof row,
                    "%s{\"set\": \"%s\", \"in_cache\": %s, \"threads\": %d, \"path\": \"%s\", \"ns\": %.2f, "
                    "\"ratio\": [%.4f, %.4f, %.4f]}",
                    first ? "" : ", ", key.set.c_str(), key.in_cache ? "true" : "false", key.threads, kPathKey[path],
                    median(mine), m, lo, hi);
      json += row;
      first = false;
    }
  }
  json += "]}\n";
  if (!out_path.empty()) std::ofstream(out_path) << json;
  return 0;
}
