// Random general pairs (tests/support/general_random.hpp): the filtered decision equals the exact one
// on every pair, the trust-region oracle agrees, certificates verify; tangencies built by hand and
// nudged by 10^-6 ... 10^-35 get the position their construction gives; matrices scaled by 10^300
// and 10^-300 get the answer of the unscaled pair.
#include <catch2/catch.hpp>
#include <map>
#include <random>
#include <string>

#include "general/decision.hpp"
#include "relpos/general_classify.hpp"
#include "support/general_random.hpp"
#include "support/scale.hpp"
#include "support/seed.hpp"
#include "support/trs_oracle.hpp"

using namespace relpos;
using namespace relpos::testing;

namespace {

const char* family_name(Family f) {
  return f == Family::General ? "general" : (f == Family::AxisAligned ? "axis-aligned" : "concentric");
}

}  // namespace

TEST_CASE("random general pairs: filter == exact on every pair, the oracle agrees, certificates verify", "[general]") {
  GeneralPairs gen(announced_seed("random general pairs", 36));
  std::map<std::string, int> positions, filtered, total;
  int checked_by_oracle = 0, certificates = 0;
  for (int round = 0; round < 40 / kSanitizerShare; ++round)
    for (Family f : {Family::General, Family::AxisAligned, Family::Concentric})
      for (QuadricType t : detail::general::kAllQuadricTypes) {
        const RandomPair p = gen.pair(f, t);
        const QuadricVerdict v = decide_position(p.e, p.q), x = decide_position_exact(p.e, p.q);
        INFO(family_name(f) << " " << to_string(t) << " round " << round);
        REQUIRE(to_string(v.position) == to_string(x.position));
        ++positions[to_string(t) + " " + to_string(x.position)];
        ++total[family_name(f)];
        if (v.stage == QuadricStage::Filter) ++filtered[family_name(f)];
        if (round % 2 == 0) {
          const OracleAnswer o = oracle_position(p.e.matrix(), p.q.matrix(), t == QuadricType::Ellipsoid);
          CHECK(to_string(o.position) == to_string(x.position));
          ++checked_by_oracle;
        }
        if (round % 4 == 0) {
          const QuadricClassification c = classify(p.e, p.q);
          CHECK(c.verdict.position == x.position);
          CHECK(verify_certificate(p.e, p.q, c.verdict.position, c.certificate).value_or("verified") == "verified");
          ++certificates;
        }
      }
  for (const auto& [name, n] : total) {
    INFO(name << ": " << filtered[name] << " of " << n << " decided by the filter");
    // The filter settles general and axis-aligned pairs; a concentric pair's f shares the roots of D.
    if (name != "concentric") CHECK(filtered[name] >= n * 9 / 10);
  }
  CHECK(checked_by_oracle == (40 / kSanitizerShare + 1) / 2 * 3 * 11);
  CHECK(certificates == (40 / kSanitizerShare + 3) / 4 * 3 * 11);
  // Every position of the random families occurs for the ellipsoid (O among concentric pairs).
  for (const char* p : {"E", "C", "I", "O"}) CHECK(positions[std::string("ellipsoid ") + p] > 0);
}

TEST_CASE("nudged tangencies: the position their construction gives, down to 1e-35", "[general]") {
  std::mt19937_64 rng(announced_seed("nudged tangencies", 35));
  int n = 0;
  for (const Nudged& k : nudged_tangencies()) {
    if (n++ % kSanitizerShare != 0) continue;
    INFO(k.name);
    const AffineMap m = random_map(rng, false);
    const Quadric qe = Quadric::from_map(Quadric::from_matrix(k.e), m.l, m.t);
    const Ellipsoid e = Ellipsoid::from_matrix(qe.matrix());
    const Quadric q = Quadric::from_map(k.q, m.l, m.t);
    CHECK(to_string(decide_position(e, q).position) == to_string(k.expected));
    const QuadricClassification c = classify(e, q);
    CHECK(to_string(c.verdict.position) == to_string(k.expected));
    CHECK(verify_certificate(e, q, c.verdict.position, c.certificate).value_or("verified") == "verified");
    CHECK(to_string(oracle_position(e.matrix(), q.matrix(), q.type() == QuadricType::Ellipsoid).position) ==
          to_string(k.expected));
  }
  CHECK(n == 264);
}

TEST_CASE("matrices scaled by 10^300 and 10^-300 get the unscaled pair's answer and certificate", "[general]") {
  GeneralPairs gen(announced_seed("scaled pairs", 300));
  Rational big(1);
  for (int i = 0; i < 300; ++i) big *= 10;
  for (QuadricType t : detail::general::kAllQuadricTypes)
    for (int i = 0; i < 5; ++i) {
      const RandomPair p = gen.pair(Family::General, t);
      const Ellipsoid e = Ellipsoid::from_matrix(scaled_matrix(p.e.matrix(), big));
      const Quadric q = Quadric::from_matrix(scaled_matrix(p.q.matrix(), Rational(1) / big));
      const QuadricVerdict v = decide_position(p.e, p.q), w = decide_position(e, q);
      CHECK(v.position == w.position);
      CHECK(v.stage == w.stage);
      const QuadricClassification c = classify(e, q);
      CHECK(verify_certificate(e, q, c.verdict.position, c.certificate).value_or("verified") == "verified");
    }
}
