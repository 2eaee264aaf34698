// The constructions of families.hpp. Each family places a sphere against the standard paraboloid
// z = x^2/a^2 + y^2/b^2 at a known distance d from its centre to the surface (a nearest point X with
// a rational unit normal), radius r = d / s*, then maps the pair by x -> t + m^2 R(q) S x (S = diag(sx,
// sy, k^2)): a congruence, which keeps the position and s* (doc/oracle.md, "Why the positions are
// known"), and keeps the forms rational: the sphere becomes an ellipsoid with semi-axes m^2 r (sx, sy,
// k^2) along the columns of R(q), the paraboloid one with vertex t, a' = m a sx / k, b' = m b sy / k
// and rotation q.
#include "oracle/families.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "oracle/nearest.hpp"
#include "oracle/random.hpp"
#include "relpos/error.hpp"

namespace relpos::detail::oracle {

namespace {

Rational q(long n, long d = 1) { return Rational(Integer(n), Integer(d)); }

Rational rmin(const Rational& x, const Rational& y) { return x < y ? x : y; }

Rational power(const Rational& x, long k) {
  Rational out(1);
  for (long i = 0; i < (k < 0 ? -k : k); ++i) out *= x;
  return k < 0 ? 1 / out : out;
}

/// A sphere against z = x^2/a^2 + y^2/b^2 (vertex at the origin), with what is known of it.
struct Standard {
  Vector3 centre;
  Rational radius, a, b;
};

/// The map x -> t + m^2 R(q) diag(sx, sy, k^2) x applied to the pair.
struct Placement {
  Rational sx{1}, sy{1}, k{1}, m{1};
  Quaternion rotation{q(1), q(0), q(0), q(0)};
  Vector3 translation{q(0), q(0), q(0)};
};

Parameters place(const Standard& s, const Placement& g) {
  const Rational sigma = g.m * g.m, kk = g.k * g.k;
  const Vector3 scaled{g.sx * s.centre[0], g.sy * s.centre[1], kk * s.centre[2]};
  const Matrix3 r = rotation_from_quaternion(g.rotation);
  Parameters p;
  for (int i = 0; i < 3; ++i) {
    Rational x(0);
    for (int j = 0; j < 3; ++j) x += r(i, j) * scaled[static_cast<std::size_t>(j)];
    p.centre[static_cast<std::size_t>(i)] = g.translation[static_cast<std::size_t>(i)] + sigma * x;
  }
  p.axes = {sigma * s.radius * g.sx, sigma * s.radius * g.sy, sigma * s.radius * kk};
  p.e_rotation = g.rotation;
  p.vertex = g.translation;
  p.a = g.m * s.a * g.sx / g.k;
  p.b = g.m * s.b * g.sy / g.k;
  p.p_rotation = g.rotation;
  return p;
}

/// A point X of the surface with the outward unit normal N (rational), from the stereographic
/// image of (s, t), s^2 + t^2 < 1 so that N points down: the gradient (2x/a^2, 2y/b^2, -1) of
/// x^2/a^2 + y^2/b^2 - z is N / (-N_z).
struct SurfacePoint {
  Vector3 x, normal;
};
SurfacePoint surface_point(const Rational& a, const Rational& b, const Rational& s, const Rational& t) {
  const Rational den = 1 + s * s + t * t;
  const Vector3 n{2 * s / den, 2 * t / den, (s * s + t * t - 1) / den};
  const Rational slope_x = n[0] / -n[2], slope_y = n[1] / -n[2];
  const Rational x = a * a * slope_x / 2, y = b * b * slope_y / 2;
  return {{x, y, x * x / (a * a) + y * y / (b * b)}, n};
}

/// The sphere of radius d / s* whose centre lies at distance d from X along the normal, inside
/// (against N) or outside. Inside, d <= min(a, b)^2 / 2 keeps X the nearest point (doc/oracle.md).
Standard sphere_at(const SurfacePoint& p, const Rational& a, const Rational& b, const Rational& d,
                   const Rational& s_star, bool inside) {
  Standard s;
  for (std::size_t i = 0; i < 3; ++i) s.centre[i] = p.x[i] + (inside ? -d : d) * p.normal[i];
  s.radius = d / s_star;
  s.a = a;
  s.b = b;
  return s;
}

Position position_of(bool inside, const Rational& s_star) {
  if (s_star > 1) return inside ? Position::I : Position::E;
  if (s_star == 1) return inside ? Position::TI : Position::TE;
  return Position::C;
}

/// A random rotation quaternion with small integer components (not all zero).
Quaternion small_quaternion(Random& rng, long bound) {
  for (;;) {
    Quaternion out{q(rng.integer(-bound, bound)), q(rng.integer(-bound, bound)), q(rng.integer(-bound, bound)),
                   q(rng.integer(-bound, bound))};
    if (out[0] != 0 || out[1] != 0 || out[2] != 0 || out[3] != 0) return out;
  }
}

Vector3 small_vector(Random& rng, const Rational& bound, long den) {
  return {rng.fraction(-bound, bound, den), rng.fraction(-bound, bound, den), rng.fraction(-bound, bound, den)};
}

// ------------------------------------------------------------------------------------------------
// The families

struct Drawn {
  Standard base;
  Placement placement;
  bool inside = true;
};

/// a, b of a cup and the radius of a body that fits: r <= min(a, b)^2 / 4, so that d = r s* stays
/// below min(a, b)^2 / 2 for s* < 2.
void cup(Random& rng, Rational& a, Rational& b, Rational& r) {
  a = rng.fraction(q(1, 2), q(2), 12);
  b = rng.fraction(q(1, 2), q(2), 12);
  r = rng.fraction(q(1, 5), q(1), 10) * rmin(a * a, b * b) / 4;
}

Drawn axis(Random& rng, const Rational& s_star, bool inside) {
  Rational a, b, r;
  cup(rng, a, b, r);
  const SurfacePoint vertex{{q(0), q(0), q(0)}, {q(0), q(0), q(-1)}};
  return {sphere_at(vertex, a, b, r * s_star, s_star, inside), {}, inside};
}

Drawn offaxis(Random& rng, const Rational& s_star, bool inside) {
  Rational a, b, r;
  cup(rng, a, b, r);
  const SurfacePoint x = surface_point(a, b, rng.fraction(q(-3, 5), q(3, 5), 9), rng.fraction(q(-3, 5), q(3, 5), 9));
  return {sphere_at(x, a, b, r * s_star, s_star, inside), {}, inside};
}

Drawn rotated(Random& rng, const Rational& s_star, bool inside) {
  Drawn c = offaxis(rng, s_star, inside);
  c.placement.rotation = small_quaternion(rng, 4);
  c.placement.translation = small_vector(rng, q(2), 8);
  return c;
}

Drawn ellipsoid(Random& rng, const Rational& s_star, bool inside) {
  Drawn c = rotated(rng, s_star, inside);
  c.placement.sx = rng.fraction(q(1, 2), q(2), 6);
  c.placement.sy = rng.fraction(q(1, 2), q(2), 6);
  c.placement.k = rng.fraction(q(2, 3), q(3, 2), 6);
  return c;
}

/// The sphere centred in the plane x = 0 where the nearest point is also the birth of the critical
/// points off that plane: f has the special root -a^2 of s as a double root, the paper's Remark
/// (doc/oracle.md): I with Disc(f) = 0 at s* > 1, TI at s* = 1. With a < b, p = (m^2 - 1)/(4m) and
/// a^2 (m^2 + 1)/(2m) <= b^2: centre (0, p (b^2 - a^2), a^2/2 + p^2 b^2), nearest point
/// (0, p b^2, p^2 b^2), distance d = (a^2/2)(m^2 + 1)/(2m). Half the cases swap x and y (-b^2).
Drawn special(Random& rng, const Rational& s_star) {
  static const Rational kM[] = {q(2), q(3), q(3, 2), q(5, 2), q(4, 3), q(5, 3), q(5, 4)};
  const Rational m = kM[rng.integer(0, 6)];
  Rational p = (m * m - 1) / (4 * m);
  if (rng.integer(0, 1)) p = -p;
  const Rational a = rng.fraction(q(1, 2), q(3, 2), 10);
  const Rational need = a * a * (m * m + 1) / (2 * m);  // b^2 must be at least this
  Rational b = a;
  while (b * b < need) b += q(1, 10);
  b += rng.fraction(q(0), q(1, 2), 10);
  const Rational d = a * a / 2 * (m * m + 1) / (2 * m);
  Standard s;
  s.centre = {q(0), p * (b * b - a * a), a * a / 2 + p * p * b * b};
  s.radius = d / s_star;
  s.a = a;
  s.b = b;
  if (rng.integer(0, 1)) {  // the same in the plane y = 0: the special root -b^2
    std::swap(s.centre[0], s.centre[1]);
    std::swap(s.a, s.b);
  }
  return {s, {}, true};
}

/// A circular cup (a = b) and a sphere on its axis above the focal height a^2/2: the nearest points
/// form a circle, d^2 = a^2 c - a^4/4 for the centre (0, 0, c); the hard case at s* = 1.
Drawn circular(Random& rng, const Rational& s_star) {
  const Rational a = rng.fraction(q(1, 2), q(3, 2), 10);
  const Rational d = a * a / 2 * rng.fraction(q(11, 10), q(3), 10);
  Standard s;
  s.centre = {q(0), q(0), (d * d + a * a * a * a / 4) / (a * a)};
  s.radius = d / s_star;
  s.a = s.b = a;
  Drawn c{s, {}, true};
  c.placement.translation = small_vector(rng, q(1), 4);
  return c;
}

Drawn tiny(Random& rng, const Rational& s_star, bool inside) {
  Rational a, b, r;
  cup(rng, a, b, r);
  r *= power(q(10), -rng.integer(3, 8));
  const SurfacePoint x = surface_point(a, b, rng.fraction(q(-3, 5), q(3, 5), 9), rng.fraction(q(-3, 5), q(3, 5), 9));
  Drawn c{sphere_at(x, a, b, r * s_star, s_star, inside), {}, inside};
  c.placement.rotation = small_quaternion(rng, 4);
  c.placement.translation = small_vector(rng, q(2), 8);
  c.placement.sx = rng.fraction(q(1, 2), q(2), 6);
  c.placement.sy = rng.fraction(q(1, 2), q(2), 6);
  return c;
}

Drawn huge(Random& rng, const Rational& s_star, bool inside) {
  Drawn c = ellipsoid(rng, s_star, inside);
  c.placement.m = power(q(10), rng.integer(2, 5));
  return c;
}

Drawn far(Random& rng, const Rational& s_star, bool inside) {
  Drawn c = rotated(rng, s_star, inside);
  const long e = rng.integer(6, 8);
  const long bound = e == 6 ? 1000000 : (e == 7 ? 10000000 : 100000000);
  c.placement.translation = {q(rng.integer(-bound, bound)), q(rng.integer(-bound, bound)),
                             q(rng.integer(-bound, bound))};
  return c;
}

/// Exact tangencies whose parameters are all doubles: dyadic a, b, normals with dyadic slopes (3-4-5,
/// 1-2-2, 1-4-8 over 5, 3 and 9), a radius that is a multiple of the normal's denominator by a power
/// of two, rotations of the cube (|q|^2 in {1, 2, 4}: R(q) has entries 0, +-1) and dyadic maps.
Drawn exact(Random& rng, bool inside) {
  static const long kNormals[][4] = {{0, 0, 1, 1}, {3, 0, 4, 5}, {0, 3, 4, 5}, {2, 2, 1, 3}, {2, 1, 2, 3},
                                     {1, 2, 2, 3}, {8, 4, 1, 9}, {4, 8, 1, 9}, {4, 1, 8, 9}, {1, 4, 8, 9}};
  static const long kRotations[][4] = {{1, 0, 0, 0},  {1, 1, 0, 0},  {1, 0, 1, 0},  {1, 0, 0, 1},  {1, -1, 0, 0},
                                       {1, 0, -1, 0}, {1, 0, 0, -1}, {0, 1, 0, 0},  {0, 0, 1, 0},  {0, 0, 0, 1},
                                       {1, 1, 1, 1},  {1, 1, 1, -1}, {1, 1, -1, 1}, {1, -1, 1, 1}, {1, -1, -1, -1}};
  const long* n = kNormals[rng.integer(0, 9)];
  const Rational den(n[3]);
  const Rational n1 = (rng.integer(0, 1) ? -1 : 1) * q(n[0]) / den, n2 = (rng.integer(0, 1) ? -1 : 1) * q(n[1]) / den,
                 n3 = -q(n[2]) / den;
  const Rational a = q(rng.integer(4, 16), 8), b = q(rng.integer(4, 16), 8);
  const Rational x = a * a * (n1 / -n3) / 2, y = b * b * (n2 / -n3) / 2;
  const SurfacePoint point{{x, y, x * x / (a * a) + y * y / (b * b)}, {n1, n2, n3}};
  Rational r = den;  // den 2^e <= min(a, b)^2 / 4, the largest such, times 1, 3/4 or 5/8
  const Rational target = rmin(a * a, b * b) / 4;
  while (r > target) r /= 2;
  while (r * 2 <= target) r *= 2;
  static const Rational kShrink[] = {q(1), q(3, 4), q(5, 8)};
  r *= kShrink[rng.integer(0, 2)];
  Drawn c{sphere_at(point, a, b, r, q(1), inside), {}, inside};
  static const Rational kPowers[] = {q(1, 2), q(1), q(2)};
  c.placement.sx = kPowers[rng.integer(0, 2)];
  c.placement.sy = kPowers[rng.integer(0, 2)];
  c.placement.k = kPowers[rng.integer(0, 2)];
  const long* rot = kRotations[rng.integer(0, 14)];
  c.placement.rotation = {q(rot[0]), q(rot[1]), q(rot[2]), q(rot[3])};
  c.placement.translation = {q(rng.integer(-32, 32), 16), q(rng.integer(-32, 32), 16), q(rng.integer(-32, 32), 16)};
  return c;
}

/// A random pair near the surface, every parameter a double (its exact value): its label is
/// relpos's, checked by its certificate.
Parameters random_pair(Random& rng) {
  Parameters p;
  p.a = q(rng.integer(8, 32), 16);
  p.b = q(rng.integer(8, 32), 16);
  p.vertex = small_vector(rng, q(1), 16);
  p.p_rotation = small_quaternion(rng, 2);
  const Matrix3 r = rotation_from_quaternion(p.p_rotation);
  const Rational x = q(rng.integer(-64, 64), 64), y = q(rng.integer(-64, 64), 64);
  const Vector3 local{x, y, x * x / (p.a * p.a) + y * y / (p.b * p.b) + q(rng.integer(-32, 32), 64)};
  for (int i = 0; i < 3; ++i) {
    Rational c = p.vertex[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j) c += r(i, j) * local[static_cast<std::size_t>(j)];
    p.centre[static_cast<std::size_t>(i)] = exact_rational(nearest_double(c));
  }
  p.axes = {q(rng.integer(2, 32), 32), q(rng.integer(2, 32), 32), q(rng.integer(2, 32), 32)};
  p.e_rotation = small_quaternion(rng, 3);
  return p;
}

}  // namespace

const std::vector<Family>& families() {
  static const std::vector<Family> all = {
      {"axis", "a sphere on the cup's axis, above the vertex (inside) or below it (outside)", true},
      {"offaxis", "a sphere at a rational point of the surface with a rational unit normal, inside or outside", true},
      {"rotated", "offaxis, both bodies rotated by a rational quaternion and moved", true},
      {"ellipsoid", "rotated, both bodies stretched along the axes first: an ellipsoid against a general cup", true},
      {"special", "the paper's Remark: f has the special root -a^2 (or -b^2) as a double root; I against TI", true},
      {"circular", "a circular cup and a sphere on its axis touching along a circle (the hard case)", true},
      {"tiny", "ellipsoid, with bodies 10^-3 to 10^-8 the size of the cup", true},
      {"huge", "ellipsoid, scaled up by 10^4 to 10^10", true},
      {"far", "rotated, moved 10^6 to 10^8 away from the origin", true},
      {"exact", "exact tangencies (TI, TE) whose parameters are all doubles", false},
      {"random", "random pairs near the surface, parameters doubles; labelled by relpos with a verified certificate",
       false},
  };
  return all;
}

const Family* find_family(std::string_view name) {
  for (const Family& f : families())
    if (name == f.name) return &f;
  return nullptr;
}

Construction construct(const Family& family, const Rational& eps, std::uint64_t seed, std::uint64_t index) {
  if (eps < 0 || eps >= 1) throw InputError("eps must lie in [0, 1), got " + to_string(eps));
  Random rng(seed, family.name, index);
  const std::string name = family.name;
  Construction out;
  if (name == "random") {
    out.exact = random_pair(rng);
    return out;
  }
  const bool inside_only = name == "special" || name == "circular";
  const bool inside = inside_only || index % 2 == 0;
  const bool closer = ((inside_only ? index : index / 2) % 2) == 1;
  const Rational s_star = family.uses_eps ? (closer ? 1 - eps : 1 + eps) : Rational(1);
  Drawn c;
  if (name == "axis")
    c = axis(rng, s_star, inside);
  else if (name == "offaxis")
    c = offaxis(rng, s_star, inside);
  else if (name == "rotated")
    c = rotated(rng, s_star, inside);
  else if (name == "ellipsoid")
    c = ellipsoid(rng, s_star, inside);
  else if (name == "special")
    c = special(rng, s_star);
  else if (name == "circular")
    c = circular(rng, s_star);
  else if (name == "tiny")
    c = tiny(rng, s_star, inside);
  else if (name == "huge")
    c = huge(rng, s_star, inside);
  else if (name == "far")
    c = far(rng, s_star, inside);
  else if (name == "exact")
    c = exact(rng, inside);
  else
    throw InputError("unknown family '" + name + "'");
  out.exact = place(c.base, c.placement);
  out.position = position_of(c.inside, s_star);
  out.s_star = s_star;
  out.side = c.inside ? "inside" : "outside";
  return out;
}

}  // namespace relpos::detail::oracle
