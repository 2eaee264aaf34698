// The validated ellipsoid and paraboloid from exact data: a matrix (the filtered shape test, then
// the exact type), 10 coefficients, a sphere, axes and a rotation, a standard paraboloid, an affine
// map (valid and sign-normalized by construction), and an ellipsoid's exact translate.
#include "relpos/quadric.hpp"

#include <gmp.h>

#include <array>
#include <string>
#include <utility>

#include "algebra/coefficients.hpp"
#include "algebra/forms.hpp"
#include "algebra/matrix4.hpp"
#include "algebra/quadric_kind.hpp"
#include "algebra/shape_filter.hpp"
#include "relpos/error.hpp"

namespace relpos {
namespace {

using detail::negated;

Matrix3 inverse3(const Matrix3& m, const char* what) {
  Matrix3 c;  // cofactor transpose
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      c(i, j) = m(r0, c0) * m(r1, c1) - m(r0, c1) * m(r1, c0);
    }
  Rational det = m(0, 0) * c(0, 0) + m(0, 1) * c(1, 0) + m(0, 2) * c(2, 0);
  if (det == 0) throw InputError(std::string(what) + " is singular (determinant 0)");
  for (auto& x : c.a) x /= det;
  return c;
}

/// Q_world = H^-T Q_local H^-1 for the affine map x = L u + t (H = [[L, t], [0, 1]]).
Matrix4 push_forward(const Matrix4& local, const Matrix3& l, const Vector3& t, const char* what) {
  Matrix3 li = inverse3(l, what);
  Matrix4 hi;  // H^-1 = [[L^-1, -L^-1 t], [0, 1]]
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) hi(i, j) = li(i, j);
    hi(i, 3) = -(li(i, 0) * t[0] + li(i, 1) * t[1] + li(i, 2) * t[2]);
  }
  hi(3, 3) = Rational(1);
  Matrix4 tmp, out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k)
        if (!CGAL::is_zero(local(i, k)) && !CGAL::is_zero(hi(k, j))) s += local(i, k) * hi(k, j);
      tmp(i, j) = s;
    }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k)
        if (!CGAL::is_zero(hi(k, i)) && !CGAL::is_zero(tmp(k, j))) s += hi(k, i) * tmp(k, j);
      out(i, j) = s;
    }
  return out;
}

Matrix3 check_orthogonal(const Matrix3& r) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational s(0);
      for (int k = 0; k < 3; ++k) s += r(k, i) * r(k, j);
      if (s != Rational(i == j ? 1 : 0))
        throw InputError(
            "rotation matrix is not exactly orthogonal (R^T R != I); give the rotation as a quaternion, "
            "which is exact for any rational components, or use the linear-map form");
    }
  return r;
}

template <std::size_t N>
std::array<Rational, N> exact_array(const std::array<double, N>& d) {
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = exact_rational(d[i]);
  return out;
}

/// |c|^2 - r^2 with one reduction instead of a canonicalisation per operation: over the lcm L of
/// the denominators, (sum_i (c_i L)^2 - (r L)^2) / L^2, reduced along L's split (decimal text puts
/// only 2s and 5s there).
Rational squared_norm_minus(const Vector3& c, const Rational& r) {
  Integer l(1), num, t;  // fresh: written through mpz()
  detail::forms::lcm_of_denominators(c.begin(), c.end(), l);
  detail::forms::fold_lcm(l.mpz(), mpq_denref(r.mpq()));
  for (const Rational& x : c) {
    detail::forms::scaled_numerator(x, l, t.mpz());
    mpz_addmul(num.mpz(), t.mpz(), t.mpz());
  }
  detail::forms::scaled_numerator(r, l, t.mpz());
  mpz_submul(num.mpz(), t.mpz(), t.mpz());
  return detail::forms::divided_by_power(num, detail::forms::split_scale(l), 2);
}

}  // namespace

Matrix4 detail::matrix_from_coefficients(const Coefficients10& c) {
  const Rational half(1, 2);
  Matrix4 m;
  m(0, 0) = c[0];
  m(1, 1) = c[1];
  m(2, 2) = c[2];
  m(3, 3) = c[9];
  m(0, 1) = m(1, 0) = c[3] * half;
  m(0, 2) = m(2, 0) = c[4] * half;
  m(1, 2) = m(2, 1) = c[5] * half;
  m(0, 3) = m(3, 0) = c[6] * half;
  m(1, 3) = m(3, 1) = c[7] * half;
  m(2, 3) = m(3, 2) = c[8] * half;
  return m;
}

