// ordinary_bench: relpos on ordinary pairs, as a user sees it, against two float decisions in plain
// doubles (float_decisions.hpp), all timed in the same run. Built against the installed package and
// its public headers only (benchmarks/ordinary/CMakeLists.txt; doc/performance.md, "Ordinary pairs").
//
//   ordinary_bench [--quick] [--out FILE] [--rounds R] [--batches B] [--seed S]
//                  [--cache N] [--issue N] [--large N] [--full N] [--paths P,...] [--sets S,...]
//
// Pairs: the paper's regime written as doubles (make_regime). Three sets: N_cache pairs looped (in
// cache), N_issue pairs and N_large pairs held in std::vectors (out of cache once they exceed the
// last-level cache). Paths, per pair:
//
//   minimal   minimal_float_decision on the 32 doubles (the bar's denominator)
//   paper     paper_float_decision on the 32 doubles
//   decide    relpos::decide_position on prebuilt objects
//   doubles   32 doubles -> Ellipsoid/Paraboloid::from_doubles -> decide_position
//   onecall   32 doubles -> decide_position(e, p) on the doubles (the same two steps in one call)
//   full      32 doubles -> from_doubles -> classify(e, p, Evidence::Full), on N_full pairs of the set
//
// Every round times each path over B batches per set, the paths interleaved batch by batch; a path's
// time in a round is its median batch (ns per pair), its ratios are to the two float decisions of the
// same set and round. Printed and written (--out): per path the median over rounds of the time and
// of each ratio, with the range of the ratios. --paths and --sets restrict the run to the named
// paths and sets (for profiling one path, or a quick A/B run): the two float decisions are always
// timed, as every ratio is to them; the pairs of a set left out are drawn (the others stay the
// same pairs) but neither checked nor timed.
//
// Before timing, every pair of every set is checked: decide_position on the prebuilt objects, on
// fresh objects from the doubles, on the doubles in one call and classify_exact (the exact
// reference) must give one position,
// and on the full-evidence pairs classify(Full) too, with a certificate verify_certificate accepts.
// Any disagreement is printed and the exit status is 1. The float decisions' answers are compared
// with relpos and counted (wrong, undecided); more than 1 % wrong also fails (a broken baseline).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/position.hpp>
#include <relpos/quadric.hpp>
#include <string>
#include <vector>

#include "float_decisions.hpp"
#include "regime_matrices.hpp"

using relpos::DoubleMatrix4;
using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::Position;
using Clock = std::chrono::steady_clock;

