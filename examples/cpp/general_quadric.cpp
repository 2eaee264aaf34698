// An ellipsoid against any real quadric (doc/quadrics.md): the position, the rule that decided it and
// a certificate that exact rational arithmetic alone checks.
#include <iostream>
#include <relpos/general_classify.hpp>

int main() {
  using namespace relpos;
  // The hyperboloid x^2 + y^2 - z^2 <= 1 (the region around its axis) and the unit ball, which
  // touches it along the waist circle: a tangency at the end of the multipliers' interval.
  const Quadric h = Quadric::hyperboloid_one_sheet({0, 0, 0}, {Rational(1), Rational(1), Rational(1)});
  const Ellipsoid ball = Ellipsoid::sphere({0, 0, 0}, Rational(1));
  const QuadricClassification c = classify(ball, h);
  std::cout << to_string(c.verdict.type) << ": " << to_string(c.verdict.position) << "\n";
  std::cout << describe(c.verdict.rule) << "\n";
  std::cout << "contact set: " << c.certificate.directions.size() << " directions, radius2 "
            << to_string(c.certificate.radius2.a) << "\n";
  const std::optional<std::string> problem = verify_certificate(ball, h, c.verdict.position, c.certificate);
  std::cout << (problem ? *problem : "certificate verified") << "\n";

  // Two ellipsoids: the second inside the first (O), decided by the certified filter.
  const Quadric inner = Quadric::ellipsoid({Rational(1, 4), Rational(1, 5), Rational(1, 7)},
                                           {Rational(1, 2), Rational(1, 3), Rational(1, 4)}, {1, 2, 3, 4});
  const QuadricVerdict v = decide_position(Ellipsoid::sphere({0, 0, 0}, Rational(1)), inner);
  std::cout << to_string(v.position) << " (" << to_string(v.stage) << ")\n";
}
// Output:
// hyperboloid of one sheet: TI
// f~ vanishes at t_hi: max q = 0, a tangency in the hard case
// contact set: 2 directions, radius2 1
// certificate verified
// O (filter)
