// Construction helpers for the relpos tests: exact matrices built by hand (independently of the
// library's own constructors), affine congruences, the paper's closed forms, exact polynomial
// helpers, and geometric certificates in the paper's normalized frame.
//
// Conventions (math.md §1): a quadric is X^T Q X = 0 with X = (x, y, z, 1)^T; interior is
// X^T Q X < 0. The "standard frame" is the paper's: sphere of radius r centred at c, paraboloid
// z = x^2/a^2 + y^2/b^2 with vertex at the origin.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>
#include <string>
#include <utility>
#include <vector>

#include "algebra/pencil.hpp"

namespace rt {

using relpos::Integer;
using relpos::Matrix3;
using relpos::Matrix4;
using relpos::Position;
using relpos::Quadratic;
using relpos::Quartic;
using relpos::Quaternion;
using relpos::Rational;
using relpos::Vector3;

// ---------------------------------------------------------------------------------------------
// Numbers and small linear algebra
// ---------------------------------------------------------------------------------------------

/// n/d exactly (d != 0, either sign).
inline Rational Q(long n, long d = 1) { return Rational(Integer(n), Integer(d)); }

inline Vector3 V(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

inline int sgn(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

inline Rational rabs(const Rational& q) { return q < 0 ? -q : q; }

inline Rational rmin(const Rational& a, const Rational& b) { return a < b ? a : b; }

inline Rational pow_q(const Rational& q, int k) {
  Rational out(1);
  for (int i = 0; i < k; ++i) out *= q;
  return out;
}

/// X^T Q X for X = (x, 1), written out: the value of a quadric's form at a point.
inline Rational form_value(const Matrix4& q, const Vector3& x) {
  const Rational v[4] = {x[0], x[1], x[2], Rational(1)};
  Rational s(0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s += v[i] * q(i, j) * v[j];
  return s;
}

inline Matrix4 mul(const Matrix4& a, const Matrix4& b) {
  Matrix4 out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k) s += a(i, k) * b(k, j);
      out(i, j) = s;
    }
  return out;
}

inline Matrix3 mul(const Matrix3& a, const Matrix3& b) {
  Matrix3 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational s(0);
      for (int k = 0; k < 3; ++k) s += a(i, k) * b(k, j);
      out(i, j) = s;
    }
  return out;
}

inline Matrix4 transpose(const Matrix4& a) {
  Matrix4 out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out(i, j) = a(j, i);
  return out;
}

inline Matrix4 scaled(const Matrix4& a, const Rational& k) {
  Matrix4 out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = k * a.a[i];
  return out;
}

/// Q -> H^T Q H.
inline Matrix4 congruence(const Matrix4& q, const Matrix4& h) { return mul(transpose(h), mul(q, h)); }

inline Rational det3(const Matrix3& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

/// The solution of m x = b by Cramer's rule, exactly (det m != 0; the tests' own, independent of
/// the library's).
inline Vector3 solve3(const Matrix3& m, const Vector3& b) {
  const Rational d = det3(m);
  Vector3 x;
  for (int col = 0; col < 3; ++col) {
    Matrix3 mc = m;
    for (int i = 0; i < 3; ++i) mc(i, col) = b[static_cast<std::size_t>(i)];
    x[static_cast<std::size_t>(col)] = det3(mc) / d;
  }
  return x;
}

/// Determinant by exact Gaussian elimination (independent of the library's Laplace expansion).
inline Rational det4(Matrix4 m) {
  Rational det(1);
  for (int c = 0; c < 4; ++c) {
    int p = c;
    while (p < 4 && m(p, c) == 0) ++p;
    if (p == 4) return Rational(0);
    if (p != c) {
      for (int j = 0; j < 4; ++j) std::swap(m(p, j), m(c, j));
      det = -det;
    }
    det *= m(c, c);
    for (int i = c + 1; i < 4; ++i) {
      if (m(i, c) == 0) continue;
      Rational f = m(i, c) / m(c, c);
      for (int j = c; j < 4; ++j) m(i, j) -= f * m(c, j);
    }
  }
  return det;
}

inline Matrix3 identity3() {
  Matrix3 m;
  for (int i = 0; i < 3; ++i) m(i, i) = Rational(1);
  return m;
}

inline Matrix3 diag3(const Rational& a, const Rational& b, const Rational& c) {
  Matrix3 m;
  m(0, 0) = a;
  m(1, 1) = b;
  m(2, 2) = c;
  return m;
}

/// H = [[L, t], [0, 1]]: the affine map x = L u + t in homogeneous form.
inline Matrix4 affine_matrix(const Matrix3& l, const Vector3& t) {
  Matrix4 h;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) h(i, j) = l(i, j);
    h(i, 3) = t[static_cast<std::size_t>(i)];
  }
  h(3, 3) = Rational(1);
  return h;
}

