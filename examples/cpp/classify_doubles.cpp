// Classify pairs given as doubles: each double is taken as the exact number it stores, so a tangency
// written in doubles is decided as a tangency (by the fast filters when they can certify it).
#include <iostream>
#include <relpos/classify.hpp>

int main() {
  using namespace relpos;
  auto p = Paraboloid::standard({0.0, 0.0, 0.0}, 1.0, 2.0);  // z = x^2 + y^2/4
  // Spheres of radius 0.25 on the axis, centre at height z: the vertex is at distance |z|.
  for (double z : {-0.5, -0.25, 0.0, 0.25, 1.0}) {
    Verdict v = decide_position(Ellipsoid::sphere({0.0, 0.0, z}, 0.25), p);  // the allocation-free path
    std::cout << "z = " << z << ": " << to_string(v.position) << "\n";
  }
}
// Output:
// z = -0.5: E
// z = -0.25: TE
// z = 0: C
// z = 0.25: TI
// z = 1: I
