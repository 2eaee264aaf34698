#include <iostream>

#include "relpos/classify.hpp"

using namespace relpos;

int main() {
  // Paper Remark example: P: x^2/1.2^2 + y^2/1.5^2 = z, sphere centre (0, 0.5, 92281/129600), r = 1/4.
  auto p = Paraboloid::standard({Rational(0), Rational(0), Rational(0)}, parse_rational("1.2"), parse_rational("1.5"));
  auto e = Ellipsoid::sphere({Rational(0), parse_rational("0.5"), parse_rational("92281/129600")}, Rational(1, 4));
  auto c = classify(e, p);
  std::cout << to_string(c.position) << " " << c.rule << " stage=" << to_string(c.stage) << " rho~" << c.rho_approx << "\n";
  for (auto& r : c.roots) std::cout << "  root sign " << r.sign << " mf=" << r.multiplicity_f << " ms=" << r.multiplicity_s << (r.exact ? " = " + to_string(*r.exact) : "") << "\n";
  auto run = [&](Rational xc, Rational zc, Rational a, Rational b, Rational r) {
    auto pp = Paraboloid::standard({Rational(0), Rational(0), Rational(0)}, a, b);
    auto ee = Ellipsoid::sphere({xc, Rational(0), zc}, r);
    auto cc = classify(ee, pp);
    auto cx = classify_exact(ee, pp);
    std::cout << to_string(cc.position) << "/" << to_string(cx.position) << " " << cc.rule << " stage=" << to_string(cc.stage) << " disc=" << cc.sign_disc_f << "\n";
  };
  run(Rational(1), Rational(131, 192), Rational(1), Rational(2), Rational(1, 4));   // C with Disc = 0
  run(Rational(6, 5), Rational(857, 1600), Rational(1), Rational(2), Rational(1, 4));  // E with Disc = 0
  run(Rational(0), Rational(1), Rational(1), Rational(2), Rational(1, 4));   // I on axis
  run(Rational(0), Rational(1, 4), Rational(1), Rational(2), Rational(1, 4));   // TI at vertex
  run(Rational(0), Rational(-1, 4), Rational(1), Rational(2), Rational(1, 4));   // TE at vertex
  run(Rational(0), Rational(0), Rational(1), Rational(2), Rational(1, 4));   // C
  run(Rational(3), Rational(0), Rational(1), Rational(2), Rational(1, 4));   // E
  run(Rational(0), Rational(1, 2), Rational(1), Rational(1), Rational(1, 2));   // circular, 2r = a^2, mult 4 -> TI
  run(Rational(0), Rational(3), Rational(1), Rational(1), Rational(2));   // not small
}
