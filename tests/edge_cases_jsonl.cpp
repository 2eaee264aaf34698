// Writes pairs of support/edge_cases.hpp as JSON Lines for the CLI check (tests/cli/check_edges.sh):
// each line {"id": "POS-family-n", "ellipsoid": {"matrix": ...}, "paraboloid": {"matrix": ...}} with
// exact "p/q" entries, the position known by construction in the id's prefix.
#include <iostream>
#include <relpos/numbers.hpp>
#include <string>
#include <vector>

#include "support/edge_cases.hpp"

namespace {

using namespace rt;
using namespace rt::edges;

std::string matrix_json(const Matrix4& m) {
  std::string out = "{\"matrix\": [";
  for (int i = 0; i < 4; ++i) {
    out += i ? ", [" : "[";
    for (int j = 0; j < 4; ++j) out += (j ? ", \"" : "\"") + relpos::to_string(m(i, j)) + "\"";
    out += "]";
  }
  return out + "]}";
}

std::string slug(std::string s) {
  for (char& ch : s)
    if (!(std::isalnum(static_cast<unsigned char>(ch)))) ch = '_';
  return s;
}

}  // namespace

int main() {
  Rng g(2110);
  std::vector<EdgeCase> cases;
  for (const EdgeCase& c : spheres_near_contact(g)) {
    cases.push_back(c);
    cases.push_back(similar(g, c, pow10(-30), pow10(-30), "scaled by 1e-30"));
    cases.push_back(affine(g, c, pow10(30), pow10(30), "affine, scaled by 1e30"));
  }
  for (const EdgeCase& c : ellipsoids_near_contact(g, {pow10(-4), Q(1), pow10(3)}, pow10(-3), pow10(3)))
    cases.push_back(similar(g, c, Q(1), pow10(15), "translated by 1e15"));
  for (int k = 15; k <= 40; k += 5)
    for (const EdgeCase& c : tiny_on_surface(g, k)) cases.push_back(c);
  for (const Rational& eps : {pow10(-5), pow10(-20), pow10(-40), pow10(-80)})
    for (const EdgeCase& c : sphere_in_cup(eps)) cases.push_back(similar(g, c, pow10(-3), pow10(6), "moved"));
  int n = 0;
  for (const EdgeCase& c : cases)
    std::cout << "{\"id\": \"" << relpos::to_string(c.expected) << "-" << slug(c.family) << "-" << ++n
              << "\", \"ellipsoid\": " << matrix_json(c.e) << ", \"paraboloid\": " << matrix_json(c.p) << "}\n";
}