Matrix3 rotation_from_quaternion(const Quaternion& q) {
  const Rational &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  Rational n = w * w + x * x + y * y + z * z;
  if (n == 0) throw InputError("rotation quaternion is zero");
  Matrix3 r;
  r(0, 0) = w * w + x * x - y * y - z * z;
  r(0, 1) = 2 * (x * y - w * z);
  r(0, 2) = 2 * (x * z + w * y);
  r(1, 0) = 2 * (x * y + w * z);
  r(1, 1) = w * w - x * x + y * y - z * z;
  r(1, 2) = 2 * (y * z - w * x);
  r(2, 0) = 2 * (x * z - w * y);
  r(2, 1) = 2 * (y * z + w * x);
  r(2, 2) = w * w - x * x - y * y + z * z;
  for (auto& v : r.a) v /= n;
  return r;
}

namespace {

bool exactly_symmetric(const Matrix4& q) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (q(i, j) != q(j, i)) return false;
  return true;
}

/// Certified enclosures of the entries (CGAL::to_interval; rounding towards +inf by the caller).
std::array<detail::shape_filter::impl::I, 16> entry_intervals(const Matrix4& q) {
  std::array<detail::shape_filter::impl::I, 16> x;
  for (std::size_t k = 0; k < 16; ++k) x[k] = detail::shape_filter::impl::I(CGAL::to_interval(q.a[k]));
  return x;
}

/// The shape of a rational matrix as a filtered predicate: the orientation (+1 or -1, the sign of
/// the first entry) when intervals around the entries certify a real ellipsoid, else 0 and the
/// exact classification decides (and names what the matrix is).
int filtered_ellipsoid(const Matrix4& e) {
  const int want = CGAL::sign(e(0, 0));
  if (want == 0 || !exactly_symmetric(e)) return 0;
  CGAL::Protect_FPU_rounding<true> guard;
  return detail::shape_filter::certified_ellipsoid_intervals(entry_intervals(e), want) == want ? want : 0;
}

/// The same for an elliptic paraboloid: the sign of the trace of Q3 when certain. det Q3 = 0 is
/// exact (zero factors, else the rational determinant: nine products, far cheaper than the
/// inertia).
int filtered_paraboloid(const Matrix4& p) {
  if (!exactly_symmetric(p)) return 0;
  if (!detail::shape_filter::impl::zero_by_pattern(CGAL::is_zero(p.a[0]), CGAL::is_zero(p.a[1]), CGAL::is_zero(p.a[2]),
                                                   CGAL::is_zero(p.a[5]), CGAL::is_zero(p.a[6]),
                                                   CGAL::is_zero(p.a[10]))) {
    if (!CGAL::is_zero(detail::shape_filter::impl::det3<Rational>(p.a))) return 0;
  }
  CGAL::Protect_FPU_rounding<true> guard;
  return detail::shape_filter::certified_paraboloid_intervals(entry_intervals(p));
}

}  // namespace

Ellipsoid Ellipsoid::from_matrix(const Matrix4& e) {
  if (const int orientation = filtered_ellipsoid(e)) return Ellipsoid(orientation > 0 ? e : negated(e));
  QuadricKind k = classify_quadric(e);
  if (k != QuadricKind::Ellipsoid) detail::refuse_as_ellipsoid(k);
  // Q3 is definite; make it positive definite (interior X^T E X < 0).
  return Ellipsoid(e(0, 0) > 0 ? e : negated(e));
}

Ellipsoid Ellipsoid::from_coefficients(const Coefficients10& c) {
  return from_matrix(detail::matrix_from_coefficients(c));
}

Ellipsoid Ellipsoid::translated(const Vector3& d) const {
  const Matrix4& q = matrix();
  Matrix4 m = q;
  Rational e0 = q(3, 3);
  for (int i = 0; i < 3; ++i) {
    Rational md(0);  // (M d)_i
    for (int j = 0; j < 3; ++j) md += q(i, j) * d[static_cast<std::size_t>(j)];
    const Rational& di = d[static_cast<std::size_t>(i)];
    m(i, 3) = m(3, i) = q(i, 3) - md;
    e0 += di * (md - 2 * q(i, 3));  // - 2 e_i d_i + d_i (M d)_i
  }
  m(3, 3) = e0;
  return Ellipsoid(std::move(m));
}

Ellipsoid Ellipsoid::sphere(const Vector3& c, const Rational& r) {
  if (r <= 0) throw InputError("sphere radius must be positive, got " + to_string(r));
  Matrix4 m;
  for (int i = 0; i < 3; ++i) {
    m(i, i) = Rational(1);
    m(i, 3) = m(3, i) = -c[static_cast<std::size_t>(i)];
  }
  m(3, 3) = squared_norm_minus(c, r);
  return Ellipsoid(m);
}

