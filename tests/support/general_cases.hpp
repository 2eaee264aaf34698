// General pairs of known position (doc/testing.md): for every type of quadric, balls placed by
// elementary geometry (a ball touching a hyperboloid's waist circle, a cone along a circle, a
// cylinder along a circle, a hyperbolic cylinder at two points, a ball around a cone's apex, ...),
// and the rational affine congruences, scalings and sign flips they are tested under.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "relpos/general_classify.hpp"

namespace relpos::testing {

inline Rational q_of(const char* s) { return parse_rational(s); }

/// The matrix of the ball |x - c|^2 <= r2 (r2 > 0 rational: the radius may be irrational).
inline Matrix4 ball(const Vector3& c, const Rational& r2) {
  Matrix4 m;
  Rational norm(0);
  for (int i = 0; i < 3; ++i) {
    m(i, i) = Rational(1);
    m(i, 3) = m(3, i) = -c[static_cast<std::size_t>(i)];
    norm += c[static_cast<std::size_t>(i)] * c[static_cast<std::size_t>(i)];
  }
  m(3, 3) = norm - r2;
  return m;
}

struct GeneralCase {
  std::string name;
  Matrix4 e;
  Quadric q;
  QuadricPosition expected;
  bool hard = false;  ///< the tangency (or the optimum of a crossing) is at the end of an interval
};

/// Every type, every position its geometry allows, known by construction.
inline std::vector<GeneralCase> constructed_cases() {
  using P = QuadricPosition;
  const Rational h(1, 2), one(1), zero(0);
  auto r = q_of;
  std::vector<GeneralCase> out;
  auto add = [&](std::string name, Matrix4 e, Quadric q, P p, bool hard = false) {
    out.push_back({std::move(name), std::move(e), std::move(q), p, hard});
  };
  // Ellipsoid.
  const Quadric unit = Quadric::sphere({0, 0, 0}, one);
  const Quadric prolate = Quadric::ellipsoid({0, 0, 0}, {one, one, Rational(2)});
  add("ellipsoid: balls apart", ball({0, 0, 0}, r("1/4")), Quadric::sphere({3, 0, 0}, one), P::E);
  add("ellipsoid: balls touching outside", ball({0, 0, 0}, one), Quadric::sphere({3, 0, 0}, Rational(2)), P::TE);
  add("ellipsoid: balls crossing", ball({0, 0, 0}, one), Quadric::sphere({1, 0, 0}, one), P::C);
  add("ellipsoid: ball inside", ball({0, 0, 0}, r("1/4")), unit, P::I);
  add("ellipsoid: ball inside touching", ball({h, 0, 0}, r("1/4")), unit, P::TI);
  add("ellipsoid: unit ball in a prolate spheroid along the equator", ball({0, 0, 0}, one), prolate, P::TI, true);
  add("ellipsoid: the second inside", ball({0, 0, 0}, one), Quadric::sphere({0, 0, 0}, h), P::O);
  add("ellipsoid: the second inside touching", ball({0, 0, 0}, one), Quadric::sphere({h, 0, 0}, h), P::TO);
  add("ellipsoid: a unit ball inside the prolate E along the equator", prolate.matrix(), unit, P::TO, true);
  add("ellipsoid: equal balls", ball({0, 0, 0}, one), unit, P::EQ);
  add("ellipsoid: equal ellipsoids",
      Quadric::ellipsoid({1, 2, 3}, {one, Rational(2), Rational(3)}, {1, 2, 3, 4}).matrix(),
      Quadric::ellipsoid({1, 2, 3}, {one, Rational(2), Rational(3)}, {1, 2, 3, 4}), P::EQ);
  add("ellipsoid: concentric crossing", Quadric::ellipsoid({0, 0, 0}, {one, Rational(2), Rational(3)}).matrix(),
      Quadric::ellipsoid({0, 0, 0}, {Rational(3), Rational(2), one}), P::C, true);
  // Hyperboloid of one sheet x^2 + y^2 - z^2 <= 1: the region around the axis.
  const Quadric h1 = Quadric::hyperboloid_one_sheet({0, 0, 0}, {one, one, one});
  add("hyperboloid 1: small ball at the centre", ball({0, 0, 0}, r("1/4")), h1, P::I);
  add("hyperboloid 1: unit ball on the waist circle", ball({0, 0, 0}, one), h1, P::TI, true);
  add("hyperboloid 1: ball on the axis touching along z = 1", ball({0, 0, 2}, Rational(3)), h1, P::TI, true);
  add("hyperboloid 1: big ball on the axis", ball({0, 0, 10}, Rational(25)), h1, P::I);
  add("hyperboloid 1: ball through the waist", ball({0, 0, 0}, Rational(4)), h1, P::C);
  add("hyperboloid 1: ball crossing at the end of the interval", ball({3, 0, 0}, Rational(4)), h1, P::C, true);
  add("hyperboloid 1: ball touching at two points outside", ball({3, 0, 0}, r("7/2")), h1, P::TE, true);
  add("hyperboloid 1: ball touching the waist outside", ball({r("3/2"), 0, 0}, r("1/4")), h1, P::TE);
  add("hyperboloid 1: ball outside", ball({5, 0, 0}, one), h1, P::E);
  // Hyperboloid of two sheets x^2 + y^2 - z^2 <= -1: the caps.
  const Quadric h2 = Quadric::hyperboloid_two_sheets({0, 0, 0}, {one, one, one});
  add("hyperboloid 2: ball in the cap", ball({0, 0, 3}, r("1/4")), h2, P::I);
  add("hyperboloid 2: ball in the cap at the vertex", ball({0, 0, r("3/2")}, r("1/4")), h2, P::TI);
  add("hyperboloid 2: ball in the cap along z = 2", ball({0, 0, 4}, Rational(7)), h2, P::TI, true);
  add("hyperboloid 2: ball between the caps", ball({0, 0, 0}, r("1/4")), h2, P::E);
  add("hyperboloid 2: ball touching both vertices", ball({0, 0, 0}, one), h2, P::TE, true);
  add("hyperboloid 2: ball touching one vertex", ball({0, 0, h}, r("1/4")), h2, P::TE);
  add("hyperboloid 2: ball through a vertex", ball({0, 0, 1}, r("1/4")), h2, P::C);
  // Cone x^2 + y^2 <= z^2.
  const Quadric cone = Quadric::cone({0, 0, 0}, one, one);
  add("cone: ball around the apex", ball({0, 0, 0}, one), cone, P::C);
  add("cone: ball in the nappe", ball({0, 0, 4}, one), cone, P::I);
  add("cone: ball in the nappe along a circle", ball({0, 0, 2}, Rational(2)), cone, P::TI, true);
  add("cone: ball in the nappe touching a generator", ball({h, 0, 2}, r("9/8")), cone, P::TI);
  add("cone: ball outside", ball({4, 0, 0}, one), cone, P::E);
  add("cone: ball outside touching both nappes", ball({4, 0, 0}, Rational(8)), cone, P::TE, true);
  add("cone: ball outside touching one generator", ball({4, 0, 2}, Rational(2)), cone, P::TE);
  // Elliptic paraboloid z >= x^2 + y^2.
  const Quadric ep = Quadric::elliptic_paraboloid({0, 0, 0}, one, one);
  add("elliptic paraboloid: ball resting at the vertex", ball({0, 0, r("1/4")}, r("1/16")), ep, P::TI);
  add("elliptic paraboloid: ball resting on a circle", ball({0, 0, 1}, r("3/4")), ep, P::TI, true);
  add("elliptic paraboloid: ball in the cup", ball({0, 0, 2}, r("1/16")), ep, P::I);
  add("elliptic paraboloid: ball at the vertex", ball({0, 0, 0}, r("1/4")), ep, P::C);
  add("elliptic paraboloid: ball below touching", ball({0, 0, -1}, one), ep, P::TE);
  add("elliptic paraboloid: ball below", ball({0, 0, -2}, one), ep, P::E);
  // Hyperbolic paraboloid z >= x^2 - y^2 (the sign as given).
  const Quadric hp = Quadric::hyperbolic_paraboloid({0, 0, 0}, one, one);
  add("hyperbolic paraboloid: ball above", ball({0, 0, 5}, one), hp, P::I);
  add("hyperbolic paraboloid: ball on the saddle from above", ball({0, 0, r("1/4")}, r("1/16")), hp, P::TI);
  add("hyperbolic paraboloid: ball at the saddle", ball({0, 0, 0}, one), hp, P::C);
  add("hyperbolic paraboloid: ball on the saddle from below", ball({0, 0, r("-1/4")}, r("1/16")), hp, P::TE);
  add("hyperbolic paraboloid: ball below", ball({0, 0, -5}, one), hp, P::E);
  // Elliptic cylinder x^2 + y^2 <= 1.
  const Quadric ec = Quadric::elliptic_cylinder({0, 0, 0}, one, one);
  add("elliptic cylinder: ball inside", ball({0, 0, 0}, r("1/4")), ec, P::I);
  add("elliptic cylinder: unit ball along a circle", ball({0, 0, 0}, one), ec, P::TI, true);
  add("elliptic cylinder: ball around the axis", ball({0, 0, 0}, Rational(4)), ec, P::C, true);
  add("elliptic cylinder: ball through the wall", ball({1, 0, 0}, r("1/4")), ec, P::C);
  add("elliptic cylinder: ball touching outside", ball({r("3/2"), 0, 0}, r("1/4")), ec, P::TE);
  add("elliptic cylinder: ball outside", ball({3, 0, 0}, one), ec, P::E);
  // Hyperbolic cylinder x^2 - y^2 <= 1: the connected middle.
  const Quadric hc = Quadric::hyperbolic_cylinder({0, 0, 0}, one, one);
  add("hyperbolic cylinder: ball in the middle", ball({0, 0, 0}, r("1/4")), hc, P::I);
  add("hyperbolic cylinder: unit ball at two points", ball({0, 0, 0}, one), hc, P::TI, true);
  add("hyperbolic cylinder: big ball", ball({0, 0, 0}, Rational(4)), hc, P::C);
  add("hyperbolic cylinder: ball touching a sheet outside", ball({r("3/2"), 0, 0}, r("1/4")), hc, P::TE);
  add("hyperbolic cylinder: ball outside", ball({5, 0, 0}, one), hc, P::E);
  // Parabolic cylinder z >= x^2.
  const Quadric pc = Quadric::parabolic_cylinder({0, 0, 0}, one);
  add("parabolic cylinder: ball inside", ball({0, 0, 3}, r("1/4")), pc, P::I);
  add("parabolic cylinder: ball resting at the bottom", ball({0, 0, r("1/4")}, r("1/16")), pc, P::TI);
  add("parabolic cylinder: ball resting at two points", ball({0, 0, 1}, r("3/4")), pc, P::TI, true);
  add("parabolic cylinder: ball through the bottom", ball({0, 0, 0}, r("1/4")), pc, P::C);
  add("parabolic cylinder: ball below touching", ball({0, 0, -1}, one), pc, P::TE);
  add("parabolic cylinder: ball below", ball({0, 0, -3}, one), pc, P::E);
  // Slab -1 <= z <= 1.
  const Quadric slab = Quadric::slab({0, 0, 1}, Rational(-1), one);
  add("slab: ball inside", ball({0, 0, 0}, r("1/4")), slab, P::I);
  add("slab: ball touching one plane inside", ball({0, 0, h}, r("1/4")), slab, P::TI);
  add("slab: ball touching both planes", ball({0, 0, 0}, one), slab, P::TI, true);
  add("slab: ball through a plane", ball({0, 0, 1}, r("1/4")), slab, P::C);
  add("slab: ball touching a plane outside", ball({0, 0, r("3/2")}, r("1/4")), slab, P::TE);
  add("slab: ball outside", ball({0, 0, 3}, one), slab, P::E);
  // Half-space z <= 1.
  const Quadric half = Quadric::half_space({0, 0, 1}, one);
  add("half-space: ball inside", ball({0, 0, 0}, r("1/4")), half, P::I);
  add("half-space: ball touching inside", ball({0, 0, 0}, one), half, P::TI);
  add("half-space: ball cut", ball({0, 0, 1}, r("1/4")), half, P::C);
  add("half-space: ball touching outside", ball({0, 0, 2}, one), half, P::TE);
  add("half-space: ball outside", ball({0, 0, 3}, one), half, P::E);
  return out;
}

/// Whether negating Q's matrix swaps its solid with the complement (the types with a tie in the
/// signs of B's eigenvalues, math.md §14).
inline bool sign_as_given(QuadricType t) {
  return t == QuadricType::HyperbolicParaboloid || t == QuadricType::HyperbolicCylinder || t == QuadricType::HalfSpace;
}

/// The position of E against the complement's closure, {q >= 0}: I <-> E, TI <-> TE, C stays.
inline QuadricPosition mirrored(QuadricPosition p) {
  switch (p) {
    case QuadricPosition::I:
      return QuadricPosition::E;
    case QuadricPosition::E:
      return QuadricPosition::I;
    case QuadricPosition::TI:
      return QuadricPosition::TE;
    case QuadricPosition::TE:
      return QuadricPosition::TI;
    default:
      return p;
  }
}

/// A random rational affine map x = L u + t: a rotation from an integer quaternion, positive
/// scalings along the axes, a shear, an optional reflection, and a translation.
struct AffineMap {
  Matrix3 l;
  Vector3 t;
};

inline AffineMap random_map(std::mt19937_64& rng, bool shear) {
  std::uniform_int_distribution<int> qd(-4, 4), sd(1, 8), td(-40, 40);
  Quaternion q;
  do {
    for (Rational& x : q) x = Rational(qd(rng));
  } while (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0);
  const Matrix3 rot = rotation_from_quaternion(q);
  Matrix3 s;
  for (int i = 0; i < 3; ++i) s(i, i) = Rational(sd(rng), sd(rng));
  if (rng() % 2) s(0, 0) = -s(0, 0);  // a reflection
  if (shear) s(0, 1) = Rational(qd(rng), 3);
  AffineMap m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational acc(0);
      for (int k = 0; k < 3; ++k) acc += rot(i, k) * s(k, j);
      m.l(i, j) = acc;
    }
  for (Rational& x : m.t) x = Rational(td(rng), 8);
  return m;
}

inline Matrix4 scaled_matrix(const Matrix4& m, const Rational& s) {
  Matrix4 out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = m.a[i] * s;
  return out;
}

}  // namespace relpos::testing
