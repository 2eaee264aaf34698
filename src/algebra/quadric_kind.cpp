// The exact affine type of a quadric (classify_quadric): the inertia of its 3x3 block and of the
// whole matrix from Descartes' rule on characteristic polynomials (exact for real symmetric
// matrices), the names the error messages give each type, and the refusals of a matrix of another
// type than the one asked for (quadric_kind.hpp).
#include "algebra/quadric_kind.hpp"

#include <array>
#include <string>
#include <utility>

#include "algebra/integer_form.hpp"
#include "relpos/error.hpp"
#include "relpos/quadric.hpp"

namespace relpos {
namespace {

template <class NT>
int sgn(const NT& q) {
  return q > 0 ? 1 : (q < 0 ? -1 : 0);
}

/// Determinant of the principal submatrix of q on the given index set (Laplace, n <= 4).
template <class NT, class M>
NT principal_minor(const M& q, const int* idx, int n) {
  if (n == 0) return NT(1);
  if (n == 1) return q(idx[0], idx[0]);
  NT det(0);
  // expand along the first row of the submatrix
  for (int c = 0; c < n; ++c) {
    int rows[3], cols[3], k = 0;
    for (int j = 0; j < n; ++j)
      if (j != c) cols[k++] = idx[j];
    for (int i = 1; i < n; ++i) rows[i - 1] = idx[i];
    // minor on rows x cols (not principal in general): small explicit cases
    NT m;
    if (n == 2) {
      m = q(rows[0], cols[0]);
    } else if (n == 3) {
      m = q(rows[0], cols[0]) * q(rows[1], cols[1]) - q(rows[0], cols[1]) * q(rows[1], cols[0]);
    } else {
      m = q(rows[0], cols[0]) *
              (q(rows[1], cols[1]) * q(rows[2], cols[2]) - q(rows[1], cols[2]) * q(rows[2], cols[1])) -
          q(rows[0], cols[1]) *
              (q(rows[1], cols[0]) * q(rows[2], cols[2]) - q(rows[1], cols[2]) * q(rows[2], cols[0])) +
          q(rows[0], cols[2]) * (q(rows[1], cols[0]) * q(rows[2], cols[1]) - q(rows[1], cols[1]) * q(rows[2], cols[0]));
    }
    NT term = q(idx[0], idx[c]) * m;
    det += (c % 2 == 0) ? term : -term;
  }
  return det;
}

/// Inertia (positive, negative) of the leading n x n block of a symmetric matrix, and its determinant.
/// The characteristic polynomial of a real symmetric matrix has only real roots, so Descartes' rule
/// of signs counts its positive and negative roots exactly. det(xI - S) = sum_k (-1)^k E_k x^(n-k),
/// E_k the sum of the k x k principal minors (E_n the determinant).
struct Inertia {
  int positive, negative, det_sign;
};

template <class NT, class M>
Inertia inertia(const M& q, int n) {
  std::array<NT, 5> e{};  // E_0..E_n
  for (int mask = 0; mask < (1 << n); ++mask) {
    int idx[4], k = 0;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) idx[k++] = i;
    e[static_cast<std::size_t>(k)] += principal_minor<NT>(q, idx, k);
  }
  auto variations = [&](bool negate_x) {
    int count = 0, last = 0;
    for (int k = 0; k <= n; ++k) {
      // coefficient of x^(n-k): (-1)^k E_k; evaluated at -x it gains (-1)^(n-k)
      int s = sgn(e[static_cast<std::size_t>(k)]) * ((k % 2) ? -1 : 1);
      if (negate_x && ((n - k) % 2)) s = -s;
      if (s == 0) continue;
      if (last != 0 && s != last) ++count;
      last = s;
    }
    return count;
  };
  return {variations(false), variations(true), sgn(e[static_cast<std::size_t>(n)])};
}

void require_symmetric(const Matrix4& q) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (q(i, j) != q(j, i))
        throw InputError("matrix is not symmetric: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) +
                         ") = " + to_string(q(i, j)) + " but entry (" + std::to_string(j + 1) + "," +
                         std::to_string(i + 1) + ") = " + to_string(q(j, i)));
}

}  // namespace

