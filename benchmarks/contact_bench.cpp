// contact_bench: per-pair time of decide_position() versus the discriminant-only decision
// (decide_by_discriminant), the translation tracker (ExteriorTracker::update), contact() and
// ContactChecker::contact(), measured back to back on the same random exact-double pairs. Each round
// times one pass of every method over all pairs, the order of the methods rotating from round to
// round (fair on a noisy, shared machine); the medians over rounds are printed, with the fraction
// of pairs each path decided. Every answer is checked against decide_position().
//
// Usage: contact_bench [pairs=20000] [rounds=15] [seed=1]
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/contact.hpp>
#include <string>
#include <vector>

#include "contact/discriminant_case.hpp"
#include "support/random_pairs.hpp"

using namespace relpos;
using Clock = std::chrono::steady_clock;

namespace {

struct Pair {
  std::size_t para;  ///< index of the paraboloid
  Ellipsoid e;
};

/// Random ellipsoids (level k in [0.01, 2]) and paraboloids of relpos_bench's family (a), all
/// entries exact doubles (tests/support/random_pairs.hpp).
Ellipsoid random_ellipsoid(std::mt19937_64& rng) {
  for (;;) {
    try {
      return Ellipsoid::from_matrix(rt::random_double_ellipsoid_matrix(rng, 0.01));
    } catch (const std::exception&) {
    }
  }
}

Paraboloid random_paraboloid(std::mt19937_64& rng) {
  return Paraboloid::from_matrix(rt::random_double_paraboloid_matrix(rng));
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

volatile int g_sink = 0;  // keeps the answers alive

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20000;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 15;
  const std::uint64_t seed = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1;
  std::mt19937_64 rng(seed);
  std::vector<Paraboloid> paras;
  for (int i = 0; i < 16; ++i) paras.push_back(random_paraboloid(rng));
  std::vector<Pair> pairs;
  pairs.reserve(n);
  for (std::size_t i = 0; i < n; ++i) pairs.push_back({i % paras.size(), random_ellipsoid(rng)});
  std::vector<ContactChecker> checkers;
  for (const auto& p : paras) checkers.emplace_back(p);
  // One tracker per body, reference = the body itself (construction, exact, not timed).
  std::vector<ExteriorTracker> trackers;
  trackers.reserve(n);
  for (const auto& q : pairs) trackers.emplace_back(paras[q.para], q.e);

  // Correctness and path fractions (one untimed pass).
  std::array<std::size_t, kAllStages.size()> by_disc{}, by_contact{}, by_checker{};  // per Stage
  std::array<std::size_t, 5> positions{};                                            // I, TI, C, TE, E
  std::size_t mismatches = 0, tracker_filter = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Paraboloid& p = paras[pairs[i].para];
    const Ellipsoid& e = pairs[i].e;
    const Verdict v = decide_position(e, p);
    ++positions[static_cast<std::size_t>(v.position)];
    const auto d = detail::decide_by_discriminant(e, p);
    ++by_disc[static_cast<std::size_t>(d.verdict.stage)];
    const ContactAnswer c = contact(e, p), s = checkers[pairs[i].para].contact(e);
    ++by_contact[static_cast<std::size_t>(c.stage)];
    ++by_checker[static_cast<std::size_t>(s.stage)];
    ExteriorTracker t(p, e);
    const auto fr = t.update(e);
    tracker_filter += fr.stage == Stage::DiscriminantFilter;
    if (d.verdict.position != v.position || d.verdict.rule != v.rule || fr.position != v.position ||
        c.position != v.position || c.contact != contact_of(v.position) || s.contact != c.contact)
      ++mismatches;
  }

