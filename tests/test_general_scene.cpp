// Scenes against a general quadric (include/relpos/general_scene.hpp): the constructed pairs of
// tests/support/general_cases.hpp grouped by their quadric, as given and under a random rational
// affine congruence of the whole scene, get the position of their construction and exactly the
// verdict of decide_position(e, q) for each body, on one thread and on several with chunks of one
// body, with counts that add up; bodies read from doubles get the answer of the same matrices read
// exactly.
#include <catch2/catch.hpp>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "relpos/general_classify.hpp"
#include "relpos/general_scene.hpp"
#include "support/general_cases.hpp"
#include "support/seed.hpp"

using namespace relpos;
using namespace relpos::testing;

namespace {

/// One scene: a quadric and the bodies of the constructed cases that share it.
struct Group {
  Quadric q;
  std::vector<Ellipsoid> bodies;
  std::vector<QuadricPosition> expected;
  std::vector<std::string> names;
};

std::vector<Group> scenes(bool mapped, std::mt19937_64& rng) {
  std::map<std::string, std::size_t> index;  // by the quadric's exact matrix
  std::vector<Group> out;
  for (const GeneralCase& k : constructed_cases()) {
    std::string key;
    for (const Rational& x : k.q.matrix().a) key += to_string(x) + ",";
    auto [it, fresh] = index.emplace(key, out.size());
    if (fresh) out.push_back(Group{k.q, {}, {}, {}});
    Group& g = out[it->second];
    g.bodies.push_back(Ellipsoid::from_matrix(k.e));
    g.expected.push_back(k.expected);
    g.names.push_back(k.name);
  }
  if (!mapped) return out;
  for (Group& g : out) {  // one congruence for the whole scene: positions are kept
    const AffineMap m = random_map(rng, true);
    g.q = Quadric::from_map(g.q, m.l, m.t);
    for (Ellipsoid& e : g.bodies) e = Ellipsoid::from_matrix(Quadric::from_map(Quadric::of(e), m.l, m.t).matrix());
  }
  return out;
}

void check_scene(const Group& g, const SceneOptions& options) {
  const QuadricSceneResult r = classify_scene(g.q, g.bodies, options);
  REQUIRE(r.verdicts.size() == g.bodies.size());
  REQUIRE(r.counts.bodies == g.bodies.size());
  QuadricSceneResult::Counts recount;
  for (std::size_t i = 0; i < g.bodies.size(); ++i) {
    INFO(g.names[i] << " against a " << to_string(g.q.type()));
    const QuadricVerdict alone = decide_position(g.bodies[i], g.q);
    CHECK(r.verdicts[i].position == g.expected[i]);
    CHECK(r.verdicts[i].position == alone.position);
    CHECK(r.verdicts[i].rule == alone.rule);
    CHECK(r.verdicts[i].stage == alone.stage);
    CHECK(r.verdicts[i].type == g.q.type());
    recount.add(r.verdicts[i]);
  }
  CHECK(recount.positions == r.counts.positions);
  CHECK(recount.stages == r.counts.stages);
  CHECK(r.threads >= 1);
}

}  // namespace

TEST_CASE("a general scene gives every body its constructed position and decide_position's verdict") {
  std::mt19937_64 rng(announced_seed("test_general_scene", 36));
  std::size_t bodies = 0, types = 0;
  for (const bool mapped : {false, true}) {
    const std::vector<Group> groups = scenes(mapped, rng);
    for (const Group& g : groups) {
      SceneOptions one;
      one.threads = 1;
      check_scene(g, one);
      SceneOptions many;
      many.threads = 3;
      many.chunk = 1;  // bodies spread over the threads one at a time
      std::atomic<std::size_t> progress{0};
      many.progress = &progress;
      check_scene(g, many);
      CHECK(progress.load() == g.bodies.size());
      bodies += g.bodies.size();
    }
    types = groups.size();
  }
  CHECK(types >= 11);  // every type has a scene
  CHECK(bodies > 50);
}

TEST_CASE("a general scene of bodies read from doubles answers as the exact bodies") {
  // Balls of dyadic radii along the x axis against the hyperboloid x^2 + y^2 - z^2 <= 1 (its waist
  // is the unit circle): inside the waist, touching it from inside and outside, crossing, outside.
  const Quadric h = Quadric::hyperboloid_one_sheet({0, 0, 0}, {Rational(1), Rational(1), Rational(1)});
  const double cases[][2] = {{0, 0.5}, {0, 1}, {2, 1}, {1, 0.5}, {4, 1}};
  const QuadricPosition expected[] = {QuadricPosition::I, QuadricPosition::TI, QuadricPosition::TE, QuadricPosition::C,
                                      QuadricPosition::E};
  std::vector<Ellipsoid> from_doubles, exact;
  for (const auto& c : cases) {
    const double r2 = c[1] * c[1];
    const DoubleMatrix4 d{1, 0, 0, -c[0], 0, 1, 0, 0, 0, 0, 1, 0, -c[0], 0, 0, c[0] * c[0] - r2};
    from_doubles.push_back(Ellipsoid::from_doubles(d));
    exact.push_back(Ellipsoid::sphere({Rational(c[0]), Rational(0), Rational(0)}, Rational(c[1])));
  }
  const QuadricSceneResult a = classify_scene(h, from_doubles), b = classify_scene(h, exact);
  for (std::size_t i = 0; i < 5; ++i) {
    CHECK(a.verdicts[i].position == expected[i]);
    CHECK(b.verdicts[i].position == expected[i]);
  }
  CHECK(a.counts.count(QuadricPosition::TI) == 1);
  CHECK(classify_scene(h, std::vector<Ellipsoid>{}).verdicts.empty());
}
