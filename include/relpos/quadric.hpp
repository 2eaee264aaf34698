// Quadrics as symmetric 4x4 rational matrices, their exact affine type, and the two validated input
// types of relpos: Ellipsoid and Paraboloid (math.md section 1; paper section 2.1).
//
// A quadric is X^T Q X = 0 with X = (x, y, z, 1)^T and Q = [[Q3, q], [q^T, q0]]. Interior points are
// those with X^T Q X < 0; constructors negate a matrix given with the other orientation, so that an
// Ellipsoid always has Q3 positive definite and det Q < 0, and a Paraboloid has Q3 positive
// semidefinite of rank 2 and det Q < 0 (inside the cup is interior).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "relpos/numbers.hpp"

namespace relpos {

/// Row-major 4x4 matrix of exact rationals.
struct Matrix4 {
  std::array<Rational, 16> a{};
  Rational& operator()(int i, int j) { return a[static_cast<std::size_t>(4 * i + j)]; }
  const Rational& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
  bool operator==(const Matrix4& o) const { return a == o.a; }
};

/// Row-major 3x3 matrix of exact rationals (linear maps, rotations).
struct Matrix3 {
  std::array<Rational, 9> a{};
  Rational& operator()(int i, int j) { return a[static_cast<std::size_t>(3 * i + j)]; }
  const Rational& operator()(int i, int j) const { return a[static_cast<std::size_t>(3 * i + j)]; }
};

using Vector3 = std::array<Rational, 3>;
/// A quaternion (w, x, y, z), not necessarily unit: it stands for the rotation R(q)/|q|^2, which has
/// rational entries whenever the components are rational.
using Quaternion = std::array<Rational, 4>;
/// Coefficients of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J, in that order.
using Coefficients10 = std::array<Rational, 10>;

/// Row-major 4x4 matrix of doubles.
using DoubleMatrix4 = std::array<double, 16>;

/// The entries as doubles if each one is exactly representable, else nullopt.
std::optional<DoubleMatrix4> exact_doubles(const Matrix4& m);

/// m times the power of two that brings its largest entry into [1/2, 1) (exact), or nullopt if a
/// non-zero entry would become subnormal or m is zero or not finite: the input range of the static
/// filter (static_filter.hpp). A positive scaling changes no decision (math.md section 1).
std::optional<DoubleMatrix4> power_of_two_normalized(const std::optional<DoubleMatrix4>& m);

/// Exact affine type of a real quadric surface.
enum class QuadricKind {
  Ellipsoid,
  ImaginaryEllipsoid,
  Point,
  HyperboloidOneSheet,
  HyperboloidTwoSheets,
  Cone,
  EllipticParaboloid,
  HyperbolicParaboloid,
  EllipticCylinder,
  ImaginaryEllipticCylinder,
  Line,
  HyperbolicCylinder,
  IntersectingPlanes,
  ParabolicCylinder,
  ParallelPlanes,
  ImaginaryParallelPlanes,
  DoublePlane,
  NotQuadratic,  ///< no quadratic terms at all: a plane or nothing
};

/// Human-readable name: "hyperboloid of one sheet", "elliptic paraboloid", ...
std::string to_string(QuadricKind kind);

/// The affine type of X^T Q X = 0, decided exactly from the inertia of Q3 and of Q and rank Q.
/// Q must be symmetric (throws InputError otherwise).
QuadricKind classify_quadric(const Matrix4& q);

/// Matrix from the 10 coefficients of the implicit equation (cross terms halved).
Matrix4 matrix_from_coefficients(const Coefficients10& c);

/// Exact rotation matrix R(q)/|q|^2 of a non-zero quaternion.
Matrix3 rotation_from_quaternion(const Quaternion& q);

/// A validated ellipsoid, sign-normalized: M = Q3 positive definite, det E < 0.
class Ellipsoid {
 public:
  /// Throws InputError naming what the matrix is when it is not a real ellipsoid.
  static Ellipsoid from_matrix(const Matrix4& e);
  static Ellipsoid from_coefficients(const Coefficients10& c);
  /// Sphere |x - centre| = radius, radius > 0.
  static Ellipsoid sphere(const Vector3& centre, const Rational& radius);
  /// Semi-axes (positive) along the columns of the rotation R(q)/|q|^2, centred at `centre`.
  static Ellipsoid from_axes(const Vector3& centre, const Vector3& semi_axes, const Quaternion& rotation);
  /// Semi-axes along the columns of an exactly orthogonal matrix (checked exactly).
  static Ellipsoid from_axes(const Vector3& centre, const Vector3& semi_axes, const Matrix3& rotation);
  /// The image of the unit ball under x = centre + L u, L invertible.
  static Ellipsoid from_map(const Vector3& centre, const Matrix3& linear);

  /// This ellipsoid moved by d (its centre becomes centre + d): E' = T^T E T, T = [[I, -d], [0, 1]],
  /// so e' = e - M d and e0' = e0 - 2 e.d + d^T M d, exactly. No validation: a translate of an
  /// ellipsoid is one (from_matrix costs tens of microseconds; this a few).
  Ellipsoid translated(const Vector3& d) const;

  const Matrix4& matrix() const { return m_; }
  /// The matrix as doubles when every entry is exactly a double (enables the static filter).
  const std::optional<DoubleMatrix4>& doubles() const { return d_; }
  /// doubles(), power-of-two normalized once for the static filter (cached: a quadric is usually
  /// classified against many others).
  const std::optional<DoubleMatrix4>& filter_doubles() const { return n_; }

 private:
  explicit Ellipsoid(Matrix4 m) : m_(std::move(m)), d_(exact_doubles(m_)), n_(power_of_two_normalized(d_)) {}
  Matrix4 m_;
  std::optional<DoubleMatrix4> d_, n_;
};

/// A validated elliptic paraboloid, sign-normalized: A = Q3 positive semidefinite of rank 2, det P < 0.
class Paraboloid {
 public:
  static Paraboloid from_matrix(const Matrix4& p);
  static Paraboloid from_coefficients(const Coefficients10& c);
  /// x'^2/a^2 + y'^2/b^2 = z' in the frame with origin `vertex` and axes the columns of R(q)/|q|^2
  /// (the cup opens along the third column). a, b > 0.
  static Paraboloid standard(const Vector3& vertex, const Rational& a, const Rational& b,
                             const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// The image of z = x^2 + y^2 under x = T u + t, T invertible.
  static Paraboloid from_map(const Matrix3& linear, const Vector3& translation);

  const Matrix4& matrix() const { return m_; }
  /// The matrix as doubles when every entry is exactly a double (enables the static filter).
  const std::optional<DoubleMatrix4>& doubles() const { return d_; }
  /// doubles(), power-of-two normalized once for the static filter (cached: a quadric is usually
  /// classified against many others).
  const std::optional<DoubleMatrix4>& filter_doubles() const { return n_; }

 private:
  explicit Paraboloid(Matrix4 m) : m_(std::move(m)), d_(exact_doubles(m_)), n_(power_of_two_normalized(d_)) {}
  Matrix4 m_;
  std::optional<DoubleMatrix4> d_, n_;
};

}  // namespace relpos
