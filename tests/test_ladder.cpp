// The ladder as a table (src/decide/stages.hpp, ladder.hpp): the one table of what each stage is;
// every stage, run alone before the exact roots, settles each pair as the exact classification does
// (so no stage depends on another's being right); the whole ladder equals decide_position; the
// per-stage counters (counters.hpp) count what ran and where each climb ended.
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/contact.hpp>
#include <set>
#include <string>
#include <vector>

#include "decide/ladder.hpp"
#include "decide/stages.hpp"
#include "io/fast_quadric.hpp"
#include "support/construct.hpp"
#include "support/random_pairs.hpp"
#include "support/seed.hpp"

using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::Stage;
using relpos::Verdict;
using namespace relpos::detail;
using rt::Q;

namespace {

struct Pair {
  std::string name;
  Ellipsoid e;
  Paraboloid p;
};

/// Pairs of known or exactly computed position on every path: the five positions around exact
/// tangencies (rational entries, and the same under a random congruence), spheres on the axis of
/// z = x^2 + y^2 given as doubles (tangencies included: the multiple-root witness), random pairs of
/// doubles, and pairs read from decimal text.
std::vector<Pair> corpus(std::uint64_t seed) {
  std::vector<Pair> out;
  rt::Rng g(seed);
  for (int i = 0; i < 6; ++i) {
    const relpos::Rational a = Q(g.uniform(2, 6), 3), b = Q(g.uniform(2, 6), 3);
    const auto [s, t] = rt::random_st(g, true);
    const rt::TangentPoint tp = rt::tangent_point(a, b, s, t);
    for (const rt::Config& k : rt::tangency_family(tp, rt::random_tangent_radius(g, a, b), g.uniform(1, 7))) {
      out.push_back({k.name, Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p())});
      const rt::Congruence h = rt::random_congruence(g);
      out.push_back({k.name + " (congruence)", Ellipsoid::from_matrix(rt::congruence(k.e(), h.h)),
                     Paraboloid::from_matrix(rt::congruence(k.p(), h.h))});
    }
  }
  const Paraboloid cup = Paraboloid::standard(std::array<double, 3>{0, 0, 0}, 1.0, 1.0);
  for (double z : {0.25, 0.125, 0.0, -0.125, -0.25, -0.375})
    out.push_back(
        {"axis sphere z=" + std::to_string(z), Ellipsoid::sphere(std::array<double, 3>{0, 0, z}, 0.125), cup});
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 60; ++i) {
    relpos::Matrix4 em = rt::random_double_ellipsoid_matrix(rng, i % 2 ? 0.001 : 0.3);
    out.push_back({"doubles " + std::to_string(i), Ellipsoid::from_matrix(em),
                   Paraboloid::from_matrix(rt::axis_paraboloid(Q(1, 2), Q(3, 2)))});
  }
  for (const char* es : {R"({"sphere":{"center":[0,0.5,0.7120447530864197],"radius":0.25}})",
                         R"({"sphere":{"center":[0.1,0.2,0.3],"radius":2}})",
                         R"([[2,0.5,0,-1],[0.5,3,0.25,0],[0,0.25,1,-0.5],[-1,0,-0.5,-0.75]])"})
    out.push_back({std::string("text ") + es, *relpos::detail::io::fast_ellipsoid(es, false),
                   *relpos::detail::io::fast_paraboloid(R"({"vertex":[0,0,0],"a":1.2,"b":1.5})", false)});
  return out;
}

template <class... S>
Verdict run(const Pair& k, StageList<S...> list, StageCounts* counts = nullptr) {
  const PairContext pair(k.e, k.p);
  Climb c(pair, true);
  if (counts) return climb(c, CountInto{*counts}, list);
  return climb(c, NoCounters{}, list);
}

/// The stage a single climb ended in, from its counts.
Stage ended_in(const StageCounts& counts) {
  Stage out = Stage::ExactRoots;
  int n = 0;
  for (const Stage s : relpos::kAllStages)
    if (counts.ended[static_cast<std::size_t>(s)].load() == 1) out = s, ++n;
  CHECK(n == 1);
  return out;
}

}  // namespace

