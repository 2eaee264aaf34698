// The README's library example, built against an installed relpos (tests/package/check_package.sh).
#include <iostream>
#include <relpos/classify.hpp>

int main() {
  using namespace relpos;
  auto p = Paraboloid::standard({0, 0, 0}, parse_rational("1.2"), parse_rational("1.5"));
  auto e = Ellipsoid::sphere({0, parse_rational("0.5"), parse_rational("92281/129600")}, Rational(1, 4));
  Classification c = classify(e, p);
  std::cout << to_string(c.verdict.position) << "\n";
  return 0;
}
