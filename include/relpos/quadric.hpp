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
/// filter (static_filter.hpp). A positive scaling changes no decision (math.md §1).
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

class Ellipsoid;
class Paraboloid;

namespace detail {

/// Certified double enclosures lo[i] <= entry i <= hi[i] of a matrix (row-major) whose entries are
/// not all doubles: the filters' input for a quadric read from decimal text.
struct EnclosureMatrix4 {
  DoubleMatrix4 lo{}, hi{};
};

/// Builds the exact matrix of a quadric on first use (for a quadric read from text: the exact
/// parse of that text, run only when an exact stage or the evidence asks for the rationals).
class ExactSource {
 public:
  virtual ~ExactSource() = default;
  virtual Matrix4 build() const = 0;
};

/// The matrix of a validated quadric: exact rationals, and the doubles when every entry is one.
/// A quadric made from doubles (from_doubles) builds its rationals only on first use by an exact
/// stage (thread-safe: a quadric shared by several threads materializes once; copies share it);
/// so does one made from enclosures and an ExactSource.
class QuadricMatrix {
 public:
  explicit QuadricMatrix(Matrix4 m);
  /// Entries known by enclosures (not all lo == hi) and built exactly by `source` on first use.
  /// The caller proves the shape, the sign normalization and the size limit (within_size_limit()).
  QuadricMatrix(const EnclosureMatrix4& enclosure, std::shared_ptr<const ExactSource> source);
  /// From doubles that are all finite (checked by the caller); no heap allocation.
  explicit QuadricMatrix(const DoubleMatrix4& d);
  /// The same with d's power_of_two_normalized copy already computed (by the caller's filter).
  QuadricMatrix(const DoubleMatrix4& d, const std::optional<DoubleMatrix4>& normalized);
  QuadricMatrix(const QuadricMatrix& o)
      : d_(o.d_), n_(o.n_), enclosure_(o.enclosure_), source_(o.source_), m_(std::atomic_load(&o.m_)) {}
  /// Moves take the matrix without atomic operations: a quadric being moved is not shared (vectors
  /// of quadrics grow by moves, not by copies).
  QuadricMatrix(QuadricMatrix&& o) noexcept
      : d_(std::move(o.d_)),
        n_(std::move(o.n_)),
        enclosure_(std::move(o.enclosure_)),
        source_(std::move(o.source_)),
        m_(std::move(o.m_)) {}
  QuadricMatrix& operator=(QuadricMatrix&& o) noexcept {
    d_ = std::move(o.d_);
    n_ = std::move(o.n_);
    enclosure_ = std::move(o.enclosure_);
    source_ = std::move(o.source_);
    m_ = std::move(o.m_);
    return *this;
  }
  QuadricMatrix& operator=(const QuadricMatrix& o) {
    if (this != &o) {
      d_ = o.d_;
      n_ = o.n_;
      enclosure_ = o.enclosure_;
      source_ = o.source_;
      std::atomic_store(&m_, std::atomic_load(&o.m_));
    }
    return *this;
  }
  const Matrix4& matrix() const {
    const Matrix4* m = std::atomic_load(&m_).get();
    return m ? *m : materialize();
  }
  const std::optional<DoubleMatrix4>& doubles() const { return d_; }
  const std::optional<DoubleMatrix4>& filter_doubles() const { return n_; }
  /// Enclosures of the entries when the quadric was made from them (nullopt otherwise).
  const std::optional<EnclosureMatrix4>& enclosure() const { return enclosure_; }
  /// True when the primitive integer form is known to be within kMaxNormalizedBits without
  /// building it: doubles, or a source whose reader bounds its numbers.
  bool within_size_limit() const { return d_.has_value() || source_ != nullptr; }

 private:
  const Matrix4& materialize() const;
  std::optional<DoubleMatrix4> d_, n_;
  std::optional<EnclosureMatrix4> enclosure_;
  std::shared_ptr<const ExactSource> source_;
  mutable std::shared_ptr<const Matrix4> m_;
};

/// A quadric whose shape and sign normalization the caller has certified (src/io's fast reader).
Ellipsoid make_ellipsoid(QuadricMatrix m);
Paraboloid make_paraboloid(QuadricMatrix m);

}  // namespace detail

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
  const std::optional<DoubleMatrix4>& doubles() const { return m_.doubles(); }
  /// doubles(), power-of-two normalized once for the static filter (cached: a quadric is usually
  /// classified against many others).
  const std::optional<DoubleMatrix4>& filter_doubles() const { return m_.filter_doubles(); }
  /// The storage of the matrix (its enclosures, whether its size is known to be within the limit).
  const detail::QuadricMatrix& storage() const { return m_; }

 private:
  friend Ellipsoid detail::make_ellipsoid(detail::QuadricMatrix m);
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
  const std::optional<DoubleMatrix4>& doubles() const { return m_.doubles(); }
  /// doubles(), power-of-two normalized once for the static filter (cached: a quadric is usually
  /// classified against many others).
  const std::optional<DoubleMatrix4>& filter_doubles() const { return m_.filter_doubles(); }
  /// The storage of the matrix (its enclosures, whether its size is known to be within the limit).
  const detail::QuadricMatrix& storage() const { return m_; }

 private:
  friend Paraboloid detail::make_paraboloid(detail::QuadricMatrix m);
  explicit Paraboloid(Matrix4 m) : m_(std::move(m)) {}
  explicit Paraboloid(const DoubleMatrix4& d) : m_(d) {}
  explicit Paraboloid(detail::QuadricMatrix m) : m_(std::move(m)) {}
  detail::QuadricMatrix m_;
};

/// Size limit on the *normalized* forms of a pair: each matrix divided by its own content (times the
/// lcm of its denominators, then divided by the gcd of the resulting integers: its primitive integer
/// form, unchanged by any rescaling of that matrix alone) must have entries of at most this many
/// bits. Beyond it, exact evidence becomes slow (doc/cli.md, Limits).
inline constexpr std::size_t kMaxNormalizedBits = 4096;

/// Bits of the largest entry of the primitive integer form of m (0 for the zero matrix).
std::size_t normalized_bits(const Matrix4& m);

/// max(normalized_bits(e), normalized_bits(p)): independent of how either matrix was scaled.
std::size_t normalized_pair_bits(const Ellipsoid& e, const Paraboloid& p);

/// Throws InputError ("numbers too large: ...", naming kMaxNormalizedBits) when
/// normalized_pair_bits(e, p) > kMaxNormalizedBits.
void check_normalized_pair_size(const Ellipsoid& e, const Paraboloid& p);

}  // namespace relpos
