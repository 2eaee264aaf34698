// Quadrics as symmetric 4x4 rational matrices, their exact affine type, and the two validated input
// types of relpos: Ellipsoid and Paraboloid (math.md §1; paper section 2.1).
//
// A quadric is X^T Q X = 0 with X = (x, y, z, 1)^T and Q = [[Q3, q], [q^T, q0]]. Interior points are
// those with X^T Q X < 0; constructors negate a matrix given with the other orientation, so that an
// Ellipsoid always has Q3 positive definite and det Q < 0, and a Paraboloid has Q3 positive
// semidefinite of rank 2 and det Q < 0 (inside the cup is interior).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "relpos/internal/quadric_matrix.hpp"
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

/// Exact rotation matrix R(q)/|q|^2 of a non-zero quaternion.
Matrix3 rotation_from_quaternion(const Quaternion& q);

/// A validated ellipsoid, sign-normalized: M = Q3 positive definite, det E < 0.
class Ellipsoid {
 public:
  /// Throws InputError naming what the matrix is when it is not a real ellipsoid.
  static Ellipsoid from_matrix(const Matrix4& e);
  /// Row-major 4x4 doubles, each taken exactly: the same validation and InputError messages as
  /// from_matrix (NaN and infinities are refused through exact_rational's message). The shape is
  /// decided in doubles with certified error bounds (intervals), exactly only when they cannot
  /// decide; the exact matrix() is built only when an exact stage first asks for it.
  static Ellipsoid from_doubles(const DoubleMatrix4& e);
  static Ellipsoid from_coefficients(const Coefficients10& c);
  /// Sphere |x - centre| = radius, radius > 0.
  static Ellipsoid sphere(const Vector3& centre, const Rational& radius);
  /// The same from doubles, each taken exactly through exact_rational (InputError on NaN or
  /// infinity; a braced list of numbers such as {0, 0, 1.5} picks this overload, so no double ever
  /// reaches Rational's implicit constructor).
  static Ellipsoid sphere(const std::array<double, 3>& centre, double radius);
  /// Semi-axes (positive) along the columns of the rotation R(q)/|q|^2, centred at `centre`.
  static Ellipsoid from_axes(const Vector3& centre, const Vector3& semi_axes, const Quaternion& rotation);
  /// The same from doubles (each exact through exact_rational; InputError on NaN or infinity).
  static Ellipsoid from_axes(const std::array<double, 3>& centre, const std::array<double, 3>& semi_axes,
                             const std::array<double, 4>& rotation);
  /// Semi-axes along the columns of an exactly orthogonal matrix (checked exactly).
  static Ellipsoid from_axes(const Vector3& centre, const Vector3& semi_axes, const Matrix3& rotation);
  /// The image of the unit ball under x = centre + L u, L invertible.
  static Ellipsoid from_map(const Vector3& centre, const Matrix3& linear);

  /// This ellipsoid moved by d (its centre becomes centre + d): E' = T^T E T, T = [[I, -d], [0, 1]],
  /// so e' = e - M d and e0' = e0 - 2 e.d + d^T M d, exactly. No validation: a translate of an
  /// ellipsoid is one (from_matrix costs tens of microseconds; this a few).
  Ellipsoid translated(const Vector3& d) const;

  /// The exact matrix (built on first use for a quadric made from doubles).
  const Matrix4& matrix() const { return m_.matrix(); }
  /// The matrix as doubles when every entry is exactly a double (enables the static filter).
  std::optional<DoubleMatrix4> doubles() const { return m_.doubles(); }

 private:
  /// The storage of the matrix (internal/quadric_matrix.hpp), found by argument-dependent lookup.
  friend const detail::QuadricMatrix& storage_of(const Ellipsoid& q) { return q.m_; }
  friend Ellipsoid detail::make_ellipsoid(detail::QuadricMatrix m);
  friend struct detail::QuadricAccess;
  explicit Ellipsoid(Matrix4 m) : m_(std::move(m)) {}
  explicit Ellipsoid(const DoubleMatrix4& d) : m_(d) {}
  explicit Ellipsoid(detail::QuadricMatrix m) : m_(std::move(m)) {}
  detail::QuadricMatrix m_;
};

