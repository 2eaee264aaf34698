// Every real quadric as the second body: the validated `Quadric` value type beside Ellipsoid and
// Paraboloid (math.md §14).
//
// A quadric is X^T Q X = 0 with X = (x, y, z, 1)^T and Q = [[B, b], [b^T, b0]]; its solid is
// {q <= 0}, q(x) = X^T Q X. The sign of Q is normalized so that B has more positive than negative
// eigenvalues (negation only); where there is a tie -- hyperbolic paraboloid, hyperbolic cylinder,
// half-space -- the sign is the one given, and negating the matrix swaps the solid with its
// complement. Degenerate and imaginary quadrics (a double plane, two intersecting planes, a line, a
// point, an imaginary ellipsoid, ...) are refused with an InputError that names them.
#pragma once

#include <array>
#include <string>

#include "relpos/internal/quadric_matrix.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

/// The eleven real quadrics relpos accepts as the second body, each with its solid {q <= 0}.
enum class QuadricType : unsigned char {
  Ellipsoid,             ///< x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1
  HyperboloidOneSheet,   ///< x^2/a^2 + y^2/b^2 - z^2/c^2 <= 1: the region around the axis (not convex)
  HyperboloidTwoSheets,  ///< x^2/a^2 + y^2/b^2 - z^2/c^2 <= -1: the two convex caps
  Cone,                  ///< x^2/a^2 + y^2/b^2 <= z^2: the double cone around the axis
  EllipticParaboloid,    ///< x^2/a^2 + y^2/b^2 <= z: inside the cup
  HyperbolicParaboloid,  ///< x^2/a^2 - y^2/b^2 <= z (the sign as given)
  EllipticCylinder,      ///< x^2/a^2 + y^2/b^2 <= 1: the solid tube
  HyperbolicCylinder,    ///< x^2/a^2 - y^2/b^2 <= 1 (the sign as given): the connected middle
  ParabolicCylinder,     ///< x^2/a^2 <= z: the convex side
  Slab,                  ///< lo <= n.x <= hi: between two parallel planes
  HalfSpace,             ///< n.x <= d: one side of a plane (a linear form, B = 0)
};
/// "ellipsoid", "hyperboloid of one sheet", ..., "slab", "half-space".
std::string to_string(QuadricType type);

/// A validated real quadric with its solid {q <= 0}, sign-normalized as described above.
class Quadric {
 public:
  /// Any symmetric matrix of one of the eleven types; InputError naming what it is otherwise.
  static Quadric from_matrix(const Matrix4& q);
  /// Row-major 4x4 doubles, each taken exactly (InputError on NaN or infinity).
  static Quadric from_doubles(const DoubleMatrix4& q);
  /// The 10 coefficients of the implicit equation (cross terms halved).
  static Quadric from_coefficients(const Coefficients10& c);
  /// The same solid as a validated ellipsoid or elliptic paraboloid.
  static Quadric of(const Ellipsoid& e);
  static Quadric of(const Paraboloid& p);

  // Geometric forms. The local frame has its origin at `centre` (apex, vertex) and its axes along
  // the columns of the rotation R(q)/|q|^2; every length is positive (InputError otherwise).
  static Quadric sphere(const Vector3& centre, const Rational& radius);
  static Quadric ellipsoid(const Vector3& centre, const Vector3& semi_axes,
                           const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// x^2/a^2 + y^2/b^2 - z^2/c^2 = 1, semi_axes = (a, b, c); the solid contains the axis.
  static Quadric hyperboloid_one_sheet(const Vector3& centre, const Vector3& semi_axes,
                                       const Quaternion& rotation = {Rational(1), Rational(0), Rational(0),
                                                                     Rational(0)});
  /// x^2/a^2 + y^2/b^2 - z^2/c^2 = -1; the solid is the two caps.
  static Quadric hyperboloid_two_sheets(const Vector3& centre, const Vector3& semi_axes,
                                        const Quaternion& rotation = {Rational(1), Rational(0), Rational(0),
                                                                      Rational(0)});
  /// x^2/a^2 + y^2/b^2 = z^2 with its apex at `apex`; the solid is the double cone around the axis.
  static Quadric cone(const Vector3& apex, const Rational& a, const Rational& b,
                      const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// x^2/a^2 + y^2/b^2 = z (as Paraboloid::standard).
  static Quadric elliptic_paraboloid(const Vector3& vertex, const Rational& a, const Rational& b,
                                     const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// x^2/a^2 - y^2/b^2 = z; the solid is z >= x^2/a^2 - y^2/b^2.
  static Quadric hyperbolic_paraboloid(const Vector3& vertex, const Rational& a, const Rational& b,
                                       const Quaternion& rotation = {Rational(1), Rational(0), Rational(0),
                                                                     Rational(0)});
  /// x^2/a^2 + y^2/b^2 = 1 along the local z axis; the solid is the tube.
  static Quadric elliptic_cylinder(const Vector3& centre, const Rational& a, const Rational& b,
                                   const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// x^2/a^2 - y^2/b^2 = 1 along the local z axis; the solid is the connected region between the sheets.
  static Quadric hyperbolic_cylinder(const Vector3& centre, const Rational& a, const Rational& b,
                                     const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// x^2/a^2 = z, ruled along the local y axis; the solid is its convex side.
  static Quadric parabolic_cylinder(const Vector3& vertex, const Rational& a,
                                    const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// {x : normal . x <= offset}, normal != 0 (the linear form normal . x - offset).
  static Quadric half_space(const Vector3& normal, const Rational& offset);
  /// {x : low <= normal . x <= high}, normal != 0, low < high ((normal . x - low)(normal . x - high)).
  static Quadric slab(const Vector3& normal, const Rational& low, const Rational& high);
  /// The image of q's solid under x = L u + t, L invertible: the same type, the matrix H^-T Q H^-1.
  static Quadric from_map(const Quadric& q, const Matrix3& linear, const Vector3& translation);

  QuadricType type() const { return type_; }
  /// The exact matrix, sign-normalized (built on first use for a quadric made from doubles).
  const Matrix4& matrix() const { return m_.matrix(); }
  /// The matrix as doubles when every entry is exactly a double.
  std::optional<DoubleMatrix4> doubles() const { return m_.doubles(); }

 private:
  friend const detail::QuadricMatrix& storage_of(const Quadric& q) { return q.m_; }
  Quadric(detail::QuadricMatrix m, QuadricType type) : m_(std::move(m)), type_(type) {}
  detail::QuadricMatrix m_;
  QuadricType type_;
};

}  // namespace relpos
