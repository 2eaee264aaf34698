// The validated Quadric (include/relpos/general_quadric.hpp; math.md §14): exact type, sign
// normalization, refusal of degenerate and imaginary quadrics, and the geometric forms.
#include <utility>

#include "algebra/coefficients.hpp"
#include "algebra/matrix4.hpp"
#include "algebra/shape_filter.hpp"
#include "relpos/error.hpp"
#include "relpos/general_quadric.hpp"

namespace relpos {
namespace {

using detail::negated;

int sgn(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

/// (positive, negative) eigenvalues of the symmetric 3x3 block B: Descartes' rule on the
/// characteristic polynomial x^3 - E1 x^2 + E2 x - E3 of a symmetric matrix (all roots real) counts
/// them exactly (math.md §1).
std::pair<int, int> inertia3(const Matrix4& q) {
  const Rational e1 = q(0, 0) + q(1, 1) + q(2, 2);
  const Rational e2 = q(0, 0) * q(1, 1) - q(0, 1) * q(1, 0) + q(0, 0) * q(2, 2) - q(0, 2) * q(2, 0) +
                      q(1, 1) * q(2, 2) - q(1, 2) * q(2, 1);
  const Rational e3 = q(0, 0) * (q(1, 1) * q(2, 2) - q(1, 2) * q(2, 1)) -
                      q(0, 1) * (q(1, 0) * q(2, 2) - q(1, 2) * q(2, 0)) +
                      q(0, 2) * (q(1, 0) * q(2, 1) - q(1, 1) * q(2, 0));
  auto variations = [](std::array<int, 4> s) {
    int count = 0, last = 0;
    for (int x : s) {
      if (x == 0) continue;
      if (last != 0 && x != last) ++count;
      last = x;
    }
    return count;
  };
  const int positive = variations({1, -sgn(e1), sgn(e2), -sgn(e3)});
  const int negative = variations({-1, -sgn(e1), -sgn(e2), -sgn(e3)});
  return {positive, negative};
}

std::string found(QuadricKind k) {
  const std::string s = to_string(k);
  const char c = s[0];
  return (c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u' ? "an " : "a ") + s;
}

/// The type of a real non-degenerate quadric, or the InputError naming what the matrix is.
QuadricType type_of(const Matrix4& q) {
  const QuadricKind k = classify_quadric(q);  // symmetric, or InputError
  switch (k) {
    case QuadricKind::Ellipsoid:
      return QuadricType::Ellipsoid;
    case QuadricKind::HyperboloidOneSheet:
      return QuadricType::HyperboloidOneSheet;
    case QuadricKind::HyperboloidTwoSheets:
      return QuadricType::HyperboloidTwoSheets;
    case QuadricKind::Cone:
      return QuadricType::Cone;
    case QuadricKind::EllipticParaboloid:
      return QuadricType::EllipticParaboloid;
    case QuadricKind::HyperbolicParaboloid:
      return QuadricType::HyperbolicParaboloid;
    case QuadricKind::EllipticCylinder:
      return QuadricType::EllipticCylinder;
    case QuadricKind::HyperbolicCylinder:
      return QuadricType::HyperbolicCylinder;
    case QuadricKind::ParabolicCylinder:
      return QuadricType::ParabolicCylinder;
    case QuadricKind::ParallelPlanes:
      return QuadricType::Slab;
    case QuadricKind::NotQuadratic:
      if (q(0, 3) != 0 || q(1, 3) != 0 || q(2, 3) != 0) return QuadricType::HalfSpace;
      throw InputError(
          "not a quadric solid: the matrix has no quadratic and no linear part (a constant equation: no surface)");
    default:
      throw InputError("not a quadric solid: the matrix describes " + found(k) +
                       " (degenerate or imaginary; relpos accepts ellipsoids, hyperboloids, cones, paraboloids, "
                       "cylinders, slabs and half-spaces)");
  }
}

void require_positive(const Rational& x, const char* what) {
  if (x <= 0) throw InputError(std::string(what) + " must be positive, got " + to_string(x));
}

/// Q_world = T^T Q_local T for the frame x = R u + c (R orthogonal: u = R^T (x - c), T = [[R^T, -R^T c], [0, 1]]).
Matrix4 placed(const Matrix4& local, const Quaternion& rotation, const Vector3& c) {
  const Matrix3 r = rotation_from_quaternion(rotation);
  Matrix4 t;
  for (int i = 0; i < 3; ++i) {
    Rational s(0);
    for (int j = 0; j < 3; ++j) {
      t(i, j) = r(j, i);
      s += r(j, i) * c[static_cast<std::size_t>(j)];
    }
    t(i, 3) = -s;
  }
  t(3, 3) = Rational(1);
  Matrix4 lt, out;  // local * t, then t^T (local t)
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k)
        if (!CGAL::is_zero(local(i, k)) && !CGAL::is_zero(t(k, j))) s += local(i, k) * t(k, j);
      lt(i, j) = s;
    }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k)
        if (!CGAL::is_zero(t(k, i)) && !CGAL::is_zero(lt(k, j))) s += t(k, i) * lt(k, j);
      out(i, j) = s;
    }
  return out;
}