TEST_CASE("stage table: one row per stage, every name, meaning and part distinct", "[ladder]") {
  std::set<std::string> names, meanings;
  for (const Stage s : relpos::kAllStages) {
    const StageRow& row = stage_row(s);
    CHECK(row.stage == s);
    CHECK(relpos::to_string(s) == row.name);
    CHECK(relpos::decided_by(s) == row.decided_by);
    names.insert(row.name);
    meanings.insert(row.meaning);
    // The classifier's stages report the full classifier, the others themselves or the scene.
    const bool classifier =
        std::find(relpos::detail::kClassifierStages.begin(), relpos::detail::kClassifierStages.end(), s) !=
        relpos::detail::kClassifierStages.end();
    CHECK((std::string(row.decided_by) == "full-classifier") == classifier);
  }
  CHECK(names.size() == relpos::kAllStages.size());
  CHECK(meanings.size() == relpos::kAllStages.size());
}

TEST_CASE("ladder: each stage alone, before the exact roots, settles every pair as classify_exact", "[ladder]") {
  for (const Pair& k : corpus(relpos::testing::announced_seed("test_ladder", 20260302))) {
    INFO(k.name);
    const relpos::Classification exact = relpos::classify_exact(k.e, k.p, relpos::Evidence::Minimal);
    auto same = [&](const Verdict& v) {
      CHECK(v.position == exact.verdict.position);
      CHECK(v.rule == exact.verdict.rule);
    };
    same(run(k, StageList<ExactRootsStage>{}));
    same(run(k, StageList<ExactSignsStage, ExactRootsStage>{}));
    same(run(k, StageList<IntervalStage, ExactRootsStage>{}));
    same(run(k, StageList<StaticDoubleStage, ExactRootsStage>{}));
    same(run(k, StageList<StaticDoubleStage, SemiStaticDoubleStage, ExactRootsStage>{}));
    same(run(k, StageList<SemiStaticDoubleStage, ExactRootsStage>{}));
    same(run(k, StageList<StaticDoubleStage, MultipleRootWitnessStage, ExactRootsStage>{}));
    const Verdict whole = run(k, ClassifierLadder{});
    same(whole);
    const Verdict v = relpos::decide_position(k.e, k.p);
    CHECK(whole.stage == v.stage);
  }
}

TEST_CASE("ladder: the counters count what ran and where each climb ended", "[ladder]") {
  const std::vector<Pair> all = corpus(relpos::testing::seed_from_env(20260302));
  StageCounts total;
  std::set<Stage> ends;
  for (const Pair& k : all) {
    INFO(k.name);
    StageCounts one;
    const Verdict v = run(k, ClassifierLadder{}, &one);
    run(k, ClassifierLadder{}, &total);
    const Stage end = ended_in(one);
    ends.insert(end);
    // The verdict names the stage that ended the climb, or a later one that the gap test used.
    CHECK(v.stage >= end);
    if (v.roots_above_lambda_s < 0) CHECK(v.stage == end);
    // No stage after the one that ended ran; the static stage ran exactly for pairs of doubles.
    for (const Stage s : relpos::detail::kClassifierStages)
      if (s > end) CHECK(one.ran[static_cast<std::size_t>(s)].load() == 0);
    const bool doubles = k.e.doubles() && k.p.doubles();
    CHECK(one.ran[static_cast<std::size_t>(Stage::StaticDouble)].load() == (doubles ? 1u : 0u));
  }
  unsigned long ended = 0;
  for (const auto& x : total.ended) ended += x.load();
  CHECK(ended == all.size());
  CHECK(ends.size() >= 4);  // the corpus reaches most of the ladder
  // The library's own counters: counting only when built with RELPOS_STAGE_COUNTERS.
  const unsigned long before = library_stage_counts().ended[static_cast<std::size_t>(Stage::StaticDouble)].load();
  const Verdict v = relpos::decide_position(all.back().e, all.back().p);
  unsigned long after = 0;
  for (const auto& x : library_stage_counts().ended) after += x.load();
  if (kLibraryCountsStages) {
    CHECK(after >= 1);
    CHECK(v.rule != relpos::Rule::None);
  } else {
    CHECK(after == 0);
    CHECK(before == 0);
  }
}