/// Rotation R(q)/|q|^2 written out here (not the library's), for building inputs.
inline Matrix3 rotation(const Quaternion& q) {
  const Rational &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  const Rational n = w * w + x * x + y * y + z * z;
  Matrix3 r;
  r(0, 0) = (w * w + x * x - y * y - z * z) / n;
  r(0, 1) = 2 * (x * y - w * z) / n;
  r(0, 2) = 2 * (x * z + w * y) / n;
  r(1, 0) = 2 * (x * y + w * z) / n;
  r(1, 1) = (w * w - x * x + y * y - z * z) / n;
  r(1, 2) = 2 * (y * z - w * x) / n;
  r(2, 0) = 2 * (x * z - w * y) / n;
  r(2, 1) = 2 * (y * z + w * x) / n;
  r(2, 2) = (w * w - x * x - y * y + z * z) / n;
  return r;
}

inline Matrix4 diag4(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  Matrix4 m;
  m(0, 0) = a;
  m(1, 1) = b;
  m(2, 2) = c;
  m(3, 3) = d;
  return m;
}

inline void set_sym(Matrix4& m, int i, int j, const Rational& v) {
  m(i, j) = v;
  m(j, i) = v;
}

// ---------------------------------------------------------------------------------------------
// The two surfaces in the standard frame, by hand
// ---------------------------------------------------------------------------------------------

/// |x - c|^2 - r^2.
inline Matrix4 sphere_matrix(const Vector3& c, const Rational& r) {
  Matrix4 m = diag4(Rational(1), Rational(1), Rational(1), c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - r * r);
  for (int i = 0; i < 3; ++i) set_sym(m, i, 3, -c[static_cast<std::size_t>(i)]);
  return m;
}

/// x^2/a^2 + y^2/b^2 - z (vertex at the origin, cup opening towards +z).
inline Matrix4 paraboloid_matrix(const Rational& a, const Rational& b) {
  Matrix4 m = diag4(Rational(1) / (a * a), Rational(1) / (b * b), Rational(0), Rational(0));
  set_sym(m, 2, 3, Rational(-1, 2));
  return m;
}

/// F(x, y, z) = x^2/a^2 + y^2/b^2 - z: negative inside the cup.
inline Rational paraboloid_value(const Rational& a, const Rational& b, const Vector3& x) {
  return x[0] * x[0] / (a * a) + x[1] * x[1] / (b * b) - x[2];
}

inline Rational dist2(const Vector3& p, const Vector3& q) {
  Rational s(0);
  for (std::size_t i = 0; i < 3; ++i) s += (p[i] - q[i]) * (p[i] - q[i]);
  return s;
}

// ---------------------------------------------------------------------------------------------
// Polynomials over Q
// ---------------------------------------------------------------------------------------------

template <std::size_t N>
Rational eval(const std::array<Rational, N>& c, const Rational& x) {
  Rational v(0);
  for (std::size_t i = N; i-- > 0;) v = v * x + c[i];
  return v;
}

/// Multiplicity of x as a root of the polynomial (0 if not a root; capped at the degree).
template <std::size_t N>
int multiplicity(std::array<Rational, N> c, const Rational& x) {
  int m = 0;
  bool nonzero = false;
  for (const auto& v : c)
    if (v != 0) nonzero = true;
  if (!nonzero) return -1;
  while (eval(c, x) == 0 && m < static_cast<int>(N)) {
    ++m;
    std::array<Rational, N> d{};
    for (std::size_t i = 1; i < N; ++i) d[i - 1] = Rational(static_cast<long>(i)) * c[i];
    c = d;
  }
  return m;
}

