// general_cases_jsonl [RANDOM] [SEED] [MAPS]: general pairs as JSON Lines for `relpos batch`
// (doc/testing.md, `cli_general`): every constructed pair of tests/support/general_cases.hpp as given
// and under a random congruence, the nudged tangencies, and RANDOM random pairs (general,
// axis-aligned, concentric, every type), each with the position it must get in "comment": {"expect": P}.
// MAPS > 1 (the self-check at scale, doc/testing.md) adds MAPS - 1 more images of every constructed
// pair, each matrix also scaled by a random rational of either sign. The
// constructed positions come from their construction, the random ones from the trust-region oracle
// (tests/support/trs_oracle.hpp), which shares no code with the classifier; a random pair whose
// optima the oracle cannot tell from 0 is not written.
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include "general/decision.hpp"
#include "support/general_random.hpp"
#include "support/trs_oracle.hpp"

using namespace relpos;
using namespace relpos::testing;

namespace {

std::string matrix_json(const Matrix4& m) {
  std::string s = "[";
  for (int i = 0; i < 4; ++i) {
    s += i ? ",[" : "[";
    for (int j = 0; j < 4; ++j) s += (j ? ",\"" : "\"") + to_string(m(i, j)) + "\"";
    s += "]";
  }
  return s + "]";
}

long id = 0;

Rational power_of_ten(int k) {
  Rational r(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) r *= 10;
  return k < 0 ? 1 / r : r;
}

void line(const Matrix4& e, const Matrix4& q, QuadricPosition expected, const std::string& source) {
  std::cout << "{\"id\":" << ++id << ",\"ellipsoid\":" << matrix_json(e) << ",\"quadric\":" << matrix_json(q)
            << ",\"comment\":{\"expect\":\"" << to_string(expected) << "\",\"source\":\"" << source << "\"}}\n";
}

}  // namespace

int main(int argc, char** argv) {
  const long random = argc > 1 ? std::atol(argv[1]) : 300;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0) : 36;
  const long maps = argc > 3 ? std::atol(argv[3]) : 1;
  std::mt19937_64 rng(seed);
  for (const GeneralCase& k : constructed_cases()) {
    line(k.e, k.q.matrix(), k.expected, k.name);
    const AffineMap m = random_map(rng, true);
    const Quadric qe = Quadric::from_map(Quadric::from_matrix(k.e), m.l, m.t);
    line(qe.matrix(), Quadric::from_map(k.q, m.l, m.t).matrix(), k.expected, k.name + " (mapped)");
  }
  // The further images draw from their own generator: the lines above stay those of cli_general.
  std::mt19937_64 more(seed + 1);
  std::uniform_int_distribution<int> sd(1, 9), exponent(-40, 40);
  for (long round = 1; round < maps; ++round)
    for (const GeneralCase& k : constructed_cases()) {
      const AffineMap m = random_map(more, round % 2 == 0);
      const Quadric qe = Quadric::from_map(Quadric::from_matrix(k.e), m.l, m.t);
      const Quadric qq = Quadric::from_map(k.q, m.l, m.t);
      // A scale of either sign for each matrix, now and then far from 1: negating Q swaps its solid
      // with the complement's closure where its type keeps the sign as given (math.md §14).
      Rational se(sd(more), sd(more)), sq(sd(more), sd(more));
      if (round % 3 == 0) se *= power_of_ten(exponent(more)), sq *= power_of_ten(exponent(more));
      const bool flip_e = more() % 2 != 0, flip_q = more() % 2 != 0;
      if (flip_e) se = -se;
      if (flip_q) sq = -sq;
      const QuadricPosition expected = flip_q && sign_as_given(k.q.type()) ? mirrored(k.expected) : k.expected;
      line(scaled_matrix(qe.matrix(), se), scaled_matrix(qq.matrix(), sq), expected,
           k.name + " (mapped, scaled, round " + std::to_string(round) + ")");
    }
  for (const Nudged& k : nudged_tangencies()) line(k.e, k.q.matrix(), k.expected, k.name);
  GeneralPairs gen(seed);
  const Family families[] = {Family::General, Family::AxisAligned, Family::Concentric};
  for (long i = 0; i < random; ++i) {
    const Family f = families[i % 3];
    const QuadricType t =
        detail::general::kAllQuadricTypes[static_cast<std::size_t>((i / 3) % detail::general::kAllQuadricTypes.size())];
    const RandomPair p = gen.pair(f, t);
    const OracleAnswer o = oracle_position(p.e.matrix(), p.q.matrix(), t == QuadricType::Ellipsoid);
    // A tangency or EQ from random numbers is a coincidence the oracle reads within its tolerance:
    // such a pair is left out rather than trusted.
    if (contact_of(o.position) == Contact::Touching) continue;
    line(p.e.matrix(), p.q.matrix(), o.position, std::string("random ") + to_string(t));
  }
  return 0;
}
