// Many ellipsoids against one paraboloid, on all cores: the paraboloid is prepared once, and bodies
// certified strictly inside or outside skip the exact stages (math.md §13).
#include <iostream>
#include <relpos/scene.hpp>
#include <vector>

int main() {
  using namespace relpos;
  auto p = Paraboloid::standard({0, 0, 0}, Rational(1), Rational(1));  // z = x^2 + y^2
  std::vector<Ellipsoid> bodies;
  // A column of spheres of radius 1/8 on the axis, centres from z = -1 to z = 1 in steps of 1/8.
  for (int k = -8; k <= 8; ++k) bodies.push_back(Ellipsoid::sphere({0, 0, Rational(k, 8)}, Rational(1, 8)));
  SceneResult r = classify_scene(p, bodies);
  for (std::size_t i = 0; i < bodies.size(); ++i) std::cout << (i ? " " : "") << to_string(r.verdicts[i].position);
  std::cout << "\n";
  for (Position pos : kAllPositions) std::cout << to_string(pos) << ": " << r.counts.count(pos) << "\n";
}
// Output:
// E E E E E E E TE C TI I I I I I I I
// I: 7
// TI: 1
// C: 1
// TE: 1
// E: 7