/// Discriminant of a x^4 + b x^3 + c x^2 + d x + e (the classical 16-term formula).
inline Rational quartic_discriminant(const Quartic<Rational>& f) {
  const Rational &a = f[4], &b = f[3], &c = f[2], &d = f[1], &e = f[0];
  return 256 * a * a * a * e * e * e - 192 * a * a * b * d * e * e - 128 * a * a * c * c * e * e +
         144 * a * a * c * d * d * e - 27 * a * a * d * d * d * d + 144 * a * b * b * c * e * e -
         6 * a * b * b * d * d * e - 80 * a * b * c * c * d * e + 18 * a * b * c * d * d * d +
         16 * a * c * c * c * c * e - 4 * a * c * c * c * d * d - 27 * b * b * b * b * e * e +
         18 * b * b * b * c * d * e - 4 * b * b * b * d * d * d - 4 * b * b * c * c * c * e + b * b * c * c * d * d;
}

/// Monic quartic with the given four roots (times lead).
inline Quartic<Rational> quartic_from_roots(const Rational& lead, const std::array<Rational, 4>& r) {
  std::array<Rational, 5> c{Rational(1), Rational(0), Rational(0), Rational(0), Rational(0)};
  int deg = 0;
  for (const auto& root : r) {
    std::array<Rational, 5> n{};
    for (int i = deg; i >= 0; --i) {
      n[static_cast<std::size_t>(i + 1)] += c[static_cast<std::size_t>(i)];
      n[static_cast<std::size_t>(i)] -= root * c[static_cast<std::size_t>(i)];
    }
    c = n;
    ++deg;
  }
  for (auto& v : c) v *= lead;
  return c;
}

/// The paper's eq. (4): f(l) = det(l P + S) for the sphere (xc, yc, zc, r) and the standard
/// paraboloid (a, b), written out from the closed form (not from a determinant).
inline Quartic<Rational> paper_f(const Rational& a, const Rational& b, const Vector3& c, const Rational& r) {
  const Rational a2 = a * a, b2 = b * b, &xc = c[0], &yc = c[1], &zc = c[2];
  const Rational k = -Rational(1) / (4 * a2 * b2);
  Quartic<Rational> f;
  f[4] = k;
  f[3] = k * (4 * zc + a2 + b2);
  f[2] = k * (4 * zc * (a2 + b2) - 4 * (xc * xc + yc * yc - r * r) + a2 * b2);
  f[1] = k * 4 * (zc * a2 * b2 - yc * yc * a2 - xc * xc * b2 + r * r * (a2 + b2));
  f[0] = -r * r;
  return f;
}

/// s(l) = det(l A + I) = (1 + l/a^2)(1 + l/b^2) for the sphere and the standard paraboloid.
inline Quadratic<Rational> paper_s(const Rational& a, const Rational& b) {
  const Rational a2 = a * a, b2 = b * b;
  return {Rational(1), Rational(1) / a2 + Rational(1) / b2, Rational(1) / (a2 * b2)};
}

// ---------------------------------------------------------------------------------------------
// Random inputs
// ---------------------------------------------------------------------------------------------

struct Rng {
  std::uint64_t seed;
  std::mt19937_64 gen;
  explicit Rng(std::uint64_t s) : seed(s), gen(s) {}
  long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(gen); }
  bool chance(int percent) { return uniform(0, 99) < percent; }
  /// n/d with n in [lo, hi], d in [1, maxden].
  Rational rational(long lo, long hi, long maxden) { return Q(uniform(lo, hi), uniform(1, maxden)); }
  Rational nonzero_rational(long lo, long hi, long maxden) {
    for (;;) {
      long n = uniform(lo, hi);
      if (n != 0) return Q(n, uniform(1, maxden));
    }
  }
  Rational positive_rational(long hi, long maxden) { return Q(uniform(1, hi), uniform(1, maxden)); }
};

/// A non-zero quaternion with small integer components.
inline Quaternion random_quaternion(Rng& g, long m = 3) {
  for (;;) {
    Quaternion q{Q(g.uniform(-m, m)), Q(g.uniform(-m, m)), Q(g.uniform(-m, m)), Q(g.uniform(-m, m))};
    if (q[0] != 0 || q[1] != 0 || q[2] != 0 || q[3] != 0) return q;
  }
}

/// A random invertible affine congruence H = [[L, t], [0, 1]] with L = R(q) D U: rotation from an
/// integer quaternion, non-zero diagonal scaling (negative entries make reflections), unit upper
/// triangular shear. `rigid` keeps only rotation and translation.
struct Congruence {
  Matrix4 h;
  Rational det;  ///< det H = det L
};