Matrix4 diagonal(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  Matrix4 m;
  m(0, 0) = a;
  m(1, 1) = b;
  m(2, 2) = c;
  m(3, 3) = d;
  return m;
}

Rational inverse_square(const Rational& a) { return Rational(1) / (a * a); }

}  // namespace

std::string to_string(QuadricType type) {
  switch (type) {
    case QuadricType::Ellipsoid:
      return "ellipsoid";
    case QuadricType::HyperboloidOneSheet:
      return "hyperboloid of one sheet";
    case QuadricType::HyperboloidTwoSheets:
      return "hyperboloid of two sheets";
    case QuadricType::Cone:
      return "elliptic cone";
    case QuadricType::EllipticParaboloid:
      return "elliptic paraboloid";
    case QuadricType::HyperbolicParaboloid:
      return "hyperbolic paraboloid";
    case QuadricType::EllipticCylinder:
      return "elliptic cylinder";
    case QuadricType::HyperbolicCylinder:
      return "hyperbolic cylinder";
    case QuadricType::ParabolicCylinder:
      return "parabolic cylinder";
    case QuadricType::Slab:
      return "slab";
    case QuadricType::HalfSpace:
      return "half-space";
  }
  return "unknown quadric type";
}

Quadric Quadric::from_matrix(const Matrix4& q) {
  const QuadricType type = type_of(q);
  const auto [positive, negative] = inertia3(q);
  // More negative than positive eigenvalues in B: the other orientation (math.md §14); a tie keeps
  // the sign as given.
  return Quadric(detail::QuadricMatrix(negative > positive ? negated(q) : q), type);
}

Quadric Quadric::from_doubles(const DoubleMatrix4& d) {
  // An ellipsoid or an elliptic paraboloid certified by the filtered shape tests of Ellipsoid and
  // Paraboloid (src/algebra/shape_filter.hpp) needs no rationals; anything else takes the exact
  // type (and names what it is when refused).
  detail::QuadricMatrix m(d);
  const DoubleMatrix4* normalized = m.filter_doubles();
  if (const int o = detail::shape_filter::certified_ellipsoid_in_doubles(normalized)) {
    if (o < 0) m.negate_doubles();
    return Quadric(std::move(m), QuadricType::Ellipsoid);
  }
  if (normalized)
    if (const int o = detail::shape_filter::certified_paraboloid_in_doubles(d, normalized)) {
      if (o < 0) m.negate_doubles();
      return Quadric(std::move(m), QuadricType::EllipticParaboloid);
    }
  Matrix4 exact;
  for (std::size_t i = 0; i < 16; ++i) exact.a[i] = exact_rational(d[i]);
  return from_matrix(exact);
}

Quadric Quadric::from_coefficients(const Coefficients10& c) { return from_matrix(detail::matrix_from_coefficients(c)); }

Quadric Quadric::of(const Ellipsoid& e) { return Quadric(storage_of(e), QuadricType::Ellipsoid); }
Quadric Quadric::of(const Paraboloid& p) { return Quadric(storage_of(p), QuadricType::EllipticParaboloid); }

// The forms below are congruences of a normalized local matrix: the inertia of B and of Q is kept
// (Sylvester), so each is valid and sign-normalized by construction.

Quadric Quadric::sphere(const Vector3& centre, const Rational& radius) {
  require_positive(radius, "sphere radius");
  return ellipsoid(centre, {radius, radius, radius});
}

Quadric Quadric::ellipsoid(const Vector3& centre, const Vector3& ax, const Quaternion& rotation) {
  for (const Rational& a : ax) require_positive(a, "ellipsoid semi-axis");
  const Matrix4 local = diagonal(inverse_square(ax[0]), inverse_square(ax[1]), inverse_square(ax[2]), Rational(-1));
  return Quadric(detail::QuadricMatrix(placed(local, rotation, centre)), QuadricType::Ellipsoid);
}

Quadric Quadric::hyperboloid_one_sheet(const Vector3& centre, const Vector3& ax, const Quaternion& rotation) {
  for (const Rational& a : ax) require_positive(a, "hyperboloid semi-axis");
  const Matrix4 local = diagonal(inverse_square(ax[0]), inverse_square(ax[1]), -inverse_square(ax[2]), Rational(-1));
  return Quadric(detail::QuadricMatrix(placed(local, rotation, centre)), QuadricType::HyperboloidOneSheet);
}

Quadric Quadric::hyperboloid_two_sheets(const Vector3& centre, const Vector3& ax, const Quaternion& rotation) {
  for (const Rational& a : ax) require_positive(a, "hyperboloid semi-axis");
  const Matrix4 local = diagonal(inverse_square(ax[0]), inverse_square(ax[1]), -inverse_square(ax[2]), Rational(1));
  return Quadric(detail::QuadricMatrix(placed(local, rotation, centre)), QuadricType::HyperboloidTwoSheets);
}

