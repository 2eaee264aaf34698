// A sphere moving up the axis of a paraboloid: its first contact, an exact algebraic instant, and
// every change of position on the way (math.md §7).
#include <iostream>
#include <relpos/motion.hpp>

int main() {
  using namespace relpos;
  auto p = Paraboloid::standard({0, 0, 0}, Rational(1), Rational(2));
  auto e0 = Ellipsoid::sphere({0, 0, 0}, Rational(1, 4));
  // Centre at (0, 0, t^2 - 9/4): it reaches the vertex from below (height -1/4) at t = sqrt(2).
  RigidMotion m = RigidMotion::translating({TimePolynomial{}, TimePolynomial{}, {Rational(-9, 4), 0, 1}});
  FirstContact fc = first_contact(e0, m, p, Rational(0), Rational(2));
  std::cout << "first contact at t = " << fc.time->decimals(12) << " (root of "
            << polynomial_text(fc.time->polynomial()) << "): " << to_string(fc.position) << "\n";
  for (const PositionSpan& s : timeline(e0, m, p, Rational(0), Rational(2)).spans())
    std::cout << (s.from_closed ? "[" : "(") << s.from.decimals(6) << ", " << s.to.decimals(6)
              << (s.to_closed ? "]" : ")") << ": " << to_string(s.position) << "\n";
}
// Output:
// first contact at t = 1.41421356237 (root of t^2 - 2): TE
// [0, 1.41421): E
// [1.41421, 1.41421]: TE
// (1.41421, 1.58114): C
// [1.58114, 1.58114]: TI
// (1.58114, 2]: I