inline Congruence random_congruence(Rng& g, bool rigid = false) {
  Matrix3 l = rotation(random_quaternion(g));
  if (!rigid) {
    Matrix3 d = diag3(g.nonzero_rational(-4, 4, 3), g.nonzero_rational(-4, 4, 3), g.nonzero_rational(-4, 4, 3));
    Matrix3 u = identity3();
    u(0, 1) = g.rational(-2, 2, 3);
    u(0, 2) = g.rational(-2, 2, 3);
    u(1, 2) = g.rational(-2, 2, 3);
    l = mul(l, mul(d, u));
  }
  Vector3 t{g.rational(-5, 5, 4), g.rational(-5, 5, 4), g.rational(-5, 5, 4)};
  return {affine_matrix(l, t), det3(l)};
}

// ---------------------------------------------------------------------------------------------
// Configurations with a known answer
// ---------------------------------------------------------------------------------------------

/// Sphere (c, r) and paraboloid z = x^2/a^2 + y^2/b^2, in the standard frame.
struct Config {
  std::string name;
  Rational a, b;
  Vector3 c;
  Rational r;
  Position expected = Position::C;  ///< by construction (set by every maker)

  Rational amin() const { return rmin(a, b); }
  /// rho = 4 r^2 / min(a, b)^4 (math.md §5).
  Rational rho() const { return 4 * r * r / pow_q(amin(), 4); }
  bool small() const { return 2 * r <= amin() * amin(); }
  Matrix4 e() const { return sphere_matrix(c, r); }
  Matrix4 p() const { return paraboloid_matrix(a, b); }
};

inline std::string describe(const Config& k) {
  return k.name + ": a=" + relpos::to_string(k.a) + " b=" + relpos::to_string(k.b) + " c=(" +
         relpos::to_string(k.c[0]) + ", " + relpos::to_string(k.c[1]) + ", " + relpos::to_string(k.c[2]) +
         ") r=" + relpos::to_string(k.r);
}

/// A point of z = x^2/a^2 + y^2/b^2 whose gradient n = (u, v, -1) has rational length m:
/// (u, v, 1, m) = (2s, 2t, D, 1 + s^2 + t^2)/D with D = 1 - s^2 - t^2 != 0.
/// n points out of the cup (towards increasing F).
struct TangentPoint {
  Rational a, b;
  Vector3 x0;
  Vector3 n;   ///< (u, v, -1)
  Rational m;  ///< |n|, rational
  /// x0 + d n/|n| (d > 0: outside the cup, d < 0: inside).
  Vector3 along(const Rational& d) const { return {x0[0] + d * n[0] / m, x0[1] + d * n[1] / m, x0[2] + d * n[2] / m}; }
};

inline TangentPoint tangent_point(const Rational& a, const Rational& b, const Rational& s, const Rational& t) {
  const Rational d = 1 - s * s - t * t;  // caller guarantees d != 0
  const Rational u = 2 * s / d, v = 2 * t / d;
  TangentPoint tp;
  tp.a = a;
  tp.b = b;
  tp.x0 = {u * a * a / 2, v * b * b / 2, u * u * a * a / 4 + v * v * b * b / 4};
  tp.n = {u, v, Rational(-1)};
  tp.m = rabs((1 + s * s + t * t) / d);
  return tp;
}

/// Random rational (s, t) with s^2 + t^2 != 1; general position (s, t != 0) unless allow_axis.
inline std::pair<Rational, Rational> random_st(Rng& g, bool allow_axis) {
  for (;;) {
    Rational s = Q(g.uniform(-4, 4), g.uniform(1, 4)), t = Q(g.uniform(-4, 4), g.uniform(1, 4));
    if (s * s + t * t == 1) continue;
    if (!allow_axis && (s == 0 || t == 0)) continue;
    return {s, t};
  }
}

/// Sphere sizes for the tangency family: r <= min(a, b)^2 / 4, so that r, and r(1 + j/8) <= 2r,
/// are small (2 r' <= a^2) and at most the smallest radius of curvature a^2/2.
inline Rational random_tangent_radius(Rng& g, const Rational& a, const Rational& b) {
  return rmin(a, b) * rmin(a, b) * Q(g.uniform(1, 4), 16);
}

