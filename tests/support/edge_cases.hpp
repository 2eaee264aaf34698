// Pairs at the edges of scale and nearness whose position is known by construction (no classifier
// involved): bodies centred on the surface, touching it at a rational point of rational normal, or
// pushed across or away from it by a distance down to 1e-100; then moved by exact similarities
// (rotations from integer quaternions, scales 1e-30 ... 1e30, translations up to 1e30) and general
// affine congruences, which keep every position (they map both solids and surfaces bijectively).
//
// Why each position holds, in the frame of the cup z = x^2/a^2 + y^2/b^2 (n the outward normal at a
// point x0 of the surface, n^ = n / |n| rational by tangent_point):
// - a body whose interior contains x0 (centred on the surface, or grown past x0): C;
// - a body on the outer side of the tangent plane at x0: E, touching the plane at x0 only: TE (the
//   cup is strictly convex and lies on the inner side); an ellipsoid (x - c)^T M (x - c) <= R^2 with
//   c = x0 + tau M^-1 n reaches down to n.(x - x0) = tau q - R sqrt(q), q = n^T M^-1 n, so
//   R^2 = tau^2 q touches, less separates, more contains x0;
// - a sphere of radius d <= min(a, b)^2 / 2 (the least radius of curvature of the cup) centred at
//   x0 - d n^ lies in the solid cup and touches it at x0 only (Blaschke's rolling theorem): TI;
//   a smaller radius there: I; a larger one: C.
#pragma once

#include <string>
#include <vector>

#include "construct.hpp"

namespace rt::edges {

struct EdgeCase {
  std::string family;
  Matrix4 e, p;
  Position expected;
};

inline Rational pow10(int k) {
  Rational r(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) r *= 10;
  return k < 0 ? Rational(1) / r : r;
}

inline Rational pow2(int k) {
  Rational r(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) r *= 2;
  return k < 0 ? Rational(1) / r : r;
}

inline Vector3 apply(const Matrix3& m, const Vector3& v) {
  Vector3 out;
  for (int i = 0; i < 3; ++i) {
    Rational s(0);
    for (int j = 0; j < 3; ++j) s += m(i, j) * v[static_cast<std::size_t>(j)];
    out[static_cast<std::size_t>(i)] = s;
  }
  return out;
}

/// (x - c)^T M (x - c) - r2.
inline Matrix4 ellipsoid_matrix(const Vector3& c, const Matrix3& m, const Rational& r2) {
  Matrix4 out;
  const Vector3 mc = apply(m, c);
  Rational k = -r2;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out(i, j) = m(i, j);
    set_sym(out, i, 3, -mc[static_cast<std::size_t>(i)]);
    k += c[static_cast<std::size_t>(i)] * mc[static_cast<std::size_t>(i)];
  }
  out(3, 3) = k;
  return out;
}

/// M = R^T diag(1/ax^2, 1/ay^2, 1/az^2) R and its inverse R^T diag(ax^2, ...) R (R orthogonal).
struct Shape {
  Matrix3 m, inverse;
};

inline Shape shape(const Vector3& axes, const Quaternion& q) {
  const Matrix3 r = rotation(q), rt = rotation({q[0], -q[1], -q[2], -q[3]});  // R^T: the conjugate's rotation
  const Rational &x = axes[0], &y = axes[1], &z = axes[2];
  return {mul(rt, mul(diag3(1 / (x * x), 1 / (y * y), 1 / (z * z)), r)), mul(rt, mul(diag3(x * x, y * y, z * z), r))};
}

/// The pair moved by x = s R u + t: Q -> H^T Q H (both quadrics, so the position is kept).
inline EdgeCase moved(const EdgeCase& c, const Matrix3& linear, const Vector3& t, const std::string& how) {
  const Matrix4 h = affine_matrix(linear, t);
  return {c.family + " " + how, congruence(c.e, h), congruence(c.p, h), c.expected};
}

inline Matrix3 scaled3(const Matrix3& m, const Rational& s) {
  Matrix3 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(i, j) = s * m(i, j);
  return out;
}

/// Nearness levels: relative distances 10^-3 ... 10^-100 and 2^-40 ... 2^-130.
inline std::vector<Rational> nearness() {
  return {pow10(-3), pow10(-20), pow10(-50), pow10(-100), pow2(-40), pow2(-130)};
}

/// A tangent point of the cup (a, b) from a small rational (s, t) (general position).
inline TangentPoint touch_point(Rng& g, const Rational& a, const Rational& b) {
  const auto st = random_st(g, false);
  return tangent_point(a, b, st.first, st.second);
}

/// Spheres around a tangent point at unit scale: TE/E/C outside and TI/I/C inside at every nearness.
inline std::vector<EdgeCase> spheres_near_contact(Rng& g) {
  std::vector<EdgeCase> out;
  for (const Rational& d : nearness()) {
    const Rational a = Q(g.uniform(2, 6), 2), b = Q(g.uniform(2, 6), 2);
    const TangentPoint tp = touch_point(g, a, b);
    const Rational r = rmin(a, b) * rmin(a, b) / 4;  // at most half the least radius of curvature
    const Matrix4 p = paraboloid_matrix(a, b);
    out.push_back({"sphere outside, separated", sphere_matrix(tp.along(r * (1 + d)), r), p, Position::E});
    out.push_back({"sphere outside, touching", sphere_matrix(tp.along(r), r), p, Position::TE});
    out.push_back({"sphere outside, crossing", sphere_matrix(tp.along(r * (1 - d)), r), p, Position::C});
    out.push_back({"sphere inside, separated", sphere_matrix(tp.along(-r * (1 + d)), r), p, Position::I});
    out.push_back({"sphere inside, touching", sphere_matrix(tp.along(-r), r), p, Position::TI});
    out.push_back({"sphere inside, crossing", sphere_matrix(tp.along(-r * (1 - d)), r), p, Position::C});
  }
  return out;
}