Quadric Quadric::cone(const Vector3& apex, const Rational& a, const Rational& b, const Quaternion& rotation) {
  require_positive(a, "cone parameter a");
  require_positive(b, "cone parameter b");
  const Matrix4 local = diagonal(inverse_square(a), inverse_square(b), Rational(-1), Rational(0));
  return Quadric(detail::QuadricMatrix(placed(local, rotation, apex)), QuadricType::Cone);
}

Quadric Quadric::elliptic_paraboloid(const Vector3& vertex, const Rational& a, const Rational& b,
                                     const Quaternion& rotation) {
  require_positive(a, "paraboloid parameter a");
  require_positive(b, "paraboloid parameter b");
  Matrix4 local = diagonal(inverse_square(a), inverse_square(b), Rational(0), Rational(0));
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Quadric(detail::QuadricMatrix(placed(local, rotation, vertex)), QuadricType::EllipticParaboloid);
}

Quadric Quadric::hyperbolic_paraboloid(const Vector3& vertex, const Rational& a, const Rational& b,
                                       const Quaternion& rotation) {
  require_positive(a, "paraboloid parameter a");
  require_positive(b, "paraboloid parameter b");
  Matrix4 local = diagonal(inverse_square(a), -inverse_square(b), Rational(0), Rational(0));
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Quadric(detail::QuadricMatrix(placed(local, rotation, vertex)), QuadricType::HyperbolicParaboloid);
}

Quadric Quadric::elliptic_cylinder(const Vector3& centre, const Rational& a, const Rational& b,
                                   const Quaternion& rotation) {
  require_positive(a, "cylinder parameter a");
  require_positive(b, "cylinder parameter b");
  const Matrix4 local = diagonal(inverse_square(a), inverse_square(b), Rational(0), Rational(-1));
  return Quadric(detail::QuadricMatrix(placed(local, rotation, centre)), QuadricType::EllipticCylinder);
}

Quadric Quadric::hyperbolic_cylinder(const Vector3& centre, const Rational& a, const Rational& b,
                                     const Quaternion& rotation) {
  require_positive(a, "cylinder parameter a");
  require_positive(b, "cylinder parameter b");
  const Matrix4 local = diagonal(inverse_square(a), -inverse_square(b), Rational(0), Rational(-1));
  return Quadric(detail::QuadricMatrix(placed(local, rotation, centre)), QuadricType::HyperbolicCylinder);
}

Quadric Quadric::parabolic_cylinder(const Vector3& vertex, const Rational& a, const Quaternion& rotation) {
  require_positive(a, "cylinder parameter a");
  Matrix4 local = diagonal(inverse_square(a), Rational(0), Rational(0), Rational(0));
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Quadric(detail::QuadricMatrix(placed(local, rotation, vertex)), QuadricType::ParabolicCylinder);
}

Quadric Quadric::half_space(const Vector3& n, const Rational& offset) {
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) throw InputError("half-space normal must not be zero");
  Matrix4 m;
  for (int i = 0; i < 3; ++i) m(i, 3) = m(3, i) = n[static_cast<std::size_t>(i)] / 2;
  m(3, 3) = -offset;
  return Quadric(detail::QuadricMatrix(std::move(m)), QuadricType::HalfSpace);
}

Quadric Quadric::slab(const Vector3& n, const Rational& low, const Rational& high) {
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) throw InputError("slab normal must not be zero");
  if (!(low < high))
    throw InputError("slab bounds must satisfy low < high, got low = " + to_string(low) +
                     ", high = " + to_string(high));
  // (n.x - low)(n.x - high) = (n.x)^2 - (low + high) n.x + low high.
  Matrix4 m;
  const Rational half_sum = (low + high) / 2;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = n[static_cast<std::size_t>(i)] * n[static_cast<std::size_t>(j)];
    m(i, 3) = m(3, i) = -half_sum * n[static_cast<std::size_t>(i)];
  }
  m(3, 3) = low * high;
  return Quadric(detail::QuadricMatrix(std::move(m)), QuadricType::Slab);
}

Quadric Quadric::from_map(const Quadric& q, const Matrix3& l, const Vector3& t) {
  // H^-1 = [[L^-1, -L^-1 t], [0, 1]] with L^-1 = adj(L) / det L.
  Matrix3 adj;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      adj(i, j) = l(r0, c0) * l(r1, c1) - l(r0, c1) * l(r1, c0);
    }
  const Rational det = l(0, 0) * adj(0, 0) + l(0, 1) * adj(1, 0) + l(0, 2) * adj(2, 0);
  if (det == 0) throw InputError("affine map is singular (determinant 0)");
  Matrix4 hi;
  for (int i = 0; i < 3; ++i) {
    Rational s(0);
    for (int j = 0; j < 3; ++j) {
      hi(i, j) = adj(i, j) / det;
      s += hi(i, j) * t[static_cast<std::size_t>(j)];
    }
    hi(i, 3) = -s;
  }
  hi(3, 3) = Rational(1);
  const Matrix4& m = q.matrix();
  Matrix4 mh, out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k) s += m(i, k) * hi(k, j);
      mh(i, j) = s;
    }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k) s += hi(k, i) * mh(k, j);
      out(i, j) = s;
    }
  return Quadric(detail::QuadricMatrix(std::move(out)), q.type());
}

}  // namespace relpos
