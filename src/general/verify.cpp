// The independent verifier of general certificates (include/relpos/general_position.hpp; math.md §18).
//
// Exact rational arithmetic on the two 4x4 matrices, the verifiers' Q(sqrt d) arithmetic and
// determinants (src/certificate/quadratic_field.hpp) and inertia of its own: no code of the
// classifier (pencils, root isolation, filters), so that a certificate checked here is evidence independent of the
// code that produced it.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "certificate/quadratic_field.hpp"
#include "relpos/general_position.hpp"

namespace relpos {
namespace {

using Reason = std::optional<std::string>;

using detail::block_rank;
using detail::Field;
using detail::form_at;
using detail::minor_det;
using detail::negated;
using detail::point_text;
using detail::Qd;
using detail::QMatrix;
using detail::rat;

Qd of(const QuadraticNumber& x) { return {x.a, x.b}; }

std::vector<int> leading(int n) {
  std::vector<int> idx;
  for (int i = 0; i < n; ++i) idx.push_back(i);
  return idx;
}

/// nullopt when sign * K is positive definite (4 leading minors > 0).
Reason definite(const Field& f, const QMatrix& k, int sign, const std::string& name) {
  for (int n = 1; n <= 4; ++n) {
    Qd m = minor_det(f, k, leading(n), leading(n));
    if (sign < 0 && n % 2 == 1) m = f.neg(m);
    if (f.sign(m) <= 0)
      return name + " is not " + (sign > 0 ? "positive" : "negative") + " definite (leading minor " +
             std::to_string(n) + " of " + (sign > 0 ? "" : "-") + "(Q + t E) is " + f.text(m) + ")";
  }
  return std::nullopt;
}

/// nullopt when sign * K is positive semidefinite (all 15 principal minors >= 0).
Reason semidefinite(const Field& f, const QMatrix& k, int sign, const std::string& name) {
  for (int mask = 1; mask < 16; ++mask) {
    std::vector<int> idx;
    for (int i = 0; i < 4; ++i)
      if (mask & (1 << i)) idx.push_back(i);
    Qd m = minor_det(f, k, idx, idx);
    if (sign < 0 && idx.size() % 2 == 1) m = f.neg(m);
    if (f.sign(m) < 0)
      return name + " is not " + (sign > 0 ? "positive" : "negative") + " semidefinite (a principal minor of " +
             (sign > 0 ? "" : "-") + "(Q + t E) is " + f.text(m) + ")";
  }
  return std::nullopt;
}

QMatrix pencil_at(const Field& f, const Matrix4& e, const Matrix4& q, const Qd& t) {
  QMatrix k;
  for (std::size_t i = 0; i < 16; ++i) k[i] = f.add(rat(q.a[i]), f.mul(t, rat(e.a[i])));
  return k;
}

Reason check_symmetric(const Matrix4& m, const std::string& name) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (m(i, j) != m(j, i))
        return name + " matrix is not symmetric (entry " + std::to_string(i + 1) + "," + std::to_string(j + 1) + ")";
  return std::nullopt;
}

/// E with M positive definite (negation only), checked to be a real ellipsoid.
Reason normalize_ellipsoid(Matrix4& e) {
  if (auto r = check_symmetric(e, "ellipsoid")) return r;
  if (e(0, 0) < 0) e = negated(e);
  const Field f{Integer(0)};
  QMatrix m;
  for (std::size_t i = 0; i < 16; ++i) m[i] = rat(e.a[i]);
  for (int n = 1; n <= 3; ++n)
    if (f.sign(minor_det(f, m, leading(n), leading(n))) <= 0)
      return "ellipsoid: the 3x3 block is not definite (leading minor " + std::to_string(n) + ")";
  if (f.sign(minor_det(f, m, leading(4), leading(4))) >= 0)
    return std::string("ellipsoid: det E >= 0, not a real ellipsoid");
  return std::nullopt;
}

/// Q negated when its 3x3 block has more negative than positive eigenvalues: Descartes' rule on the
/// block's characteristic polynomial x^3 - E1 x^2 + E2 x - E3 (all roots real).
Reason normalize_quadric(Matrix4& q) {
  if (auto r = check_symmetric(q, "quadric")) return r;
  const Field f{Integer(0)};
  QMatrix m;
  for (std::size_t i = 0; i < 16; ++i) m[i] = rat(q.a[i]);
  int e[4] = {1, 0, 0, 0};
  Rational sums[4] = {Rational(1), Rational(0), Rational(0), Rational(0)};
  for (int mask = 1; mask < 8; ++mask) {
    std::vector<int> idx;
    for (int i = 0; i < 3; ++i)
      if (mask & (1 << i)) idx.push_back(i);
    sums[idx.size()] += minor_det(f, m, idx, idx).u;
  }
  for (int k = 0; k < 4; ++k) e[k] = CGAL::sign(sums[k]);
  auto variations = [](std::array<int, 4> s) {
    int count = 0, last = 0;
    for (int x : s) {
      if (x == 0) continue;
      if (last != 0 && x != last) ++count;
      last = x;
    }
    return count;
  };
  const int positive = variations({1, -e[1], e[2], -e[3]});
  const int negative = variations({-1, -e[1], -e[2], -e[3]});
  if (negative > positive) q = negated(q);
  bool zero = true;
  for (const Rational& x : q.a) zero = zero && x == 0;
  if (zero) return std::string("quadric: the matrix is zero");
  return std::nullopt;
}

/// Whether Q is a real ellipsoid: B positive definite and det Q < 0.
bool real_ellipsoid(const Matrix4& q) {
  const Field f{Integer(0)};
  QMatrix m;
  for (std::size_t i = 0; i < 16; ++i) m[i] = rat(q.a[i]);
  for (int n = 1; n <= 3; ++n)
    if (f.sign(minor_det(f, m, leading(n), leading(n))) <= 0) return false;
  return f.sign(minor_det(f, m, leading(4), leading(4))) < 0;
}

// ---- the kinds ----------------------------------------------------------------------------------

std::string sign_text(int s) { return s > 0 ? "> 0" : "< 0"; }

Reason verify_definite(const Matrix4& e, const Matrix4& q, int t_sign, int definiteness, const QuadricCertificate& c) {
  const Field f{Integer(0)};
  if (CGAL::sign(c.t) != t_sign) return "t = " + to_string(c.t) + " must be " + sign_text(t_sign);
  return definite(f, pencil_at(f, e, q, rat(c.t)), definiteness, "Q + t E");
}

Reason verify_tangent(const Matrix4& e, const Matrix4& q, int t_sign, int definiteness, const QuadricCertificate& c) {
  const Field f{Integer(0)};
  if (CGAL::sign(c.t) != t_sign) return "t = " + to_string(c.t) + " must be " + sign_text(t_sign);
  if (auto r = semidefinite(f, pencil_at(f, e, q, rat(c.t)), definiteness, "Q + t E")) return r;
  const Rational qv = form_at(q, c.contact), ev = form_at(e, c.contact);
  if (qv != 0) return "contact " + point_text(c.contact) + " is not on the quadric (X^T Q X = " + to_string(qv) + ")";
  if (ev != 0) return "contact " + point_text(c.contact) + " is not on the ellipsoid (X^T E X = " + to_string(ev) + ")";
  return std::nullopt;
}

/// The directions of a hard tangency's contact set: at most three, each non-zero, in the kernel of
/// B + t M and M-orthogonal to M centre + m, and linearly independent.
Reason check_directions(const Field& f, const Matrix4& e, const QMatrix& k, const std::array<Qd, 4>& centre,
                        const QuadricCertificate& c) {
  const std::size_t n = c.directions.size();
  if (n > 3) return "more than 3 directions (" + std::to_string(n) + ")";
  QMatrix rows;
  for (Qd& x : rows) x = rat(Rational(0));
  for (std::size_t a = 0; a < n; ++a) {
    const std::string name = "direction " + std::to_string(a + 1);
    std::array<Qd, 3> w;
    for (std::size_t j = 0; j < 3; ++j) rows[4 * a + j] = w[j] = of(c.directions[a][j]);
    if (f.sign(w[0]) == 0 && f.sign(w[1]) == 0 && f.sign(w[2]) == 0) return name + " is zero";
    for (std::size_t i = 0; i < 3; ++i) {
      Qd s = rat(Rational(0));
      for (std::size_t j = 0; j < 3; ++j) s = f.add(s, f.mul(k[4 * i + j], w[j]));
      if (f.sign(s) != 0) return name + " is not in the kernel of B + t M (row " + std::to_string(i + 1) + ")";
    }
    Qd g = rat(Rational(0));  // w^T (M centre + m)
    for (std::size_t i = 0; i < 3; ++i) {
      Qd row = rat(e(static_cast<int>(i), 3));
      for (std::size_t j = 0; j < 3; ++j)
        row = f.add(row, f.mul(rat(e(static_cast<int>(i), static_cast<int>(j))), centre[j]));
      g = f.add(g, f.mul(w[i], row));
    }
    if (f.sign(g) != 0) return name + " is not M-orthogonal to M centre + m (" + f.text(g) + ")";
  }
  if (n >= 2) {
    bool independent = false;
    for (int mask = 0; mask < 8 && !independent; ++mask) {
      std::vector<int> cols;
      for (int j = 0; j < 3; ++j)
        if (mask & (1 << j)) cols.push_back(j);
      if (cols.size() == n && f.sign(minor_det(f, rows, leading(static_cast<int>(n)), cols)) != 0) independent = true;
    }
    if (!independent) return std::string("the directions are linearly dependent");
  }
  return std::nullopt;
}

Reason verify_hard_tangent(const Matrix4& e, const Matrix4& q, int t_sign, int definiteness,
                           const QuadricCertificate& c) {
  if (c.d < 0) return "d = " + to_string(c.d) + " must be >= 0";
  const Field f{c.d};
  const Qd t = of(c.t_q);
  if (f.sign(t) != t_sign) return "t = " + f.text(t) + " must be " + sign_text(t_sign);
  const QMatrix k = pencil_at(f, e, q, t);
  if (auto r = semidefinite(f, k, definiteness, "Q + t E")) return r;
  const std::array<Qd, 4> centre{of(c.centre[0]), of(c.centre[1]), of(c.centre[2]), rat(Rational(1))};
  for (std::size_t i = 0; i < 4; ++i) {  // K (centre, 1) = 0
    Qd s = rat(Rational(0));
    for (std::size_t j = 0; j < 4; ++j) s = f.add(s, f.mul(k[4 * i + j], centre[j]));
    if (f.sign(s) != 0) return "(Q + t E) (centre, 1) != 0 (row " + std::to_string(i + 1) + " is " + f.text(s) + ")";
  }
  const std::size_t n = c.directions.size();
  if (auto r = check_directions(f, e, k, centre, c)) return r;
  Qd ec = rat(Rational(0));  // e(centre)
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      ec = f.add(ec, f.mul(f.mul(centre[i], rat(e(static_cast<int>(i), static_cast<int>(j)))), centre[j]));
  const Qd r2 = of(c.radius2);
  if (f.sign(f.add(r2, ec)) != 0) return "radius2 = " + f.text(r2) + " is not -e(centre) = " + f.text(f.neg(ec));
  const int r2_sign = f.sign(r2);
  if (r2_sign < 0) return "radius2 = " + f.text(r2) + " is negative: the contact set is empty";
  if (r2_sign > 0) {
    if (n == 0) return std::string("radius2 > 0 but no direction: the contact set is empty");
    const int rank = block_rank(f, k);  // of B + t M: the directions must span its kernel
    if (static_cast<std::size_t>(rank) + n != 3)
      return std::to_string(n) + " direction(s) but the kernel of B + t M has dimension " + std::to_string(3 - rank);
  }
  return std::nullopt;
}

Reason verify_crossing(const Matrix4& e, const Matrix4& q, const QuadricCertificate& c) {
  const Rational ei = form_at(e, c.inside), eo = form_at(e, c.outside);
  if (ei > 0)
    return "inside point " + point_text(c.inside) + " is not in the solid ellipsoid (e = " + to_string(ei) + ")";
  if (eo > 0)
    return "outside point " + point_text(c.outside) + " is not in the solid ellipsoid (e = " + to_string(eo) + ")";
  const Rational qi = form_at(q, c.inside), qo = form_at(q, c.outside);
  if (qi >= 0) return "inside point " + point_text(c.inside) + " is not inside the quadric (q = " + to_string(qi) + ")";
  if (qo <= 0)
    return "outside point " + point_text(c.outside) + " is not outside the quadric (q = " + to_string(qo) + ")";
  // B positive definite: Q's solid is bounded and could lie inside E (O, TO); a point of it outside E
  // rules that out. Otherwise its solid, non-empty (q(inside) < 0), is unbounded and cannot.
  const Field f{Integer(0)};
  QMatrix m;
  for (std::size_t i = 0; i < 16; ++i) m[i] = rat(q.a[i]);
  bool b_definite = true;
  for (int n = 1; n <= 3; ++n) b_definite = b_definite && f.sign(minor_det(f, m, leading(n), leading(n))) > 0;
  if (!b_definite) return std::nullopt;
  if (!c.beyond) return std::string("the quadric is an ellipsoid: a point of its solid outside E is needed (beyond)");
  const Rational qb = form_at(q, *c.beyond), eb = form_at(e, *c.beyond);
  if (qb > 0)
    return "beyond point " + point_text(*c.beyond) + " is not in the quadric's solid (q = " + to_string(qb) + ")";
  if (eb <= 0)
    return "beyond point " + point_text(*c.beyond) + " is not outside the ellipsoid (e = " + to_string(eb) + ")";
  return std::nullopt;
}

Reason verify_equal(const Matrix4& e, const Matrix4& q, const QuadricCertificate& c) {
  if (c.ratio <= 0) return "ratio = " + to_string(c.ratio) + " must be > 0";
  for (std::size_t i = 0; i < 16; ++i)
    if (q.a[i] != c.ratio * e.a[i])
      return "Q != ratio E (entry " + std::to_string(i / 4 + 1) + "," + std::to_string(i % 4 + 1) + ")";
  return std::nullopt;
}

const char* kind_name(QuadricCertificate::Kind k) {
  using K = QuadricCertificate::Kind;
  switch (k) {
    case K::None:
      return "none";
    case K::Definite:
      return "definite (t)";
    case K::Tangent:
      return "tangent (t, contact)";
    case K::HardTangent:
      return "hard tangent (t, contact_set)";
    case K::Crossing:
      return "crossing (inside, outside)";
    case K::Equal:
      return "equal (ratio)";
  }
  return "unknown";
}

}  // namespace

