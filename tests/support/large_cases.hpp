// A corpus of ellipsoid / elliptic paraboloid pairs of ANY size whose relative position is known BY
// CONSTRUCTION (worked out on paper below, never by running a classifier), for math.md §8.
//
// Families (standard frame unless said otherwise; q(x, y) the quadratic part of the paraboloid z = q):
//  1. axis spheres, circular cup z = k(x^2 + y^2), centre (0, 0, h), h > 0. Squared distance from the centre
//     to the surface point at radius^2 u: g(u) = u + (ku - h)^2, minimal at u* = h/k - 1/(2k^2) when h >= 1/(2k):
//     d^2 = h/k - 1/(4k^2), contact along the circle x^2 + y^2 = u*. Written with u* = m^2 (contact point
//     (m, 0, k m^2) rational): h = k m^2 + 1/(2k), d^2 = m^2 + 1/(4k^2); 4 d^2 k^2 >= 1: never small.
//     r^2 = d^2: TI; r^2 < d^2: I; d^2 < r^2 < h^2: C in two circles; r^2 >= h^2: C (ball contains the vertex).
//     Also h = 1/(2k) (osculating sphere at the vertex, u* = 0): r^2 = h^2 TI at the vertex.
//  2. below the vertex, any cup with q >= 0: centre (0, 0, -h), distance^2 to (x, y, q) = x^2 + y^2 + (q + h)^2
//     >= h^2, equality only at the vertex: r^2 = h^2 TE (any size), r^2 < h^2 E, r^2 > h^2 C.
//     And spheres of any radius r tangent from outside at a surface point with rational unit normal: the ball
//     and the cup lie on the two sides of the tangent plane: TE; same centre, smaller radius E, larger C.
//  3. ellipsoids of revolution u/al2 + (z - h)^2/be2 <= sigma (u = x^2 + y^2) in z = k u: on the surface
//     Q = z/(k al2) + (z - h)^2/be2, minimal at z* = h - be2/(2 k al2) > 0 with value
//     sigma* = z*/(k al2) + be2/(4 k^2 al2^2): TI along a circle at sigma*, I below, C above. Prolate and oblate.
//  4. long thin ellipsoids wedged in the cup z = x^2/a2 + y^2/b2: X/L2 + Y/W2 + (z - h)^2/H2 <= sigma with
//     X = x^2, Y = y^2. Q is convex in (X, Y) >= 0; with W2 < b2 L2/a2 its minimum is at Y = 0,
//     z* = h - a2 H2/(2 L2), X* = a2 z*, value sigma* = a2 z*/L2 + a2^2 H2/(4 L2^2): TI at the two points
//     (+-sqrt(X*), 0, z*) (irrational when X* is not a square), I below, C above. W2 = b2 L2/a2 makes Q a
//     function of z alone: contact along the ellipse q = z*. Spheres (L2 = W2 = H2 = 1, a2 < b2) touch at two
//     points.
//  5. irrational lambda_s: z = 2x^2 + 2xy + y^2 and z = x^2 + xy + 2y^2 (eigenvalues of A irrational, largest
//     < 3): their cups contain the cup z >= 3(x^2 + y^2), so a ball inside that circular cup (family 1's
//     distance with k = 3) is I; balls below the vertex as in 2; balls centred at a surface point are C; the
//     tall ellipsoid x^2 + y^2 + (z - 6)^2/36 <= 1 satisfies 3(x^2 + y^2) <= z - z^2/12 <= z, with equality only
//     at the origin: TI at the vertex (I / C for sigma = 1 -+ delta).
//  6. osculating +-1e-30: in every tangent family, sigma* +- 10^-30 (I / C or E / C) next to the +-1/50 ones.
//  7. math.md §3's examples: the paper's Remark (I), and the -b^2 double roots with C and E.
// Every case is also available under random rigid motions and general affine congruences, sign flips and
// positive rescalings (transformed_copies): the answers do not change (math.md §1).
#pragma once

#include <functional>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/quadric.hpp>
#include <string>
#include <vector>

#include "support/construct.hpp"

