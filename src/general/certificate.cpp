// The certificates of math.md §18 from the exact evidence: definite pencil members (E, I, O), the
// rational double root and its contact point (TE, TI, TO), the contact set over Q(sqrt n) at the end
// of an interval (the hard case), the crossing witnesses (C) and the ratio of equal ellipsoids (EQ).
#include "general/certificate.hpp"

#include <stdexcept>
#include <string>

#include "algebra/matrix4.hpp"
#include "general/quadratic_field.hpp"
#include "general/witness.hpp"

namespace relpos::detail::general {
namespace {

std::logic_error internal_error(const std::string& what) { return std::logic_error("relpos internal error: " + what); }

using detail::form_at;
using detail::negated;

QuadraticNumber to_number(const Qn& x) { return {x.u, x.v}; }

/// The system (B + t M) x = -(b + t m) of the pencil Q + t E, over the field.
std::optional<AffineSolution> stationary_points(const QuadraticField& k, const Matrix4& e, const Matrix4& q,
                                                const Qn& t) {
  std::array<Qn, 9> a;
  Qn3 r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[static_cast<std::size_t>(3 * i + j)] = k.add(k.of(q(i, j)), k.mul(t, k.of(e(i, j))));
    r[static_cast<std::size_t>(i)] = k.sub(k.of(Rational(0)), k.add(k.of(q(i, 3)), k.mul(t, k.of(e(i, 3)))));
  }
  return solve_affine(k, a, r);
}

/// The tangent certificate at a rational double root t of f inside an interval: B + t M is
/// non-singular there, and x(t) lies on both surfaces (math.md §18).
QuadricCertificate tangent(const Matrix4& e, const Matrix4& q, const Rational& t) {
  const QuadraticField k{Integer(0)};
  const auto s = stationary_points(k, e, q, k.of(t));
  if (!s || !s->kernel.empty()) throw internal_error("B + t M is singular at a tangency inside an interval");
  QuadricCertificate c;
  c.kind = QuadricCertificate::Kind::Tangent;
  c.t = t;
  for (std::size_t i = 0; i < 3; ++i) c.contact[i] = s->particular[i].u;
  if (form_at(e, c.contact) != 0 || form_at(q, c.contact) != 0)
    throw internal_error("the contact point of a tangency is not on both surfaces");
  return c;
}

/// The hard case (math.md §18): t = a + b sqrt n an end of the interval; the stationary points form
/// an affine space, its point of least e is the centre, the kernel of B + t M gives the directions.
QuadricCertificate hard_tangent(const Matrix4& e, const Matrix4& q, const QuadraticNumber& t, const Integer& n) {
  const QuadraticField k{n};
  const Qn tq{t.a, t.b};
  const auto s = stationary_points(k, e, q, tq);
  if (!s) throw internal_error("no stationary point at the end of a tangency");
  const std::size_t dim = s->kernel.size();
  // centre = p + W y with (W^T M W) y = -W^T (M p + m): the least e on the affine space.
  std::array<Qn, 9> g;
  Qn3 rhs;
  for (std::size_t i = 0; i < 9; ++i) g[i] = k.of(Rational(i % 4 == 0 ? 1 : 0));
  for (Qn& x : rhs) x = k.of(Rational(0));
  auto m_times = [&](const Qn3& x) {  // M x + m (with m only when `affine`)
    Qn3 out;
    for (int i = 0; i < 3; ++i) {
      Qn acc = k.of(Rational(0));
      for (int j = 0; j < 3; ++j) acc = k.add(acc, k.mul(k.of(e(i, j)), x[static_cast<std::size_t>(j)]));
      out[static_cast<std::size_t>(i)] = acc;
    }
    return out;
  };
  auto dot = [&](const Qn3& x, const Qn3& y) {
    Qn acc = k.of(Rational(0));
    for (std::size_t i = 0; i < 3; ++i) acc = k.add(acc, k.mul(x[i], y[i]));
    return acc;
  };
  Qn3 grad = m_times(s->particular);  // M p + m
  for (int i = 0; i < 3; ++i)
    grad[static_cast<std::size_t>(i)] = k.add(grad[static_cast<std::size_t>(i)], k.of(e(i, 3)));
  for (std::size_t i = 0; i < dim; ++i) {
    const Qn3 mw = m_times(s->kernel[i]);
    for (std::size_t j = 0; j < dim; ++j) g[3 * i + j] = dot(s->kernel[j], mw);
    rhs[i] = k.sub(k.of(Rational(0)), dot(s->kernel[i], grad));
  }
  const auto y = solve_affine(k, g, rhs);
  if (!y || !y->kernel.empty()) throw internal_error("the contact set's centre is not unique");
  Qn3 centre = s->particular;
  for (std::size_t i = 0; i < dim; ++i)
    for (std::size_t j = 0; j < 3; ++j) centre[j] = k.add(centre[j], k.mul(y->particular[i], s->kernel[i][j]));
  // radius2 = -e(centre).
  Qn ec = k.of(e(3, 3));
  const Qn3 mc = m_times(centre);
  for (std::size_t i = 0; i < 3; ++i) {
    ec = k.add(ec, k.mul(centre[i], mc[i]));
    ec = k.add(ec, k.mul(k.of(2 * e(static_cast<int>(i), 3)), centre[i]));
  }
  QuadricCertificate c;
  c.kind = QuadricCertificate::Kind::HardTangent;
  c.d = n;
  c.t_q = t;
  for (std::size_t i = 0; i < 3; ++i) c.centre[i] = to_number(centre[i]);
  for (const Qn3& w : s->kernel) c.directions.push_back({to_number(w[0]), to_number(w[1]), to_number(w[2])});
  c.radius2 = to_number(k.sub(k.of(Rational(0)), ec));
  if (k.sign(k.sub(k.of(Rational(0)), ec)) < 0) throw internal_error("the contact set of a tangency is empty");
  return c;
}

/// Q = ratio E with ratio > 0 (EQ, math.md §16).
QuadricCertificate equal(const Matrix4& e, const Matrix4& q) {
  QuadricCertificate c;
  c.kind = QuadricCertificate::Kind::Equal;
  for (std::size_t i = 0; i < 16; ++i)
    if (e.a[i] != 0) {
      c.ratio = q.a[i] / e.a[i];
      break;
    }
  for (std::size_t i = 0; i < 16; ++i)
    if (q.a[i] != c.ratio * e.a[i]) throw internal_error("EQ for matrices that are not proportional");
  return c;
}

}  // namespace