/// A validated elliptic paraboloid, sign-normalized: A = Q3 positive semidefinite of rank 2, det P < 0.
class Paraboloid {
 public:
  static Paraboloid from_matrix(const Matrix4& p);
  /// Row-major 4x4 doubles, each taken exactly; as Ellipsoid::from_doubles (the rank-2 test of the
  /// 3x3 block is an exact zero test of its determinant on floating-point expansions).
  static Paraboloid from_doubles(const DoubleMatrix4& p);
  static Paraboloid from_coefficients(const Coefficients10& c);
  /// x'^2/a^2 + y'^2/b^2 = z' in the frame with origin `vertex` and axes the columns of R(q)/|q|^2
  /// (the cup opens along the third column). a, b > 0.
  static Paraboloid standard(const Vector3& vertex, const Rational& a, const Rational& b,
                             const Quaternion& rotation = {Rational(1), Rational(0), Rational(0), Rational(0)});
  /// The same from doubles (each exact through exact_rational; InputError on NaN or infinity).
  static Paraboloid standard(const std::array<double, 3>& vertex, double a, double b,
                             const std::array<double, 4>& rotation = {1.0, 0.0, 0.0, 0.0});
  /// The image of z = x^2 + y^2 under x = T u + t, T invertible.
  static Paraboloid from_map(const Matrix3& linear, const Vector3& translation);

  /// The exact matrix (built on first use for a quadric made from doubles).
  const Matrix4& matrix() const { return m_.matrix(); }
  /// The matrix as doubles when every entry is exactly a double (enables the static filter).
  std::optional<DoubleMatrix4> doubles() const { return m_.doubles(); }

 private:
  /// The storage of the matrix (internal/quadric_matrix.hpp), found by argument-dependent lookup.
  friend const detail::QuadricMatrix& storage_of(const Paraboloid& q) { return q.m_; }
  friend Paraboloid detail::make_paraboloid(detail::QuadricMatrix m);
  friend struct detail::QuadricAccess;
  explicit Paraboloid(Matrix4 m) : m_(std::move(m)) {}
  explicit Paraboloid(const DoubleMatrix4& d) : m_(d) {}
  explicit Paraboloid(detail::QuadricMatrix m) : m_(std::move(m)) {}
  detail::QuadricMatrix m_;
};

namespace detail {

/// What the library's own code may do with a quadric that its users may not, on this floor: build
/// one from doubles before its shape is certified and negate their orientation in place
/// (decide_position on 32 doubles certifies the shape from the pair's pencil, classify.hpp).
struct QuadricAccess {
  /// The quadric from_doubles builds, without its shape test: the caller certifies the shape.
  template <class Q>
  static Q from_doubles_unchecked(const DoubleMatrix4& d) {
    return Q(d);
  }
  static QuadricMatrix& storage(Ellipsoid& e) { return e.m_; }
  static QuadricMatrix& storage(Paraboloid& p) { return p.m_; }
};

}  // namespace detail

/// Size limit on the *normalized* forms of a pair: each matrix divided by its own content (times the
/// lcm of its denominators, then divided by the gcd of the resulting integers: its primitive integer
/// form, unchanged by any rescaling of that matrix alone) must have entries of at most this many
/// bits. A safe default: beyond it one pair's exact evidence takes from a tenth of a second to
/// minutes (doc/cli.md, Limits, measured); a caller can raise it with SizeLimit.
inline constexpr std::size_t kMaxNormalizedBits = 4096;

/// The size limit a call applies (an options argument of classify, decide_position, the batch
/// lines and the scenes): at least kMaxNormalizedBits, which every matrix of doubles and every
/// number of the fast reader is known to pass without a check (`relpos ... --max-bits N`, the
/// Python package's max_bits).
struct SizeLimit {
  std::size_t max_bits = kMaxNormalizedBits;
};

}  // namespace relpos