namespace relpos::testing {

struct LargeCase {
  std::string name;
  Ellipsoid e;
  Paraboloid p;
  Position expected;
  /// Within 10^-30 of a tangency from inside (-1) or outside (+1), else 0: long-double sampling can only check
  /// the non-strict inequality on that side (max p <= 0, resp. min p >= 0).
  int near = 0;
  /// Exact contact points (tangencies only; possibly a subset of the contact set).
  std::vector<Vector3> contacts;
  /// Exact points strictly inside the solid ellipsoid that the sampling test adds to its random points (for
  /// crossings whose region on one side is too thin for random samples).
  std::vector<Vector3> witnesses = {};
};

namespace large_detail {

using rt::Q;

/// 10^-30 exactly.
inline Rational tiny() {
  Integer p(1);
  for (int i = 0; i < 30; ++i) p *= 10;
  return Rational(Integer(1), p);
}

/// Paraboloid z = c20 x^2 + c11 xy + c02 y^2 (vertex at the origin, cup towards +z).
inline Matrix4 cup(const Rational& c20, const Rational& c11, const Rational& c02) {
  Matrix4 m;
  m(0, 0) = c20;
  m(1, 1) = c02;
  m(0, 1) = m(1, 0) = c11 / 2;
  m(2, 3) = m(3, 2) = Rational(-1, 2);
  return m;
}

/// Axis-aligned ellipsoid x^2/l1 + y^2/l2 + (z - h)^2/l3 <= sigma (l_i squared semi-axes), centre (cx, cy, h).
inline Matrix4 axis_ellipsoid(const Vector3& c, const Rational& l1, const Rational& l2, const Rational& l3,
                              const Rational& sigma) {
  Matrix4 m;
  const Rational w[3] = {1 / l1, 1 / l2, 1 / l3};
  Rational k(-sigma);
  for (int i = 0; i < 3; ++i) {
    m(i, i) = w[i];
    m(i, 3) = m(3, i) = -w[i] * c[static_cast<std::size_t>(i)];
    k += w[i] * c[static_cast<std::size_t>(i)] * c[static_cast<std::size_t>(i)];
  }
  m(3, 3) = k;
  return m;
}

inline Matrix4 sphere2(const Vector3& c, const Rational& r2) {
  return axis_ellipsoid(c, Rational(1), Rational(1), Rational(1), r2);
}

inline LargeCase make(std::string name, const Matrix4& e, const Matrix4& p, Position pos, int near = 0,
                      std::vector<Vector3> contacts = {}) {
  return LargeCase{
      std::move(name), Ellipsoid::from_matrix(e), Paraboloid::from_matrix(p), pos, near, std::move(contacts), {}};
}

/// The five neighbours of a tangency from inside at parameter sigma*: TI, I/C at -+1/50, I/C at -+1e-30.
inline void inside_family(std::vector<LargeCase>& out, const std::string& name,
                          const std::function<Matrix4(const Rational&)>& ellipsoid, const Rational& sigma,
                          const Matrix4& p, const std::vector<Vector3>& contacts) {
  out.push_back(make(name + " TI", ellipsoid(sigma), p, Position::TI, 0, contacts));
  out.push_back(make(name + " I (-1/50)", ellipsoid(sigma * Q(49, 50)), p, Position::I));
  out.push_back(make(name + " C (+1/50)", ellipsoid(sigma * Q(51, 50)), p, Position::C));
  out.push_back(make(name + " I (-1e-30)", ellipsoid(sigma - tiny()), p, Position::I, -1));
  out.push_back(make(name + " C (+1e-30)", ellipsoid(sigma + tiny()), p, Position::C, -1));
}

inline void outside_family(std::vector<LargeCase>& out, const std::string& name,
                           const std::function<Matrix4(const Rational&)>& ellipsoid, const Rational& sigma,
                           const Matrix4& p, const std::vector<Vector3>& contacts,
                           const std::optional<Vector3>& step = std::nullopt) {
  out.push_back(make(name + " TE", ellipsoid(sigma), p, Position::TE, 0, contacts));
  out.push_back(make(name + " E (-1/50)", ellipsoid(sigma * Q(49, 50)), p, Position::E));
  out.push_back(make(name + " C (+1/50)", ellipsoid(sigma * Q(51, 50)), p, Position::C));
  // The contact point moved by a short step into the cup is inside the grown ball.
  if (!contacts.empty() && step)
    out.back().witnesses.push_back(
        {contacts[0][0] + (*step)[0], contacts[0][1] + (*step)[1], contacts[0][2] + (*step)[2]});
  out.push_back(make(name + " E (-1e-30)", ellipsoid(sigma - tiny()), p, Position::E, 1));
  out.push_back(make(name + " C (+1e-30)", ellipsoid(sigma + tiny()), p, Position::C, 1));
}

inline std::string str(const Rational& q) { return relpos::to_string(q); }

}  // namespace large_detail

/// Family 1: spheres on the axis of a circular cup (contact along a circle, or at the vertex).
inline std::vector<LargeCase> axis_sphere_cases() {
  using namespace large_detail;
  std::vector<LargeCase> out;
  for (const Rational& k : {Q(1), Q(1, 2), Q(2), Q(3, 4)}) {
    const Matrix4 p = cup(k, Q(0), k);
    for (const Rational& m : {Q(1), Q(3, 2), Q(5)}) {
      const Rational h = k * m * m + 1 / (2 * k), d2 = m * m + 1 / (4 * k * k);
      const Vector3 c{Q(0), Q(0), h};
      const std::string name = "axis sphere k=" + str(k) + " m=" + str(m);
      inside_family(out, name, [&](const Rational& r2) { return sphere2(c, r2); }, d2, p, {{m, Q(0), k * m * m}});
      // Between d^2 and h^2: two circles; h^2: through the vertex; beyond: one circle.
      out.push_back(make(name + " C two circles", sphere2(c, (d2 + h * h) / 2), p, Position::C));
      out.push_back(make(name + " C through the vertex", sphere2(c, h * h), p, Position::C));
      out.push_back(make(name + " C one circle", sphere2(c, 2 * h * h), p, Position::C));
    }
    // The osculating sphere at the vertex: h = 1/(2k), r^2 = h^2 (multiplicity 4 in f).
    const Rational h = 1 / (2 * k);
    const Vector3 c{Q(0), Q(0), h};
    inside_family(out, "osculating vertex sphere k=" + str(k), [&](const Rational& r2) { return sphere2(c, r2); },
                  h * h, p, {{Q(0), Q(0), Q(0)}});
  }
  return out;
}

/// Family 2: balls below the vertex (any cup) and big balls tangent from outside at a rational-normal point.
inline std::vector<LargeCase> outside_cases() {
  using namespace large_detail;
  std::vector<LargeCase> out;
  const Matrix4 cups[3] = {cup(Q(1), Q(0), Q(1)), cup(Q(1), Q(0), Q(1, 4)), cup(Q(2), Q(2), Q(1))};
  const char* cup_names[3] = {"z=x^2+y^2", "z=x^2+y^2/4", "z=2x^2+2xy+y^2"};
  for (int i = 0; i < 3; ++i)
    for (const Rational& h : {Q(1), Q(5), Q(20)}) {
      const Vector3 c{Q(0), Q(0), -h};
      outside_family(
          out, std::string("below the vertex of ") + cup_names[i] + " h=" + str(h),
          [&](const Rational& r2) { return sphere2(c, r2); }, h * h, cups[i], {{Q(0), Q(0), Q(0)}},
          Vector3{Q(0), Q(0), h / 200});
    }
  // Tangent from outside at a point of z = x^2/a^2 + y^2/b^2 with rational unit normal, any radius.
  struct Pt {
    Rational a, b, s, t;
  };
  for (const Pt& pt : {Pt{Q(1), Q(2), Q(1, 2), Q(1, 3)}, Pt{Q(3, 2), Q(1), Q(2), Q(-1, 2)}}) {
    const rt::TangentPoint tp = rt::tangent_point(pt.a, pt.b, pt.s, pt.t);
    const Matrix4 p = rt::paraboloid_matrix(pt.a, pt.b);
    for (const Rational& r : {Q(1, 3), Q(4), Q(25)}) {
      const Vector3 c = tp.along(r);
      outside_family(
          out, "tangent from outside a=" + str(pt.a) + " b=" + str(pt.b) + " r=" + str(r),
          [&](const Rational& r2) { return sphere2(c, r2); }, r * r, p, {tp.x0},
          Vector3{-r * tp.n[0] / (200 * tp.m), -r * tp.n[1] / (200 * tp.m), -r * tp.n[2] / (200 * tp.m)});
    }
  }
  return out;
}

/// Family 3: prolate and oblate ellipsoids of revolution touching a circular cup along a circle.
inline std::vector<LargeCase> revolution_cases() {
  using namespace large_detail;
  std::vector<LargeCase> out;
  struct Par {
    Rational k, al2, be2, m;
  };
  for (const Par& q : {Par{Q(1), Q(1), Q(2), Q(1, 2)}, Par{Q(1), Q(1, 4), Q(9), Q(2)}, Par{Q(1, 2), Q(1), Q(4), Q(3)},
                       Par{Q(1), Q(4), Q(1), Q(2)}, Par{Q(2), Q(9), Q(1, 4), Q(1)}}) {
    const Rational zs = q.k * q.m * q.m, h = zs + q.be2 / (2 * q.k * q.al2);
    const Rational sigma = zs / (q.k * q.al2) + q.be2 / (4 * q.k * q.k * q.al2 * q.al2);
    const Vector3 c{Q(0), Q(0), h};
    const std::string name = std::string(q.be2 > q.al2 ? "prolate" : "oblate") + " along a circle k=" + str(q.k) +
                             " al2=" + str(q.al2) + " be2=" + str(q.be2);
    inside_family(out, name, [&](const Rational& s) { return axis_ellipsoid(c, q.al2, q.al2, q.be2, s); }, sigma,
                  cup(q.k, Q(0), q.k), {{q.m, Q(0), zs}});
  }
  return out;
}

/// Family 4: long thin ellipsoids wedged in z = x^2/a2 + y^2/b2 (two contact points or an ellipse), spheres
/// touching a non-circular cup at two points.
inline std::vector<LargeCase> wedged_cases() {
  using namespace large_detail;
  std::vector<LargeCase> out;
  struct Par {
    Rational a2, b2, L2, W2, H2, m;
    std::string what;
  };
  const Par pars[] = {
      {Q(1), Q(2), Q(9), Q(1, 4), Q(1, 4), Q(3, 2), "thin horizontal, rational contacts"},
      {Q(1), Q(2), Q(16), Q(1, 9), Q(1, 16), Q(5, 2), "long thin horizontal"},
      {Q(1, 4), Q(1), Q(4), Q(1, 16), Q(1, 4), Q(1), "thin horizontal, narrow cup"},
      {Q(1), Q(4), Q(1), Q(1), Q(1), Q(3), "sphere, two points"},
      {Q(1, 4), Q(9, 4), Q(1), Q(1), Q(1), Q(1, 2), "sphere, two points, narrow"},
      {Q(1), Q(2), Q(3), Q(6), Q(1, 2), Q(2), "similar section, contact ellipse"},
  };
  for (const Par& q : pars) {
    const Rational zs = q.m * q.m / q.a2, h = zs + q.a2 * q.H2 / (2 * q.L2);
    const Rational sigma = q.a2 * zs / q.L2 + q.a2 * q.a2 * q.H2 / (4 * q.L2 * q.L2);
    const Vector3 c{Q(0), Q(0), h};
    const std::string name = "wedged " + q.what;
    inside_family(out, name, [&](const Rational& s) { return axis_ellipsoid(c, q.L2, q.W2, q.H2, s); }, sigma,
                  cup(1 / q.a2, Q(0), 1 / q.b2), {{q.m, Q(0), zs}, {-q.m, Q(0), zs}});
  }
  // Irrational contact points (X* = 23/8 is not a square): contact checked by sampling only.
  {
    const Rational a2(1), b2(2), L2(4), W2(1, 4), H2(1), h(3);
    const Rational zs = h - a2 * H2 / (2 * L2), sigma = a2 * zs / L2 + a2 * a2 * H2 / (4 * L2 * L2);
    const Vector3 c{Q(0), Q(0), h};
    inside_family(out, "wedged, irrational contact points",
                  [&](const Rational& s) { return axis_ellipsoid(c, L2, W2, H2, s); }, sigma, cup(1 / a2, Q(0), 1 / b2),
                  {});
  }
  return out;
}

/// Family 5: cups whose A has irrational eigenvalues (lambda_s a quadratic irrational).
inline std::vector<LargeCase> irrational_cases() {
  using namespace large_detail;
  std::vector<LargeCase> out;
  const Matrix4 cups[2] = {cup(Q(2), Q(2), Q(1)), cup(Q(1), Q(1), Q(2))};
  const char* names[2] = {"z=2x^2+2xy+y^2", "z=x^2+xy+2y^2"};
  for (int i = 0; i < 2; ++i) {
    const Matrix4& p = cups[i];
    const std::string n = std::string(" in ") + names[i];
    // Inside the circular cup z = 3(x^2 + y^2): d^2 = h/3 - 1/36 for h >= 1/6.
    out.push_back(
        make("ball r^2=1/4 at height 1 (d^2 = 11/36)" + n, sphere2({Q(0), Q(0), Q(1)}, Q(1, 4)), p, Position::I));
    out.push_back(
        make("ball r^2=3/2 at height 5 (d^2 = 59/36)" + n, sphere2({Q(0), Q(0), Q(5)}, Q(3, 2)), p, Position::I));
    out.push_back(make("big ball r^2=40 at height 200" + n, sphere2({Q(0), Q(0), Q(200)}, Q(40)), p, Position::I));
    out.push_back(make("ball through the vertex region, r^2=2 at height 1" + n, sphere2({Q(0), Q(0), Q(1)}, Q(2)), p,
                       Position::C));
    for (const Rational& h : {Q(1), Q(10)}) {
      const Vector3 c{Q(0), Q(0), -h};
      out.push_back(
          make("below the vertex TE h=" + str(h) + n, sphere2(c, h * h), p, Position::TE, 0, {{Q(0), Q(0), Q(0)}}));
      out.push_back(make("below the vertex E h=" + str(h) + n, sphere2(c, h * h * Q(49, 50)), p, Position::E));
      out.push_back(make("below the vertex C h=" + str(h) + n, sphere2(c, 4 * h * h), p, Position::C));
    }
    // Balls centred at surface points: C for every radius.
    const Rational c11 = 2 * p(0, 1);
    for (const auto& xy : {std::pair<Rational, Rational>{Q(1), Q(0)}, {Q(1), Q(-1)}, {Q(-2), Q(3)}}) {
      const Rational z = p(0, 0) * xy.first * xy.first + c11 * xy.first * xy.second + p(1, 1) * xy.second * xy.second;
      for (const Rational& r2 : {Q(1, 100), Q(9), Q(900)})
        out.push_back(make("ball centred on the surface r^2=" + str(r2) + n, sphere2({xy.first, xy.second, z}, r2), p,
                           Position::C));
    }
    // The tall ellipsoid x^2 + y^2 + (z - 6)^2/36 <= sigma, touching at the vertex only for sigma = 1.
    inside_family(out, "tall ellipsoid on the vertex" + n,
                  [&](const Rational& s) {
                    return axis_ellipsoid({Q(0), Q(0), Q(6)}, Q(1), Q(1), Q(36), s);
                  },
                  Q(1), p, {{Q(0), Q(0), Q(0)}});
  }
  return out;
}

/// Family 7: math.md §3's examples (paper's Remark: I; -b^2 double root: C and E).
inline std::vector<LargeCase> paper_cases() {
  using namespace large_detail;
  std::vector<LargeCase> out;
  out.push_back(make("paper Remark a=6/5 b=3/2 r=1/4 (0,1/2,92281/129600)",
                     sphere2({Q(0), Q(1, 2), Q(92281, 129600)}, Q(1, 16)), rt::paraboloid_matrix(Q(6, 5), Q(3, 2)),
                     Position::I));
  out.push_back(make("math.md §3 -b^2 double, C: a=1 b=2 r=1/4 (1,0,131/192)",
                     sphere2({Q(1), Q(0), Q(131, 192)}, Q(1, 16)), rt::paraboloid_matrix(Q(1), Q(2)), Position::C));
  out.push_back(make("math.md §3 -b^2 double, E: a=1 b=2 r=1/4 (6/5,0,857/1600)",
                     sphere2({Q(6, 5), Q(0), Q(857, 1600)}, Q(1, 16)), rt::paraboloid_matrix(Q(1), Q(2)), Position::E));
  return out;
}

/// Every family, in the standard frames.
inline std::vector<LargeCase> large_cases() {
  std::vector<LargeCase> out;
  for (auto&& fam :
       {axis_sphere_cases(), outside_cases(), revolution_cases(), wedged_cases(), irrational_cases(), paper_cases()})
    out.insert(out.end(), fam.begin(), fam.end());
  return out;
}

/// The case moved by a random congruence (rigid: rotation from an integer quaternion and a rational
/// translation; otherwise a general invertible affine map), with independent positive rescalings and sign
/// flips of the two matrices. The answer is unchanged (math.md §1).
inline LargeCase transformed_copy(const LargeCase& c, rt::Rng& g, bool rigid) {
  const rt::Transformed t = rt::transform(c.e.matrix(), c.p.matrix(), g, rigid, true);
  return LargeCase{c.name + (rigid ? " [rigid motion]" : " [affine congruence]"),
                   Ellipsoid::from_matrix(t.e),
                   Paraboloid::from_matrix(t.p),
                   c.expected,
                   c.near,
                   {}};
}

}  // namespace relpos::testing
