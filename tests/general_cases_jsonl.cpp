// general_cases_jsonl [RANDOM] [SEED]: general pairs as JSON Lines for `relpos batch` (doc/testing.md,
// `cli_general`): every constructed pair of tests/support/general_cases.hpp as given and under a
// random congruence, the nudged tangencies, and RANDOM random pairs (general, axis-aligned,
// concentric, every type), each with the position it must get in "comment": {"expect": P}. The
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

void line(const Matrix4& e, const Matrix4& q, QuadricPosition expected, const std::string& source) {
  std::cout << "{\"id\":" << ++id << ",\"ellipsoid\":" << matrix_json(e) << ",\"quadric\":" << matrix_json(q)
            << ",\"comment\":{\"expect\":\"" << to_string(expected) << "\",\"source\":\"" << source << "\"}}\n";
}

}  // namespace

int main(int argc, char** argv) {
  const long random = argc > 1 ? std::atol(argv[1]) : 300;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0) : 36;
  std::mt19937_64 rng(seed);
  for (const GeneralCase& k : constructed_cases()) {
    line(k.e, k.q.matrix(), k.expected, k.name);
    const AffineMap m = random_map(rng, true);
    const Quadric qe = Quadric::from_map(Quadric::from_matrix(k.e), m.l, m.t);
    line(qe.matrix(), Quadric::from_map(k.q, m.l, m.t).matrix(), k.expected, k.name + " (mapped)");
  }
  for (const Nudged& k : nudged_tangencies()) line(k.e, k.q.matrix(), k.expected, k.name);
  GeneralPairs gen(seed);
  const Family families[] = {Family::General, Family::AxisAligned, Family::Concentric};
  for (long i = 0; i < random; ++i) {
    const Family f = families[i % 3];
    const QuadricType t =
        general::kAllQuadricTypes[static_cast<std::size_t>((i / 3) % general::kAllQuadricTypes.size())];
    const RandomPair p = gen.pair(f, t);
    const OracleAnswer o = oracle_position(p.e.matrix(), p.q.matrix(), t == QuadricType::Ellipsoid);
    // A tangency or EQ from random numbers is a coincidence the oracle reads within its tolerance:
    // such a pair is left out rather than trusted.
    if (contact_of(o.position) == Contact::Touching) continue;
    line(p.e.matrix(), p.q.matrix(), o.position, std::string("random ") + to_string(t));
  }
  return 0;
}