/// Rotated ellipsoids of axes `axes` supported by the tangent plane at a point of the cup (a, b):
/// TE, E and C at every nearness, and centred on the surface (C).
inline std::vector<EdgeCase> ellipsoids_near_contact(Rng& g, const Vector3& axes, const Rational& a,
                                                     const Rational& b) {
  std::vector<EdgeCase> out;
  const Matrix4 p = paraboloid_matrix(a, b);
  for (const Rational& d : nearness()) {
    const TangentPoint tp = touch_point(g, a, b);
    const Shape s = shape(axes, random_quaternion(g));
    const Vector3 mn = apply(s.inverse, tp.n);
    const Rational q = tp.n[0] * mn[0] + tp.n[1] * mn[1] + tp.n[2] * mn[2];
    const Rational tau = Q(1) / (1 + rabs(tp.n[0]) + rabs(tp.n[1]));  // any tau > 0
    const Vector3 c{tp.x0[0] + tau * mn[0], tp.x0[1] + tau * mn[1], tp.x0[2] + tau * mn[2]};
    const Rational r2 = tau * tau * q;
    out.push_back({"ellipsoid outside, separated", ellipsoid_matrix(c, s.m, r2 * (1 - d)), p, Position::E});
    out.push_back({"ellipsoid outside, touching", ellipsoid_matrix(c, s.m, r2), p, Position::TE});
    out.push_back({"ellipsoid outside, crossing", ellipsoid_matrix(c, s.m, r2 * (1 + d)), p, Position::C});
    out.push_back({"ellipsoid centred on the surface", ellipsoid_matrix(tp.x0, s.m, Rational(1)), p, Position::C});
  }
  return out;
}

/// Bodies of size 10^-k (spheres and rotated ellipsoids) centred on the surface of a unit cup: C.
inline std::vector<EdgeCase> tiny_on_surface(Rng& g, int k) {
  const Rational a = Q(g.uniform(1, 4)), b = Q(g.uniform(1, 4));
  const TangentPoint tp = touch_point(g, a, b);
  const Rational r = pow10(-k);
  const Shape s = shape({r, r * 3 / 2, r * 2}, random_quaternion(g));
  return {{"tiny sphere centred on the surface", sphere_matrix(tp.x0, r), paraboloid_matrix(a, b), Position::C},
          {"tiny ellipsoid centred on the surface", ellipsoid_matrix(tp.x0, s.m, Rational(1)), paraboloid_matrix(a, b),
           Position::C}};
}

/// The sphere of radius 1/4 resting in the cup z = x^2 + y^2 at the vertex, moved down by eps/4
/// (C: its lowest point leaves the cup), up by eps/4 (I) or not at all (TI).
inline std::vector<EdgeCase> sphere_in_cup(const Rational& eps) {
  const Matrix4 p = paraboloid_matrix(Q(1), Q(1));
  const Rational r = Q(1, 4);
  return {{"sphere in the cup, lowered", sphere_matrix(V(Q(0), Q(0), r - eps / 4), r), p, Position::C},
          {"sphere in the cup, raised", sphere_matrix(V(Q(0), Q(0), r + eps / 4), r), p, Position::I},
          {"sphere in the cup, resting", sphere_matrix(V(Q(0), Q(0), r), r), p, Position::TI}};
}

/// A sphere centred on the axis of the circular cup z = (x^2 + y^2)/a^2 at height h > a^2/2: its
/// squared distance to the surface, min over u = x^2 + y^2 of u + (u/a^2 - h)^2, is a^2 h - a^4/4,
/// reached along the circle u = a^2 h - a^4/2: TI along a circle (the hard case) at that squared
/// radius, I below it, C above.
inline std::vector<EdgeCase> sphere_on_circle(const Rational& a, const Rational& h, const Rational& d) {
  const Matrix4 p = paraboloid_matrix(a, a);
  const Rational r2 = a * a * h - a * a * a * a / 4;
  const Vector3 c{Q(0), Q(0), h};
  return {{"sphere touching along a circle", ellipsoid_matrix(c, identity3(), r2), p, Position::TI},
          {"sphere inside, near a circle", ellipsoid_matrix(c, identity3(), r2 * (1 - d)), p, Position::I},
          {"sphere crossing near a circle", ellipsoid_matrix(c, identity3(), r2 * (1 + d)), p, Position::C}};
}

/// A similarity x = s R u + t with R from an integer quaternion and t of size ~ shift.
inline EdgeCase similar(Rng& g, const EdgeCase& c, const Rational& s, const Rational& shift, const std::string& how) {
  const Vector3 t{shift * g.rational(-9, 9, 7), shift * g.rational(-9, 9, 7), shift * g.rational(-9, 9, 7)};
  return moved(c, scaled3(rotation(random_quaternion(g, 5)), s), t, how);
}

/// A general affine congruence (rotation, reflection, scaling, shear; construct.hpp) times s.
inline EdgeCase affine(Rng& g, const EdgeCase& c, const Rational& s, const Rational& shift, const std::string& how) {
  const Congruence h = random_congruence(g, false);
  Matrix3 l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l(i, j) = s * h.h(i, j);
  const Vector3 t{shift * g.rational(-9, 9, 7), shift * g.rational(-9, 9, 7), shift * g.rational(-9, 9, 7)};
  return moved(c, l, t, how);
}

}  // namespace rt::edges