std::optional<std::string> verify_certificate(const Matrix4& e_in, const Matrix4& q_in, QuadricPosition position,
                                              const QuadricCertificate& c) {
  Matrix4 e = e_in, q = q_in;
  if (auto r = normalize_ellipsoid(e)) return r;
  if (auto r = normalize_quadric(q)) return r;
  using K = QuadricCertificate::Kind;
  using P = QuadricPosition;
  const std::string wrong =
      std::string("a certificate of kind ") + kind_name(c.kind) + " cannot prove position " + to_string(position);
  // Q + t E with t > 0 positive (semi)definite: q >= -t e >= 0 on E's solid (E, TE); t < 0 and
  // negative: q <= -t e <= 0 there (I, TI); t < 0 and positive: t e >= -q >= 0 on Q's solid, so e <= 0
  // there (O, TO). math.md §18.
  struct Sides {
    int t_sign, definiteness;
  };
  Sides s{0, 0};
  switch (position) {
    case P::E:
    case P::TE:
      s = {1, 1};
      break;
    case P::I:
    case P::TI:
      s = {-1, -1};
      break;
    case P::O:
    case P::TO:
      s = {-1, 1};
      break;
    default:
      break;
  }
  if ((position == P::O || position == P::TO || position == P::EQ) && !real_ellipsoid(q))
    return "position " + to_string(position) + " needs the quadric to be a real ellipsoid";
  switch (position) {
    case P::E:
    case P::I:
    case P::O:
      if (c.kind != K::Definite) return wrong;
      return verify_definite(e, q, s.t_sign, s.definiteness, c);
    case P::TE:
    case P::TI:
    case P::TO:
      if (c.kind == K::Tangent) return verify_tangent(e, q, s.t_sign, s.definiteness, c);
      if (c.kind == K::HardTangent) return verify_hard_tangent(e, q, s.t_sign, s.definiteness, c);
      return wrong;
    case P::C:
      if (c.kind != K::Crossing) return wrong;
      return verify_crossing(e, q, c);
    case P::EQ:
      if (c.kind != K::Equal) return wrong;
      return verify_equal(e, q, c);
  }
  return std::string("not a position");
}

std::optional<std::string> verify_certificate(const Ellipsoid& e, const Quadric& q, QuadricPosition position,
                                              const QuadricCertificate& c) {
  return verify_certificate(e.matrix(), q.matrix(), position, c);
}

}  // namespace relpos