QuadricCertificate build_certificate(const Matrix4& e, const Matrix4& q, const ExactEvidence& ev,
                                     const Rational& scale) {
  const QuadricPosition p = ev.verdict.position;
  const std::string name = to_string(p);
  QuadricCertificate c;
  switch (p) {
    case QuadricPosition::E:
    case QuadricPosition::I:
    case QuadricPosition::O:
      if (!ev.definite) throw internal_error("no definite multiplier for a pair classified " + name);
      c.kind = QuadricCertificate::Kind::Definite;
      c.t = *ev.definite * scale;
      return c;
    case QuadricPosition::TE:
    case QuadricPosition::TI:
    case QuadricPosition::TO:
      if (ev.tangent) return tangent(e, q, *ev.tangent * scale);
      if (ev.endpoint) return hard_tangent(e, q, {ev.endpoint->a * scale, ev.endpoint->b * scale}, ev.d);
      throw internal_error("no multiplier for a pair classified " + name);
    case QuadricPosition::EQ:
      return equal(e, q);
    case QuadricPosition::C:
      c.kind = QuadricCertificate::Kind::Crossing;
      c.inside = negative_point(e, q);
      c.outside = negative_point(e, negated(q));
      // B positive definite: Q's solid is bounded, so C also needs a point of it outside E.
      if (ev.facts.ellipsoid) c.beyond = negative_point(q, negated(e));
      return c;
  }
  throw internal_error("no certificate for a pair classified " + name);
}

}  // namespace relpos::detail::general