  using Method = std::function<int(std::size_t)>;
  const std::vector<std::pair<std::string, Method>> methods = {
      {"decide_position",
       [&](std::size_t i) { return int(decide_position(pairs[i].e, paras[pairs[i].para]).position); }},
      {"decide_by_discriminant",
       [&](std::size_t i) {
         return int(detail::decide_by_discriminant(pairs[i].e, paras[pairs[i].para]).verdict.position);
       }},
      {"ExteriorTracker::update", [&](std::size_t i) { return int(trackers[i].update(pairs[i].e).position); }},
      {"contact()", [&](std::size_t i) { return int(contact(pairs[i].e, paras[pairs[i].para]).contact); }},
      {"ContactChecker::contact",
       [&](std::size_t i) { return int(checkers[pairs[i].para].contact(pairs[i].e).contact); }},
  };
  std::vector<std::vector<double>> ns(methods.size());
  for (int r = 0; r < rounds; ++r)
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const std::size_t m = (k + static_cast<std::size_t>(r)) % methods.size();  // rotate the order
      int acc = 0;
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < n; ++i) acc += methods[m].second(i);
      const auto t1 = std::chrono::steady_clock::now();
      g_sink = g_sink + acc;
      ns[m].push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(n));
    }

  std::printf("contact_bench: %zu random exact-double pairs (16 paraboloids), %d rounds, seed %llu\n", n, rounds,
              static_cast<unsigned long long>(seed));
  std::printf("positions: I %zu, TI %zu, C %zu, TE %zu, E %zu; mismatches %zu\n", positions[0], positions[1],
              positions[2], positions[3], positions[4], mismatches);
  const double base = median(ns[0]);
  std::printf("%-26s %12s %12s %12s %9s\n", "method", "median ns", "min ns", "max ns", "speedup");
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const auto& v = ns[m];
    std::printf("%-26s %12.1f %12.1f %12.1f %9.2f\n", methods[m].first.c_str(), median(v),
                *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end()), base / median(v));
  }
  // Percent of the pairs whose stage has the given decided_by text (scene-certificate, ...).
  auto frac = [&](const std::array<std::size_t, kAllStages.size()>& a, const char* by) {
    std::size_t k = 0;
    for (const Stage s : kAllStages)
      if (decided_by(s) == by) k += a[static_cast<std::size_t>(s)];
    return 100.0 * static_cast<double>(k) / static_cast<double>(n);
  };
  std::printf("decided by (%%):            scene-cert  disc-filter  full-classifier\n");
  for (const auto& [name, a] :
       {std::pair<const char*, const std::array<std::size_t, kAllStages.size()>*>{"decide_by_discriminant", &by_disc},
        {"contact()", &by_contact},
        {"ContactChecker::contact", &by_checker}})
    std::printf("%-26s %10.2f %12.2f %16.2f\n", name, frac(*a, "scene-certificate"), frac(*a, "discriminant-filter"),
                frac(*a, "full-classifier"));
  std::printf("%-26s %23.2f\n", "ExteriorTracker::update",
              100.0 * static_cast<double>(tracker_filter) / static_cast<double>(n));

  // A body moving by translation, frame by frame: the tracker's update(translation) (no moved
  // ellipsoid formed) against what a caller would otherwise do per frame: build the moved body
  // exactly (Ellipsoid::translated, or from_matrix with validation) and classify it.
  std::size_t moving_mismatches = 0;
  {
    const Paraboloid& p = paras[0];
    const Vector3 axes{Rational(1, 4), Rational(1, 8), Rational(1, 16)};
    const Ellipsoid bodies[2] = {Ellipsoid::sphere({Rational(0), Rational(0), Rational(0)}, Rational(1, 8)),
                                 Ellipsoid::from_axes({Rational(0), Rational(0), Rational(0)}, axes,
                                                      Quaternion{Rational(2), Rational(1), Rational(-1), Rational(1)})};
    const char* names[2] = {"dyadic sphere", "rotated ellipsoid (rational)"};
    const std::size_t frames = 2000;
    std::uniform_real_distribution<double> u(-2, 2);
    std::vector<std::array<double, 3>> path(frames);
    for (auto& d : path) d = {u(rng), u(rng), u(rng) + 1};
    std::printf("moving body, %zu frames of random double translations, median over %d rounds (ns per frame):\n",
                frames, std::max(3, rounds / 3));
    std::printf("%-30s %16s %22s %26s\n", "body", "tracker.update(d)", "translated+decide", "from_matrix+decide");
    for (int b = 0; b < 2; ++b) {
      std::vector<double> t_track, t_trans, t_full;
      for (int r = 0; r < std::max(3, rounds / 3); ++r) {
        ExteriorTracker tr(p, bodies[b]);
        std::vector<Position> a(frames), c(frames);
        auto t0 = Clock::now();
        for (std::size_t k = 0; k < frames; ++k) a[k] = tr.update(path[k]).position;
        auto t1 = Clock::now();
        for (std::size_t k = 0; k < frames; ++k) {
          const Vector3 d{exact_rational(path[k][0]), exact_rational(path[k][1]), exact_rational(path[k][2])};
          c[k] = decide_position(bodies[b].translated(d), p).position;
        }
        auto t2 = Clock::now();
        for (std::size_t k = 0; k < frames / 10; ++k) {  // slow: a tenth of the frames
          const Vector3 d{exact_rational(path[k][0]), exact_rational(path[k][1]), exact_rational(path[k][2])};
          const Position x = decide_position(Ellipsoid::from_matrix(bodies[b].translated(d).matrix()), p).position;
          moving_mismatches += x != c[k];
        }
        auto t3 = Clock::now();
        for (std::size_t k = 0; k < frames; ++k) moving_mismatches += a[k] != c[k];
        t_track.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / frames);
        t_trans.push_back(std::chrono::duration<double, std::nano>(t2 - t1).count() / frames);
        t_full.push_back(std::chrono::duration<double, std::nano>(t3 - t2).count() / (frames / 10));
      }
      std::printf("%-30s %16.0f %22.0f %26.0f\n", names[b], median(t_track), median(t_trans), median(t_full));
    }
    std::printf("moving-body mismatches against decide_position: %zu\n", moving_mismatches);
  }
  return mismatches == 0 && moving_mismatches == 0 ? 0 : 1;
}