std::string to_string(QuadricKind kind) {
  switch (kind) {
    case QuadricKind::Ellipsoid:
      return "ellipsoid";
    case QuadricKind::ImaginaryEllipsoid:
      return "imaginary ellipsoid (no real point)";
    case QuadricKind::Point:
      return "single point (degenerate ellipsoid, det = 0)";
    case QuadricKind::HyperboloidOneSheet:
      return "hyperboloid of one sheet";
    case QuadricKind::HyperboloidTwoSheets:
      return "hyperboloid of two sheets";
    case QuadricKind::Cone:
      return "cone";
    case QuadricKind::EllipticParaboloid:
      return "elliptic paraboloid";
    case QuadricKind::HyperbolicParaboloid:
      return "hyperbolic paraboloid";
    case QuadricKind::EllipticCylinder:
      return "elliptic cylinder";
    case QuadricKind::ImaginaryEllipticCylinder:
      return "imaginary elliptic cylinder (no real point)";
    case QuadricKind::Line:
      return "line (pair of imaginary planes)";
    case QuadricKind::HyperbolicCylinder:
      return "hyperbolic cylinder";
    case QuadricKind::IntersectingPlanes:
      return "pair of intersecting planes";
    case QuadricKind::ParabolicCylinder:
      return "parabolic cylinder";
    case QuadricKind::ParallelPlanes:
      return "pair of parallel planes";
    case QuadricKind::ImaginaryParallelPlanes:
      return "pair of imaginary parallel planes (no real point)";
    case QuadricKind::DoublePlane:
      return "double plane";
    case QuadricKind::NotQuadratic:
      return "equation without quadratic terms (a plane or nothing)";
  }
  return "unknown quadric";
}

namespace detail {
namespace {

/// The name of a type with its article, as a message gives it.
std::string found(QuadricKind k) {
  std::string s = to_string(k);
  const char* article = (s[0] == 'a' || s[0] == 'e' || s[0] == 'i' || s[0] == 'o' || s[0] == 'u') ? "an " : "a ";
  return article + s;
}

}  // namespace

void refuse_as_ellipsoid(QuadricKind k) {
  if (k == QuadricKind::EllipticParaboloid)
    throw InputError(
        "not an ellipsoid: the matrix describes an elliptic paraboloid (ellipsoid and paraboloid swapped?)");
  throw InputError("not an ellipsoid: the matrix describes " + found(k));
}

void refuse_as_paraboloid(QuadricKind k) {
  if (k == QuadricKind::Ellipsoid)
    throw InputError(
        "not an elliptic paraboloid: the matrix describes an ellipsoid (ellipsoid and paraboloid swapped?)");
  throw InputError("not an elliptic paraboloid: the matrix describes " + found(k));
}

}  // namespace detail

QuadricKind classify_quadric(const Matrix4& q) {
  require_symmetric(q);
  // The signs on the matrix's primitive integer form (a positive multiple): products of integers,
  // no gcd, and a matrix scaled by 10^300 or 10^-300 costs what the unscaled one does.
  Integer l, g;  // fresh: written through mpz()
  detail::forms::MatrixOf<Integer> z = detail::forms::integer_form(q, l);
  for (const Integer& x : z.a)
    if (mpz_cmp_ui(g.mpz(), 1) != 0) mpz_gcd(g.mpz(), g.mpz(), x.mpz());  // stops at 1, as most do at once
  if (mpz_cmp_ui(g.mpz(), 1) > 0) {
    detail::forms::MatrixOf<Integer> w;  // fresh integers (an entry of z may share its value with another)
    for (std::size_t i = 0; i < 16; ++i) mpz_divexact(w.a[i].mpz(), z.a[i].mpz(), g.mpz());
    z = w;
  }
  const Inertia i3 = inertia<Integer>(z, 3), i4 = inertia<Integer>(z, 4);
  int p3 = i3.positive, n3 = i3.negative, p4 = i4.positive, n4 = i4.negative;
  if (p3 < n3) {  // orientation does not change the type: normalize to p3 >= n3
    std::swap(p3, n3);
    std::swap(p4, n4);
  }
  const int rank4 = p4 + n4;
  const int s = i4.det_sign;
  if (p3 == 3) return s < 0 ? QuadricKind::Ellipsoid : (s > 0 ? QuadricKind::ImaginaryEllipsoid : QuadricKind::Point);
  if (p3 == 2 && n3 == 1)
    return s > 0 ? QuadricKind::HyperboloidOneSheet : (s < 0 ? QuadricKind::HyperboloidTwoSheets : QuadricKind::Cone);
  if (p3 == 2 && n3 == 0) {
    if (rank4 == 4) return QuadricKind::EllipticParaboloid;
    if (rank4 == 3)
      return (n4 == 1 || p4 == 1) ? QuadricKind::EllipticCylinder : QuadricKind::ImaginaryEllipticCylinder;
    return QuadricKind::Line;
  }
  if (p3 == 1 && n3 == 1) {
    if (rank4 == 4) return QuadricKind::HyperbolicParaboloid;
    if (rank4 == 3) return QuadricKind::HyperbolicCylinder;
    return QuadricKind::IntersectingPlanes;
  }
  if (p3 == 1) {
    if (rank4 == 3) return QuadricKind::ParabolicCylinder;
    if (rank4 == 2) return (p4 == 1 && n4 == 1) ? QuadricKind::ParallelPlanes : QuadricKind::ImaginaryParallelPlanes;
    return QuadricKind::DoublePlane;
  }
  return QuadricKind::NotQuadratic;
}

}  // namespace relpos