Ellipsoid Ellipsoid::sphere(const std::array<double, 3>& c, double r) {
  return sphere(exact_array(c), exact_rational(r));
}

Ellipsoid Ellipsoid::from_axes(const std::array<double, 3>& c, const std::array<double, 3>& ax,
                               const std::array<double, 4>& q) {
  return from_axes(exact_array(c), exact_array(ax), Quaternion(exact_array(q)));
}

Ellipsoid Ellipsoid::from_axes(const Vector3& c, const Vector3& ax, const Quaternion& q) {
  return from_axes(c, ax, rotation_from_quaternion(q));
}

Ellipsoid Ellipsoid::from_axes(const Vector3& c, const Vector3& ax, const Matrix3& rot) {
  for (const auto& a : ax)
    if (a <= 0) throw InputError("ellipsoid semi-axes must be positive, got " + to_string(a));
  check_orthogonal(rot);
  Matrix3 l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l(i, j) = rot(i, j) * ax[static_cast<std::size_t>(j)];
  return from_map(c, l);
}

Ellipsoid Ellipsoid::from_map(const Vector3& c, const Matrix3& l) {
  Matrix4 unit;  // x^2 + y^2 + z^2 - 1
  unit(0, 0) = unit(1, 1) = unit(2, 2) = Rational(1);
  unit(3, 3) = Rational(-1);
  // The image of the unit ball under an invertible affine map: an ellipsoid, positive definite block
  // (Sylvester's law of inertia): no validation, no sign normalization.
  return Ellipsoid(push_forward(unit, l, c, "ellipsoid linear map"));
}

Paraboloid Paraboloid::from_matrix(const Matrix4& p) {
  if (const int orientation = filtered_paraboloid(p)) return Paraboloid(orientation > 0 ? p : negated(p));
  QuadricKind k = classify_quadric(p);
  if (k != QuadricKind::EllipticParaboloid) detail::refuse_as_paraboloid(k);
  // Q3 is semidefinite of rank 2; its trace has the sign of its non-zero eigenvalues.
  return Paraboloid(p(0, 0) + p(1, 1) + p(2, 2) > 0 ? p : negated(p));
}

Paraboloid Paraboloid::from_coefficients(const Coefficients10& c) {
  return from_matrix(detail::matrix_from_coefficients(c));
}

Paraboloid Paraboloid::standard(const Vector3& v, const Rational& a, const Rational& b, const Quaternion& q) {
  if (a <= 0 || b <= 0)
    throw InputError("paraboloid parameters a, b must be positive, got a = " + to_string(a) + ", b = " + to_string(b));
  const Rational ia = detail::forms::inverse_square(a), ib = detail::forms::inverse_square(b);
  // A congruence of the standard paraboloid by an invertible affine map is an elliptic paraboloid
  // with the same orientation (Sylvester's law of inertia): no validation, no sign normalization.
  if (q[0] != 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) {
    // No rotation: (x - v)^T A (x - v) - (z - v_z), written directly (the common case).
    Matrix4 m;
    m(0, 0) = ia;
    m(1, 1) = ib;
    m(2, 3) = m(3, 2) = Rational(-1, 2);
    if (v[0] == 0 && v[1] == 0) {  // a vertex on the z axis (the usual input): no products of zeros
      m(3, 3) = v[2];
      return Paraboloid(std::move(m));
    }
    m(0, 3) = m(3, 0) = -ia * v[0];
    m(1, 3) = m(3, 1) = -ib * v[1];
    m(3, 3) = ia * v[0] * v[0] + ib * v[1] * v[1] + v[2];
    return Paraboloid(std::move(m));
  }
  Matrix4 local;
  local(0, 0) = ia;
  local(1, 1) = ib;
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Paraboloid(push_forward(local, rotation_from_quaternion(q), v, "paraboloid rotation"));
}

Paraboloid Paraboloid::standard(const std::array<double, 3>& v, double a, double b, const std::array<double, 4>& q) {
  return standard(exact_array(v), exact_rational(a), exact_rational(b), Quaternion(exact_array(q)));
}

Paraboloid Paraboloid::from_map(const Matrix3& l, const Vector3& t) {
  Matrix4 local;  // x^2 + y^2 - z
  local(0, 0) = local(1, 1) = Rational(1);
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Paraboloid(push_forward(local, l, t, "paraboloid linear map"));  // valid by construction
}

}  // namespace relpos