namespace {

struct Raw {
  DoubleMatrix4 p{}, e{};
};

/// The paper's regime in doubles (regime::ordinary_pair).
std::vector<Raw> make_regime(std::mt19937_64& rng, std::size_t n) {
  std::vector<Raw> out(n);
  for (Raw& r : out) regime::ordinary_pair(rng, r.e, r.p);
  return out;
}

enum Path { kMinimal, kPaper, kDecide, kDoubles, kOneCall, kFull, kPaths };
constexpr const char* kPathName[kPaths] = {"minimal", "paper", "decide", "doubles", "onecall", "full"};
constexpr const char* kPathText[kPaths] = {
    "minimal float decision (quartic, discriminant, sign rule)",
    "paper's float decision (+ Sturm-Habicht, smallness)",
    "decide_position on prebuilt objects",
    "32 doubles -> from_doubles -> decide_position",
    "32 doubles -> decide_position on the doubles, one call",
    "32 doubles -> from_doubles -> classify, full evidence",
};

struct PairSet {
  std::string name, text;
  bool timed = true;
  std::vector<Raw> raw;
  std::vector<Ellipsoid> es;  // as a user holds them
  std::vector<Paraboloid> ps;
  std::vector<Position> exact;                   // classify_exact
  std::vector<std::size_t> full_at;              // the pairs timed with full evidence (spread over the set)
  std::size_t reps = 1;                          // passes over the set per batch of a fast path
  std::array<std::vector<double>, kPaths> time;  // ns per pair, one entry per round
};

struct Checks {
  std::size_t pairs = 0, library_mismatches = 0, certificates_rejected = 0;
  std::array<std::size_t, kPaths> wrong{}, undecided{};
  std::map<std::string, std::size_t> mix;
};

const char* position_name(std::optional<Position> p) {
  static const char* names[] = {"I", "TI", "C", "TE", "E"};
  return p ? names[static_cast<int>(*p)] : "undecided";
}

/// Builds the objects and checks every pair (see the header comment); returns false on a library
/// disagreement.
bool prepare(PairSet& s, std::size_t n_full, Checks& checks) {
  const std::size_t n = s.raw.size();
  s.es.reserve(n);
  s.ps.reserve(n);
  for (const Raw& r : s.raw) {
    s.es.push_back(Ellipsoid::from_doubles(r.e));
    s.ps.push_back(Paraboloid::from_doubles(r.p));
  }
  const std::size_t nf = std::min(n, n_full), stride = n / std::max<std::size_t>(nf, 1);
  for (std::size_t k = 0; k < nf; ++k) s.full_at.push_back(k * stride);
  bool ok = true;
  auto mismatch = [&](std::size_t i, const char* what, Position got) {
    if (checks.library_mismatches++ < 10)
      std::fprintf(stderr, "%s pair %zu: %s gives %s, classify_exact %s\n", s.name.c_str(), i, what, position_name(got),
                   position_name(s.exact[i]));
    ok = false;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Raw& r = s.raw[i];
    const Ellipsoid e = Ellipsoid::from_doubles(r.e);
    const Paraboloid p = Paraboloid::from_doubles(r.p);
    const relpos::Verdict v = relpos::classify_exact(e, p, relpos::Evidence::Minimal).verdict;
    s.exact.push_back(v.position);
    ++checks.mix[std::string(position_name(v.position)) + (v.small ? "" : " (not small)")];
    const Position decided = relpos::decide_position(s.es[i], s.ps[i]).position;
    if (decided != v.position) mismatch(i, "decide_position (prebuilt)", decided);
    const Position fresh = relpos::decide_position(e, p).position;
    if (fresh != v.position) mismatch(i, "from_doubles + decide_position", fresh);
    const Position one = relpos::decide_position(r.e, r.p).position;
    if (one != v.position) mismatch(i, "decide_position on the doubles", one);
    const std::optional<Position> floats[2] = {ordinary::minimal_float_decision(r.p, r.e),
                                               ordinary::paper_float_decision(r.p, r.e)};
    for (int k = 0; k < 2; ++k) {
      if (!floats[k])
        ++checks.undecided[static_cast<std::size_t>(k)];
      else if (*floats[k] != v.position)
        ++checks.wrong[static_cast<std::size_t>(k)];
    }
  }
  for (std::size_t i : s.full_at) {
    const Ellipsoid e = Ellipsoid::from_doubles(s.raw[i].e);
    const Paraboloid p = Paraboloid::from_doubles(s.raw[i].p);
    const relpos::Classification c = relpos::classify(e, p, relpos::Evidence::Full);
    if (c.verdict.position != s.exact[i]) mismatch(i, "classify (full evidence)", c.verdict.position);
    if (const auto why = relpos::verify_certificate(e, p, c.verdict.position, c.certificate)) {
      if (checks.certificates_rejected++ < 10)
        std::fprintf(stderr, "%s pair %zu: certificate rejected: %s\n", s.name.c_str(), i, why->c_str());
      ok = false;
    }
  }
  checks.pairs += n;
  return ok;
}

volatile int sink = 0;

/// ns per pair of one batch of `path` on set s.
double time_batch(const PairSet& s, int path) {
  int acc = 0;
  std::size_t calls = 0;
  const auto t0 = Clock::now();
  if (path == kFull) {
    for (std::size_t i : s.full_at) {
      const Ellipsoid e = Ellipsoid::from_doubles(s.raw[i].e);
      const Paraboloid p = Paraboloid::from_doubles(s.raw[i].p);
      acc += static_cast<int>(relpos::classify(e, p, relpos::Evidence::Full).verdict.position);
    }
    calls = s.full_at.size();
  } else {
    const std::size_t n = s.raw.size();
    for (std::size_t rep = 0; rep < s.reps; ++rep) {
      switch (path) {
        case kMinimal:
          for (std::size_t i = 0; i < n; ++i) {
            const auto v = ordinary::minimal_float_decision(s.raw[i].p, s.raw[i].e);
            acc += v ? static_cast<int>(*v) : -1;
          }
          break;
        case kPaper:
          for (std::size_t i = 0; i < n; ++i) {
            const auto v = ordinary::paper_float_decision(s.raw[i].p, s.raw[i].e);
            acc += v ? static_cast<int>(*v) : -1;
          }
          break;
        case kDecide:
          for (std::size_t i = 0; i < n; ++i)
            acc += static_cast<int>(relpos::decide_position(s.es[i], s.ps[i]).position);
          break;
        case kDoubles:
          for (std::size_t i = 0; i < n; ++i) {
            const Ellipsoid e = Ellipsoid::from_doubles(s.raw[i].e);
            const Paraboloid p = Paraboloid::from_doubles(s.raw[i].p);
            acc += static_cast<int>(relpos::decide_position(e, p).position);
          }
          break;
        case kOneCall:
          for (std::size_t i = 0; i < n; ++i)
            acc += static_cast<int>(relpos::decide_position(s.raw[i].e, s.raw[i].p).position);
          break;
      }
    }
    calls = n * s.reps;
  }
  const auto t1 = Clock::now();
  sink = sink + acc;
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(calls);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

struct Summary {
  double median, lo, hi;
};

Summary summary(const std::vector<double>& v) {
  return {median(v), *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
}

std::vector<double> ratios(const PairSet& s, int path, int base) {
  std::vector<double> r;
  for (std::size_t k = 0; k < s.time[static_cast<std::size_t>(path)].size(); ++k)
    r.push_back(s.time[static_cast<std::size_t>(path)][k] / s.time[static_cast<std::size_t>(base)][k]);
  return r;
}

/// The first line of `path` that starts with `key` (after it), or "" (Linux: /proc/loadavg, /proc/cpuinfo).
std::string read_line(const char* path, const std::string& key) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (line.compare(0, key.size(), key) == 0) return line.substr(key.size());
  return "";
}

/// The machine's state, recorded with the figures: the load is what makes them comparable or not.
std::string load_average() {
  const std::string l = read_line("/proc/loadavg", "");
  return l.substr(0, l.find(' ', l.find(' ', l.find(' ') + 1) + 1));  // the 1, 5 and 15 minute averages
}

std::size_t parse_size(const char* s) { return static_cast<std::size_t>(std::strtoull(s, nullptr, 10)); }

/// The comma-separated names of an option's value.
std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  for (std::size_t at = 0; at <= s.size();) {
    const std::size_t end = std::min(s.find(',', at), s.size());
    out.push_back(s.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

bool named(const std::vector<std::string>& names, const std::string& name) {
  return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n_cache = 256, n_issue = 6000, n_large = 262144, n_full = 2000, min_calls = 16384;
  int rounds = 5, batches = 5;
  unsigned long seed = 20261125;
  std::string out;
  std::vector<std::string> paths, set_names;  // empty: all
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--quick") {
      n_cache = 64, n_issue = 300, n_large = 2000, n_full = 40, min_calls = 2000, rounds = 1, batches = 1;
    } else if (a == "--out" && has_value) {
      out = argv[++i];
    } else if (a == "--rounds" && has_value) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--batches" && has_value) {
      batches = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--seed" && has_value) {
      seed = std::strtoul(argv[++i], nullptr, 10);
    } else if (a == "--cache" && has_value) {
      n_cache = std::max<std::size_t>(1, parse_size(argv[++i]));
    } else if (a == "--issue" && has_value) {
      n_issue = std::max<std::size_t>(1, parse_size(argv[++i]));
    } else if (a == "--large" && has_value) {
      n_large = std::max<std::size_t>(1, parse_size(argv[++i]));
    } else if (a == "--full" && has_value) {
      n_full = parse_size(argv[++i]);
    } else if (a == "--paths" && has_value) {
      paths = split(argv[++i]);
    } else if (a == "--sets" && has_value) {
      set_names = split(argv[++i]);
    } else {
      std::fprintf(
          stderr,
          "usage: ordinary_bench [--quick] [--out FILE] [--rounds R] [--batches B] [--seed S]\n"
          "                      [--cache N] [--issue N] [--large N] [--full N] [--paths P,...] [--sets S,...]\n");
      return 2;
    }
  }
  const std::string load_before = load_average();
  std::mt19937_64 rng(seed);
  std::vector<PairSet> sets(3);
  sets[0].name = "cache", sets[0].text = "in cache, looped";
  sets[1].name = "issue", sets[1].text = "held in std::vector";
  sets[2].name = "large", sets[2].text = "held in std::vector";
  const std::size_t sizes[3] = {n_cache, n_issue, n_large};
  Checks checks;
  bool ok = true;
  std::array<bool, kPaths> timed{};
  for (int path = 0; path < kPaths; ++path)
    timed[static_cast<std::size_t>(path)] = path == kMinimal || path == kPaper || named(paths, kPathName[path]);
  for (const std::string& name : paths)
    if (std::find_if(kPathName, kPathName + kPaths, [&](const char* p) { return name == p; }) == kPathName + kPaths) {
      std::fprintf(stderr, "unknown path %s\n", name.c_str());
      return 2;
    }
  for (const std::string& name : set_names)
    if (name != "cache" && name != "issue" && name != "large") {
      std::fprintf(stderr, "unknown set %s\n", name.c_str());
      return 2;
    }
  for (std::size_t k = 0; k < sets.size(); ++k) {
    sets[k].raw = make_regime(rng, sizes[k]);
    sets[k].reps = std::max<std::size_t>(1, min_calls / sizes[k]);
    sets[k].timed = named(set_names, sets[k].name);
    if (sets[k].timed) ok = prepare(sets[k], n_full, checks) && ok;
  }
  const double pair_bytes = sizeof(Raw) + sizeof(Ellipsoid) + sizeof(Paraboloid);
  std::printf("ordinary pairs (seed %lu): %zu checked; positions:", seed, checks.pairs);
  for (const auto& [k, c] : checks.mix)
    std::printf(" %s %.1f%%", k.c_str(), 100.0 * static_cast<double>(c) / static_cast<double>(checks.pairs));
  std::printf(
      "\nrelpos paths (decide, from_doubles, classify full) against classify_exact: %zu disagreements, %zu "
      "certificates rejected\n",
      checks.library_mismatches, checks.certificates_rejected);
  for (int k : {kMinimal, kPaper})
    std::printf("%s float decision: wrong on %zu, undecided on %zu of %zu pairs\n", kPathName[k],
                checks.wrong[static_cast<std::size_t>(k)], checks.undecided[static_cast<std::size_t>(k)], checks.pairs);
  std::printf("held per pair: %.0f bytes (32 doubles + the two objects, heap not counted)\n", pair_bytes);
  // A float decision that gets many of these well-separated pairs wrong computes something else
  // than it claims, and a time measured against it would mean nothing.
  for (int k : {kMinimal, kPaper})
    if (checks.wrong[static_cast<std::size_t>(k)] * 100 > checks.pairs) {
      std::printf("FAILED: the %s float decision is wrong on more than 1 %% of the pairs\n", kPathName[k]);
      ok = false;
    }

  for (int round = 0; round < rounds; ++round)
    for (PairSet& s : sets) {
      if (!s.timed) continue;
      std::array<std::vector<double>, kPaths> batch;
      for (int b = 0; b < batches; ++b)
        for (int j = 0; j < kPaths; ++j) {  // interleaved, the order rotated from batch to batch
          const int path = (j + b + round) % kPaths;
          if (timed[static_cast<std::size_t>(path)])
            batch[static_cast<std::size_t>(path)].push_back(time_batch(s, path));
        }
      for (int path = 0; path < kPaths; ++path)
        if (timed[static_cast<std::size_t>(path)])
          s.time[static_cast<std::size_t>(path)].push_back(median(batch[static_cast<std::size_t>(path)]));
    }

  const std::string load_after = load_average();
  std::string cpu = read_line("/proc/cpuinfo", "model name");
  cpu = cpu.substr(std::min(cpu.size(), cpu.find_first_not_of(" \t:")));
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::printf("\n%s, %s, load average %s before and %s after\n", date, cpu.c_str(), load_before.c_str(),
              load_after.c_str());
  std::printf("%d rounds of %d batches; per path: median ns per pair, median of the per-round ratios [range]\n", rounds,
              batches);
  std::FILE* json = out.empty() ? nullptr : std::fopen(out.c_str(), "w");
  if (!out.empty() && !json) {
    std::fprintf(stderr, "cannot write %s\n", out.c_str());
    return 2;
  }
  if (json) {
    std::fprintf(json, "{\n  \"date\": \"%s\", \"cpu\": \"%s\", \"load_before\": \"%s\", \"load_after\": \"%s\",\n",
                 date, cpu.c_str(), load_before.c_str(), load_after.c_str());
    std::fprintf(json, "  \"seed\": %lu, \"rounds\": %d, \"batches\": %d, \"pairs_checked\": %zu,\n", seed, rounds,
                 batches, checks.pairs);
    std::fprintf(json, "  \"library_mismatches\": %zu, \"certificates_rejected\": %zu, \"bytes_per_pair\": %.0f,\n",
                 checks.library_mismatches, checks.certificates_rejected, pair_bytes);
    std::fprintf(json, "  \"float_wrong\": {\"minimal\": %zu, \"paper\": %zu}, ", checks.wrong[kMinimal],
                 checks.wrong[kPaper]);
    std::fprintf(json, "\"float_undecided\": {\"minimal\": %zu, \"paper\": %zu},\n  \"mix\": {",
                 checks.undecided[kMinimal], checks.undecided[kPaper]);
    const char* sep = "";
    for (const auto& [k, c] : checks.mix) std::fprintf(json, "%s\"%s\": %zu", sep, k.c_str(), c), sep = ", ";
    std::fprintf(json, "},\n  \"paths\": {");
    sep = "";
    for (int path = 0; path < kPaths; ++path)
      if (timed[static_cast<std::size_t>(path)])
        std::fprintf(json, "%s\"%s\": \"%s\"", sep, kPathName[path], kPathText[path]), sep = ", ";
    std::fprintf(json, "},\n  \"sets\": [\n");
  }
  const char* set_sep = "";
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const PairSet& s = sets[k];
    if (!s.timed) continue;
    std::printf("\n%s: %zu pairs, %s (%.1f MB)\n", s.name.c_str(), s.raw.size(), s.text.c_str(),
                pair_bytes * static_cast<double>(s.raw.size()) / 1e6);
    std::printf("  %-8s %10s   %-22s %-22s  %s\n", "path", "ns/pair", "x minimal [range]", "x paper [range]", "");
    if (json)
      std::fprintf(json,
                   "%s    {\"name\": \"%s\", \"pairs\": %zu, \"full_pairs\": %zu, \"text\": \"%s\", \"paths\": {\n",
                   set_sep, s.name.c_str(), s.raw.size(), s.full_at.size(), s.text.c_str());
    set_sep = ",\n";
    const char* path_sep = "";
    for (int path = 0; path < kPaths; ++path) {
      if (!timed[static_cast<std::size_t>(path)]) continue;
      const Summary t = summary(s.time[static_cast<std::size_t>(path)]);
      const Summary rm = summary(ratios(s, path, kMinimal)), rp = summary(ratios(s, path, kPaper));
      char a[64], b[64];
      std::snprintf(a, sizeof a, "%.2f [%.2f-%.2f]", rm.median, rm.lo, rm.hi);
      std::snprintf(b, sizeof b, "%.2f [%.2f-%.2f]", rp.median, rp.lo, rp.hi);
      std::printf("  %-8s %10.1f   %-22s %-22s  %s\n", kPathName[path], t.median, a, b, kPathText[path]);
      if (json)
        std::fprintf(
            json,
            "%s      \"%s\": {\"ns\": %.2f, \"ns_lo\": %.2f, \"ns_hi\": %.2f, \"vs_minimal\": [%.4f, %.4f, %.4f], "
            "\"vs_paper\": [%.4f, %.4f, %.4f]}",
            path_sep, kPathName[path], t.median, t.lo, t.hi, rm.median, rm.lo, rm.hi, rp.median, rp.lo, rp.hi);
      path_sep = ",\n";
    }
    if (json) std::fprintf(json, "\n    }}");
  }
  if (json) {
    std::fprintf(json, "\n  ]\n}\n");
    std::fclose(json);
  }
  if (!ok) std::printf("\nFAILED (see above)\n");
  return ok ? 0 : 1;
}