/// The five positions around an exact tangency at tp (radius r <= min(a,b)^2 / 4; 0 < j < 8):
/// TI / TE: the tangent spheres; I / E: the same centres, radius shrunk (the smaller ball lies in
/// the open tangent ball); C: radius grown (the ball then contains x0 in its interior), or the TI
/// sphere slid along the tangent plane (its lowest point leaves the strictly convex cup).
inline std::vector<Config> tangency_family(const TangentPoint& tp, const Rational& r, long j) {
  const Rational shrink = r * Q(8 - j, 8), grow = r * Q(8 + j, 8);
  std::vector<Config> out;
  out.push_back({"TI at rational-normal point", tp.a, tp.b, tp.along(-r), r, Position::TI});
  out.push_back({"TE at rational-normal point", tp.a, tp.b, tp.along(r), r, Position::TE});
  out.push_back({"I: TI centre, smaller radius", tp.a, tp.b, tp.along(-r), shrink, Position::I});
  out.push_back({"E: TE centre, smaller radius", tp.a, tp.b, tp.along(r), shrink, Position::E});
  out.push_back({"I: centre pushed inwards", tp.a, tp.b, tp.along(-grow), r, Position::I});
  out.push_back({"E: centre pushed outwards", tp.a, tp.b, tp.along(grow), r, Position::E});
  out.push_back({"C: TI centre, larger radius", tp.a, tp.b, tp.along(-r), grow, Position::C});
  out.push_back({"C: TE centre, larger radius", tp.a, tp.b, tp.along(r), grow, Position::C});
  out.push_back({"C: centre moved out across x0", tp.a, tp.b, tp.along(-shrink), r, Position::C});
  // Slide the TI sphere along the tangent plane by eps w, w = (v, -u, 0) (or (1, 0, 0)),
  // eps |w| < r/2 so that the new centre stays in the open ball of the TI sphere (inside the cup).
  Vector3 w =
      (tp.n[0] == 0 && tp.n[1] == 0) ? V(Rational(1), Rational(0), Rational(0)) : V(tp.n[1], -tp.n[0], Rational(0));
  const Rational eps = r * Q(j, 16) / (rabs(w[0]) + rabs(w[1]) + 1);
  Vector3 c = tp.along(-r);
  out.push_back({"C: TI sphere slid along the tangent plane", tp.a, tp.b, V(c[0] + eps * w[0], c[1] + eps * w[1], c[2]),
                 r, Position::C});
  return out;
}

/// Centre on the axis of the cup (the paper's section on the axis): small spheres give I / TI / C / TE / E by the
/// sign of z - r and z + r (the nearest point of the cup to an axis point at height z <= a^2/2 is
/// the vertex, and beyond it the distance^2 is a^2 z - a^4/4 > r^2).
inline Position axis_position(const Rational& z, const Rational& r) {
  if (z > r) return Position::I;
  if (z == r) return Position::TI;
  if (z > -r) return Position::C;
  if (z == -r) return Position::TE;
  return Position::E;
}

// ---------------------------------------------------------------------------------------------
// Geometric certificates in the standard frame (valid for spheres of any size)
// ---------------------------------------------------------------------------------------------

/// A point of the paraboloid strictly inside the ball: the ball then has points on both sides of
/// the surface, so the position is C (when small) and the surfaces certainly meet.
inline bool crossing_certificate(const Config& k) {
  if (paraboloid_value(k.a, k.b, k.c) == 0) return true;  // the centre itself
  const Rational h = k.r / 6;
  for (long i = -8; i <= 8; ++i)
    for (long j = -8; j <= 8; ++j) {
      const Rational x = k.c[0] + h * Q(i), y = k.c[1] + h * Q(j);
      const Vector3 p{x, y, x * x / (k.a * k.a) + y * y / (k.b * k.b)};
      if (dist2(p, k.c) < k.r * k.r) return true;
    }
  return false;
}

