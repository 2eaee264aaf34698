// The crossing certificate's assembly (src/certificate/crossing.cpp) called directly: bodies centred
// on the paraboloid's surface cross it by construction, at every scale (radii from 10^-30 to 10^3,
// where doubles around the centre cannot resolve the body and the search runs in its frame, far from
// the origin or near it), as spheres and rotated ellipsoids, from rationals, doubles and decimal text;
// both points returned are checked here, exactly and independently of the library: in the solid
// ellipsoid, one on each side of the paraboloid.
#include <catch2/catch.hpp>
#include <relpos/position.hpp>
#include <string>
#include <vector>

#include "certificate/kinds.hpp"
#include "io/fast_quadric.hpp"
#include "pair/pair.hpp"
#include "support/construct.hpp"
#include "support/seed.hpp"

using relpos::Certificate;
using relpos::Ellipsoid;
using relpos::Matrix4;
using relpos::Paraboloid;
using relpos::Rational;
using rt::form_value;
using rt::Q;

namespace {

void check_crossing(const Ellipsoid& e, const Paraboloid& p) {
  const relpos::detail::PairContext pair(e, p);
  Certificate c;
  relpos::detail::certificate::crossing_points(pair, c);
  CHECK(c.kind == Certificate::Kind::Crossing);
  CHECK(form_value(e.matrix(), c.inside) <= 0);
  CHECK(form_value(p.matrix(), c.inside) < 0);
  CHECK(form_value(e.matrix(), c.outside) <= 0);
  CHECK(form_value(p.matrix(), c.outside) > 0);
  CHECK_FALSE(relpos::verify_certificate(e, p, relpos::Position::C, c));
}

/// 10^k exactly.
Rational ten_to(int k) {
  Rational out(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) out *= 10;
  return k < 0 ? 1 / out : out;
}

}  // namespace

TEST_CASE("crossing_points: spheres and ellipsoids centred on the surface, radii 10^-30 to 10^3", "[crossing]") {
  rt::Rng g(relpos::testing::announced_seed("test_crossing", 20260304));
  for (int t = 0; t < 24; ++t) {
    const Rational a = g.positive_rational(9, 4), b = g.positive_rational(9, 4);
    const Rational x0 = g.rational(-6, 6, 5) * ten_to(int(g.uniform(-3, 6))), y0 = g.rational(-6, 6, 7);
    const rt::Vector3 c{x0, y0, x0 * x0 / (a * a) + y0 * y0 / (b * b)};  // on z = x^2/a^2 + y^2/b^2
    const Rational r = ten_to(int(g.uniform(-30, 3)));
    INFO("a=" << relpos::to_string(a) << " b=" << relpos::to_string(b) << " c=(" << relpos::to_string(c[0]) << ", "
              << relpos::to_string(c[1]) << ") r=" << relpos::to_string(r));
    const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, a, b);
    check_crossing(Ellipsoid::sphere(c, r), p);
    const relpos::Quaternion q = rt::random_quaternion(g);
    check_crossing(Ellipsoid::from_axes(c, {r, r * Q(g.uniform(1, 9), 4), r * Q(g.uniform(1, 9), 7)}, q), p);
  }
}

TEST_CASE("crossing_points: pairs of doubles and of decimal text", "[crossing]") {
  for (int k = -40; k <= 10; k += 5) {
    const double r = std::ldexp(1.0, k), x = 0.75;
    INFO("r = 2^" << k);
    // On z = x^2 + y^2 at (0.75, 0, 0.5625): every number a double.
    check_crossing(Ellipsoid::sphere(std::array<double, 3>{x, 0, x * x}, r),
                   Paraboloid::standard(std::array<double, 3>{0, 0, 0}, 1.0, 1.0));
  }
  for (const char* es :
       {R"({"sphere":{"center":[1.2,0,1],"radius":0.5}})", R"({"sphere":{"center":[0.6,0.75,0.5],"radius":1e-9}})",
        R"({"sphere":{"center":[0,0,0],"radius":3}})"})
    check_crossing(*relpos::detail::io::fast_ellipsoid(es, false),
                   *relpos::detail::io::fast_paraboloid(R"({"vertex":[0,0,0],"a":1.2,"b":1.5})", false));
}
