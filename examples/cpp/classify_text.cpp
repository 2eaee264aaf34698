// Classify a pair given as exact text: decimals and fractions are read exactly, never rounded.
#include <iostream>
#include <relpos/classify.hpp>

int main() {
  using namespace relpos;
  // z = x^2/1.2^2 + y^2/1.5^2, and a sphere of radius 1/4 just inside it.
  auto p = Paraboloid::standard({0, 0, 0}, parse_rational("1.2"), parse_rational("1.5"));
  auto e = Ellipsoid::sphere({0, parse_rational("0.5"), parse_rational("92281/129600")}, Rational(1, 4));
  Classification c = classify(e, p);
  std::cout << to_string(c.verdict.position) << "\n";  // I
  std::cout << "small: " << (c.verdict.small ? "yes" : "no") << ", rho = " << to_string(*c.rho) << "\n";
  std::cout << "Disc(f) = 0 (f has a multiple root): " << (c.verdict.sign_disc_f == 0 ? "yes" : "no") << "\n";
}
// Output:
// I
// small: yes, rho = 625/5184
// Disc(f) = 0 (f has a multiple root): yes