/// A tangent plane of the cup with the whole ball strictly on its outer side: separated (E).
/// Plane at X = (x, y, F=0) with normal n = (2x/a^2, 2y/b^2, -1): n.(c - X) > 0 and
/// (n.(c - X))^2 > r^2 |n|^2.
inline bool separation_certificate(const Config& k) {
  if (paraboloid_value(k.a, k.b, k.c) <= 0) return false;
  // Candidates: around the vertical projection of c and around the origin, on a grid.
  const Rational h = Rational(1, 8) * (rabs(k.c[0]) + rabs(k.c[1]) + 1) / 2;
  for (long i = -8; i <= 8; ++i)
    for (long j = -8; j <= 8; ++j)
      for (int around = 0; around < 2; ++around) {
        const Rational x = (around ? Rational(0) : k.c[0]) + h * Q(i), y = (around ? Rational(0) : k.c[1]) + h * Q(j);
        const Vector3 p{x, y, x * x / (k.a * k.a) + y * y / (k.b * k.b)};
        const Vector3 n{2 * x / (k.a * k.a), 2 * y / (k.b * k.b), Rational(-1)};
        const Rational val = n[0] * (k.c[0] - p[0]) + n[1] * (k.c[1] - p[1]) + n[2] * (k.c[2] - p[2]);
        if (val > 0 && val * val > k.r * k.r * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2])) return true;
      }
  return false;
}

// ---------------------------------------------------------------------------------------------
// Transformed instances
// ---------------------------------------------------------------------------------------------

/// The pair after Q -> k H^T Q H (same H for both, independent positive k's, optional sign flip).
/// f and s of the sign-normalized result are then
///   f'(l) = det(H)^2 kE^4 f(l kP / kE),   s'(l) = det(L)^2 kE^3 s(l kP / kE):
/// every root is multiplied by kE / kP; signs and multiplicities are unchanged.
struct Transformed {
  Matrix4 e, p;
  Rational det_h, ke, kp;
  bool flip_e = false, flip_p = false;
  Rational root_scale() const { return ke / kp; }
};

inline Transformed transform(const Matrix4& e, const Matrix4& p, Rng& g, bool rigid = false, bool rescale = true) {
  Congruence h = random_congruence(g, rigid);
  Transformed t;
  t.det_h = h.det;
  t.ke = rescale ? g.positive_rational(7, 5) : Rational(1);
  t.kp = rescale ? g.positive_rational(7, 5) : Rational(1);
  t.flip_e = rescale && g.chance(30);
  t.flip_p = rescale && g.chance(30);
  t.e = scaled(congruence(e, h.h), t.flip_e ? -t.ke : t.ke);
  t.p = scaled(congruence(p, h.h), t.flip_p ? -t.kp : t.kp);
  return t;
}

/// The expected f and s coefficients of a transformed pair (see Transformed).
inline Quartic<Rational> transformed_f(const Quartic<Rational>& f, const Transformed& t) {
  Quartic<Rational> out;
  const Rational q = t.kp / t.ke;
  for (int i = 0; i < 5; ++i)
    out[static_cast<std::size_t>(i)] =
        t.det_h * t.det_h * pow_q(t.ke, 4) * pow_q(q, i) * f[static_cast<std::size_t>(i)];
  return out;
}

inline Quadratic<Rational> transformed_s(const Quadratic<Rational>& s, const Transformed& t) {
  Quadratic<Rational> out;
  const Rational q = t.kp / t.ke;
  for (int i = 0; i < 3; ++i)
    out[static_cast<std::size_t>(i)] =
        t.det_h * t.det_h * pow_q(t.ke, 3) * pow_q(q, i) * s[static_cast<std::size_t>(i)];
  return out;
}

// ---------------------------------------------------------------------------------------------
// The paper's Table 2 (coefficient-sign rule), for comparison
// ---------------------------------------------------------------------------------------------

/// Table 2 of the paper on the monic p = f/f4: I/TI iff Disc >= 0 and all c_i >= 0 (I when
/// Disc > 0, TI when Disc = 0); C iff Disc < 0; TE iff Disc = 0 and some c_i < 0; E iff Disc > 0
/// and some c_i < 0.
inline Position table2(const Quartic<Rational>& f) {
  const Rational d = quartic_discriminant(f);
  bool all_nonneg = true;
  for (int i = 0; i < 4; ++i)
    if (f[static_cast<std::size_t>(i)] / f[4] < 0) all_nonneg = false;
  if (d < 0) return Position::C;
  if (all_nonneg) return d > 0 ? Position::I : Position::TI;
  return d == 0 ? Position::TE : Position::E;
}

}  // namespace rt
