#include "motion/polynomial_motion.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <utility>

#include "algebra/centre.hpp"
#include "algebra/forms.hpp"
#include "relpos/error.hpp"
#include "relpos/motion.hpp"

namespace relpos {
namespace {

using PolyQ = CGAL::Polynomial<Rational>;
using PolyZ = CGAL::Polynomial<Integer>;

PolyQ to_poly(const TimePolynomial& p) {
  if (p.empty()) return PolyQ(Rational(0));
  return PolyQ(p.begin(), p.end());
}

TimePolynomial from_poly(const PolyQ& p) {
  TimePolynomial out;
  if (CGAL::is_zero(p)) return out;
  for (int i = 0; i <= p.degree(); ++i) out.push_back(p[i]);
  return out;
}

/// The 4x4 matrix K = N T^-1 = [[Q^T, N p - Q^T (p + c)], [0, N]] (math.md §7), over NT.
/// `q` empty means no rotation (Q = I, N = 1).
template <class NT>
std::array<NT, 16> scaled_inverse(const std::array<NT, 4>* q, const std::array<NT, 3>& c, const std::array<NT, 3>& p) {
  std::array<NT, 9> qm;
  NT n(1);
  if (q) {
    qm = quaternion_matrix<NT>((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
    n = (*q)[0] * (*q)[0] + (*q)[1] * (*q)[1] + (*q)[2] * (*q)[2] + (*q)[3] * (*q)[3];
  } else {
    qm = {NT(1), NT(0), NT(0), NT(0), NT(1), NT(0), NT(0), NT(0), NT(1)};
  }
  std::array<NT, 16> k;
  for (std::size_t i = 0; i < 3; ++i) {
    NT last = n * p[i];
    for (std::size_t j = 0; j < 3; ++j) {
      k[4 * i + j] = qm[3 * j + i];                 // (Q^T)_{ij}
      last = last - qm[3 * j + i] * (p[j] + c[j]);  // - (Q^T (p + c))_i
    }
    k[4 * i + 3] = last;
  }
  k[12] = k[13] = k[14] = NT(0);
  k[15] = n;
  return k;
}

/// K^T E0 K.
template <class NT>
std::array<NT, 16> congruence(const std::array<NT, 16>& k, const Matrix4& e0) {
  std::array<NT, 16> ek;  // E0 K
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      NT v(0);
      for (std::size_t l = 0; l < 4; ++l)
        if (e0(static_cast<int>(i), static_cast<int>(l)) != 0)
          v = v + NT(e0(static_cast<int>(i), static_cast<int>(l))) * k[4 * l + j];
      ek[4 * i + j] = v;
    }
  std::array<NT, 16> out;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i; j < 4; ++j) {
      NT v(0);
      for (std::size_t l = 0; l < 4; ++l) v = v + k[4 * l + i] * ek[4 * l + j];
      out[4 * i + j] = v;
      out[4 * j + i] = v;
    }
  return out;
}

}  // namespace

RigidMotion RigidMotion::translating(std::array<TimePolynomial, 3> c) {
  RigidMotion m;
  m.translation = std::move(c);
  return m;
}

Vector3 centre_of(const Ellipsoid& e) {
  return *detail::centre_of(e.matrix());  // M is positive definite: never singular
}

Vector3 detail::pivot_of(const Ellipsoid& e0, const RigidMotion& m) {
  switch (m.pivot) {
    case Pivot::Origin:
      return {Rational(0), Rational(0), Rational(0)};
    case Pivot::Centre:
      return centre_of(e0);
    case Pivot::Point:
      return m.pivot_point;
  }
  return {};
}

TimeMatrix4 moving_ellipsoid_matrix(const Ellipsoid& e0, const RigidMotion& m) {
  const Vector3 p = detail::pivot_of(e0, m);
  std::array<PolyQ, 3> c, pp;
  for (std::size_t i = 0; i < 3; ++i) {
    c[i] = to_poly(m.translation[i]);
    pp[i] = PolyQ(p[i]);
  }
  std::array<PolyQ, 4> q;
  if (m.rotation)
    for (std::size_t i = 0; i < 4; ++i) q[i] = to_poly((*m.rotation)[i]);
  const auto k = scaled_inverse<PolyQ>(m.rotation ? &q : nullptr, c, pp);
  const auto e = congruence<PolyQ>(k, e0.matrix());
  TimeMatrix4 out;
  for (std::size_t i = 0; i < 16; ++i) out[i] = from_poly(e[i]);
  return out;
}

Ellipsoid detail::placed_ellipsoid(const Ellipsoid& e0, const RigidMotion& m, const Rational& t) {
  const Vector3 p = detail::pivot_of(e0, m);
  std::array<Rational, 3> c;
  for (std::size_t i = 0; i < 3; ++i) c[i] = evaluate(m.translation[i], t);
  std::array<Rational, 4> q;
  Rational n(1);
  if (m.rotation) {
    for (std::size_t i = 0; i < 4; ++i) q[i] = evaluate((*m.rotation)[i], t);
    n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (n == 0) throw InputError("the rotation quaternion q(t) vanishes at t = " + to_string(t));
  }
  auto k = scaled_inverse<Rational>(m.rotation ? &q : nullptr, c, p);
  auto e = congruence<Rational>(k, e0.matrix());
  Matrix4 out;
  const Rational n2 = n * n;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = e[i] / n2;  // T^-T E0 T^-1 itself
  return Ellipsoid::from_matrix(out);
}

void detail::validate_motion(const RigidMotion& m, const Rational& t0, const Rational& t1) {
  if (t1 < t0) throw InputError("the time interval is empty: t0 = " + to_string(t0) + " > t1 = " + to_string(t1));
  if (!m.rotation) return;
  // q(t) = 0 exactly at the common real roots of its four components, i.e. the real roots of
  // g = gcd(q_w, q_x, q_y, q_z) over Q.
  PolyQ g(Rational(0));
  for (const auto& comp : *m.rotation) g = CGAL::gcd(g, to_poly(comp));
  if (CGAL::is_zero(g)) throw InputError("the rotation quaternion q(t) is identically zero");
  if (g.degree() < 1) return;
  // Integer multiple of g (clear denominators) and its real roots in [t0, t1].
  Integer l(1);
  forms::lcm_of_denominators(g.begin(), g.end(), l);
  std::vector<Integer> zc;
  for (int i = 0; i <= g.degree(); ++i) zc.push_back(g[i].numerator() * (l / g[i].denominator()));
  using AK = CGAL::Algebraic_kernel_d_1<Integer>;
  AK ak;
  std::vector<std::pair<AK::Algebraic_real_1, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(PolyZ(zc.begin(), zc.end()), t0, t1, std::back_inserter(roots));
  if (!roots.empty())
    throw InputError("the rotation quaternion q(t) vanishes inside [" + to_string(t0) + ", " + to_string(t1) +
                     "] (near t = " + std::to_string(CGAL::to_double(roots.front().first.low())) +
                     "): the rotation is undefined there");
}

}  // namespace relpos
