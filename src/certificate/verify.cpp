// The independent certificate verifier (include/relpos/position.hpp; math.md §8).
//
// Only exact rational arithmetic (relpos::Rational / Integer) on the two 4x4 matrices and a few lines
// of Q(sqrt d) arithmetic of the verifiers (quadratic_field.hpp): no code of the classifier (pencil, Sturm sequences,
// roots, filters) is used, so that a certificate checked here is evidence independent of the code that produced it.
#include "certificate/verify.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "certificate/quadratic_field.hpp"
#include "relpos/position.hpp"

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

Qd principal_minor(const Field& f, const QMatrix& m, const std::vector<int>& idx) { return minor_det(f, m, idx, idx); }

std::string index_text(const std::vector<int>& idx) {
  std::string s = "{";
  for (std::size_t i = 0; i < idx.size(); ++i) s += (i ? "," : "") + std::to_string(idx[i] + 1);
  return s + "}";
}

/// nullopt if the 4 leading principal minors are > 0 (Sylvester), else the failing one.
Reason positive_definite(const Field& f, const QMatrix& k, const std::string& name) {
  for (int n = 1; n <= 4; ++n) {
    std::vector<int> idx;
    for (int i = 0; i < n; ++i) idx.push_back(i);
    const Qd m = principal_minor(f, k, idx);
    if (f.sign(m) <= 0)
      return name + " is not positive definite (leading minor " + std::to_string(n) + " is " + f.text(m) + ")";
  }
  return std::nullopt;
}

/// nullopt if all 15 principal minors are >= 0, else the failing one.
Reason positive_semidefinite(const Field& f, const QMatrix& k, const std::string& name) {
  for (int mask = 1; mask < 16; ++mask) {
    std::vector<int> idx;
    for (int i = 0; i < 4; ++i)
      if (mask & (1 << i)) idx.push_back(i);
    const Qd m = principal_minor(f, k, idx);
    if (f.sign(m) < 0)
      return name + " is not positive semidefinite (principal minor " + index_text(idx) + " is " + f.text(m) + ")";
  }
  return std::nullopt;
}

QMatrix to_q(const Matrix4& m) {
  QMatrix out;
  for (std::size_t i = 0; i < 16; ++i) out[i] = rat(m.a[i]);
  return out;
}

/// lambda P + E with lambda = l.u + l.v sqrt d.
QMatrix pencil_at(const Field& f, const Matrix4& e, const Matrix4& p, const Qd& l) {
  QMatrix k;
  for (std::size_t i = 0; i < 16; ++i) k[i] = f.add(f.mul(l, rat(p.a[i])), rat(e.a[i]));
  return k;
}

Qd from_quadratic(const QuadraticNumber& x) { return {x.a, x.b}; }

// ---- normalization ------------------------------------------------------------------------------

Reason check_symmetric(const Matrix4& m, const std::string& name) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (m(i, j) != m(j, i))
        return name + " matrix is not symmetric (entry " + std::to_string(i + 1) + "," + std::to_string(j + 1) + ")";
  return std::nullopt;
}

/// E made to have a positive definite 3x3 block (negation only), checked to be a real ellipsoid.
Reason normalize_ellipsoid(Matrix4& e) {
  if (auto r = check_symmetric(e, "ellipsoid")) return r;
  if (e(0, 0) < 0) e = negated(e);
  const Field f{Integer(0)};
  const QMatrix q = to_q(e);
  for (int n = 1; n <= 3; ++n) {
    std::vector<int> idx;
    for (int i = 0; i < n; ++i) idx.push_back(i);
    if (f.sign(principal_minor(f, q, idx)) <= 0)
      return std::string("ellipsoid: the 3x3 block is not definite (leading minor ") + std::to_string(n) +
             " after normalization is " + f.text(principal_minor(f, q, idx)) + ")";
  }
  const Qd det = principal_minor(f, q, {0, 1, 2, 3});
  if (f.sign(det) >= 0) return "ellipsoid: not a real ellipsoid (det E = " + f.text(det) + ", expected < 0)";
  return std::nullopt;
}

/// P made to have a 3x3 block of positive trace (negation only), checked to be an elliptic paraboloid:
/// block positive semidefinite of rank 2, det P < 0.
Reason normalize_paraboloid(Matrix4& p) {
  if (auto r = check_symmetric(p, "paraboloid")) return r;
  const Rational trace = p(0, 0) + p(1, 1) + p(2, 2);
  if (trace == 0) return std::string("paraboloid: the 3x3 block has trace 0");
  if (trace < 0) p = negated(p);
  const Field f{Integer(0)};
  const QMatrix q = to_q(p);
  bool some_2x2_positive = false;
  for (int mask = 1; mask < 8; ++mask) {
    std::vector<int> idx;
    for (int i = 0; i < 3; ++i)
      if (mask & (1 << i)) idx.push_back(i);
    const int s = f.sign(principal_minor(f, q, idx));
    if (s < 0) return "paraboloid: the 3x3 block is not semidefinite (principal minor " + index_text(idx) + " < 0)";
    if (idx.size() == 2 && s > 0) some_2x2_positive = true;
    if (idx.size() == 3 && s != 0) return std::string("paraboloid: the 3x3 block is not singular");
  }
  if (!some_2x2_positive) return std::string("paraboloid: the 3x3 block has rank < 2");
  const Qd det = principal_minor(f, q, {0, 1, 2, 3});
  if (f.sign(det) >= 0) return "paraboloid: det P = " + f.text(det) + ", expected < 0";
  return std::nullopt;
}

// ---- the four kinds of certificates -------------------------------------------------------------

Reason verify_definite(const Matrix4& e, const Matrix4& p, int lambda_sign, const Certificate& c) {
  const Field f{Integer(0)};
  if (CGAL::sign(c.lambda) != lambda_sign)
    return "lambda = " + to_string(c.lambda) + " must be " + (lambda_sign > 0 ? "> 0" : "< 0");
  return positive_definite(f, pencil_at(f, e, p, rat(c.lambda)), "lambda P + E");
}

Reason verify_tangent(const Matrix4& e, const Matrix4& p, int lambda_sign, const Certificate& c) {
  const Field f{Integer(0)};
  if (CGAL::sign(c.lambda) != lambda_sign)
    return "lambda = " + to_string(c.lambda) + " must be " + (lambda_sign > 0 ? "> 0" : "< 0");
  if (auto r = positive_semidefinite(f, pencil_at(f, e, p, rat(c.lambda)), "lambda P + E")) return r;
  const Rational pv = form_at(p, c.contact), ev = form_at(e, c.contact);
  if (pv != 0)
    return "contact " + point_text(c.contact) + " is not on the paraboloid (X^T P X = " + to_string(pv) + ")";
  if (ev != 0) return "contact " + point_text(c.contact) + " is not on the ellipsoid (X^T E X = " + to_string(ev) + ")";
  return std::nullopt;
}

/// The hard case's directions: at most 3, non-zero, in ker(lambda A + M) (K's first three rows and
/// columns), M-orthogonal to the gradient of e at the centre (so that e(centre + w) = e(centre) +
/// w^T M w), and independent; written as rows 0..n-1 of `w_rows`.
Reason check_directions(const Field& f, const Matrix4& e, const QMatrix& k, const std::array<Qd, 4>& centre,
                        const Certificate& c, QMatrix& w_rows) {
  const std::size_t n = c.directions.size();
  if (n > 3) return "more than 3 directions (" + std::to_string(n) + ")";
  for (std::size_t i = 0; i < 16; ++i) w_rows[i] = f.zero();
  for (std::size_t t = 0; t < n; ++t) {
    const std::string name = "direction " + std::to_string(t + 1);
    std::array<Qd, 3> w;
    for (std::size_t j = 0; j < 3; ++j) w_rows[4 * t + j] = w[j] = from_quadratic(c.directions[t][j]);
    if (f.sign(w[0]) == 0 && f.sign(w[1]) == 0 && f.sign(w[2]) == 0) return name + " is zero";
    for (std::size_t i = 0; i < 3; ++i) {
      Qd s = f.zero();
      for (std::size_t j = 0; j < 3; ++j) s = f.add(s, f.mul(k[4 * i + j], w[j]));
      if (f.sign(s) != 0)
        return name + " is not in the kernel of lambda A + M (row " + std::to_string(i + 1) + " is " + f.text(s) + ")";
    }
    Qd g = f.zero();  // w^T (M centre + m)
    for (std::size_t i = 0; i < 3; ++i) {
      Qd row = rat(e(static_cast<int>(i), 3));
      for (std::size_t j = 0; j < 3; ++j)
        row = f.add(row, f.mul(rat(e(static_cast<int>(i), static_cast<int>(j))), centre[j]));
      g = f.add(g, f.mul(w[i], row));
    }
    if (f.sign(g) != 0) return name + " is not conjugate to the centre (w^T (M centre + m) = " + f.text(g) + ")";
  }
  if (n >= 2) {
    bool independent = false;
    std::vector<int> rows;
    for (std::size_t t = 0; t < n; ++t) rows.push_back(static_cast<int>(t));
    // Some n x n minor of the n x 3 matrix of directions is non-zero.
    for (int mask = 0; mask < 8 && !independent; ++mask) {
      std::vector<int> cols;
      for (int j = 0; j < 3; ++j)
        if (mask & (1 << j)) cols.push_back(j);
      if (cols.size() == n && f.sign(minor_det(f, w_rows, rows, cols)) != 0) independent = true;
    }
    if (!independent) return std::string("the directions are linearly dependent");
  }
  return std::nullopt;
}

/// radius2 = -e(centre) >= 0, and when it is positive the directions span the whole kernel of
/// lambda A + M (the contact set is complete).
Reason check_radius(const Field& f, const Matrix4& e, const QMatrix& k, const std::array<Qd, 4>& centre,
                    const Certificate& c) {
  const std::size_t n = c.directions.size();
  Qd ec = f.zero();
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      ec = f.add(ec, f.mul(f.mul(centre[i], rat(e(static_cast<int>(i), static_cast<int>(j)))), centre[j]));
  const Qd r2 = from_quadratic(c.radius2);
  if (f.sign(f.add(r2, ec)) != 0) return "radius2 = " + f.text(r2) + " is not -e(centre) = " + f.text(Qd{-ec.u, -ec.v});
  const int r2_sign = f.sign(r2);
  if (r2_sign < 0) return "radius2 = " + f.text(r2) + " is negative";
  if (r2_sign > 0) {
    if (n == 0) return std::string("radius2 > 0 but no direction: the contact set is empty");
    const int rank = block_rank(f, k);
    if (static_cast<std::size_t>(rank) + n != 3)
      return std::to_string(n) + " direction(s) but the kernel of lambda A + M has dimension " +
             std::to_string(3 - rank);
  }
  return std::nullopt;
}

Reason verify_hard_tangent(const Matrix4& e, const Matrix4& p, const Certificate& c) {
  if (c.d < 0) return "d = " + to_string(c.d) + " must be >= 0";
  const Field f{c.d};
  const Qd lambda = from_quadratic(c.lambda_q);
  if (f.sign(lambda) >= 0) return "lambda = " + f.text(lambda) + " must be < 0";
  const QMatrix k = pencil_at(f, e, p, lambda);
  if (auto r = positive_semidefinite(f, k, "lambda P + E")) return r;
  const std::array<Qd, 4> centre{from_quadratic(c.centre[0]), from_quadratic(c.centre[1]), from_quadratic(c.centre[2]),
                                 rat(Rational(1))};
  // K (centre, 1) = 0.
  for (std::size_t i = 0; i < 4; ++i) {
    Qd s = f.zero();
    for (std::size_t j = 0; j < 4; ++j) s = f.add(s, f.mul(k[4 * i + j], centre[j]));
    if (f.sign(s) != 0)
      return "K (centre, 1) != 0 (row " + std::to_string(i + 1) + " is " + f.text(s) + "), K = lambda P + E";
  }
  QMatrix w_rows;  // rows 0..n-1: the directions, as a matrix for the independence minors
  if (auto r = check_directions(f, e, k, centre, c, w_rows)) return r;
  return check_radius(f, e, k, centre, c);
}

Reason verify_crossing(const Matrix4& e, const Matrix4& p, const Certificate& c) {
  const Rational ei = form_at(e, c.inside), eo = form_at(e, c.outside);
  if (ei > 0)
    return "inside point " + point_text(c.inside) + " is not in the solid ellipsoid (X^T E X = " + to_string(ei) + ")";
  if (eo > 0)
    return "outside point " + point_text(c.outside) + " is not in the solid ellipsoid (X^T E X = " + to_string(eo) +
           ")";
  const Rational pi = form_at(p, c.inside), po = form_at(p, c.outside);
  if (pi >= 0)
    return "inside point " + point_text(c.inside) + " is not inside the paraboloid (X^T P X = " + to_string(pi) + ")";
  if (po <= 0)
    return "outside point " + point_text(c.outside) + " is not outside the paraboloid (X^T P X = " + to_string(po) +
           ")";
  return std::nullopt;
}

const char* kind_name(Certificate::Kind k) {
  switch (k) {
    case Certificate::Kind::None:
      return "none";
    case Certificate::Kind::Definite:
      return "definite (lambda)";
    case Certificate::Kind::Tangent:
      return "tangent (lambda, contact)";
    case Certificate::Kind::HardTangent:
      return "hard tangent (lambda, contact_set)";
    case Certificate::Kind::Crossing:
      return "crossing (inside, outside)";
  }
  return "unknown";
}

}  // namespace

int quadratic_sign(const QuadraticNumber& x, const Integer& d) { return Field(d).sign(from_quadratic(x)); }

std::optional<std::string> verify_certificate(const Matrix4& e_in, const Matrix4& p_in, Position position,
                                              const Certificate& c) {
  Matrix4 e = e_in, p = p_in;
  if (auto r = normalize_ellipsoid(e)) return r;
  if (auto r = normalize_paraboloid(p)) return r;
  using K = Certificate::Kind;
  const std::string wrong = std::string("a certificate of kind ") + kind_name(c.kind) + " cannot prove position ";
  switch (position) {
    case Position::E:
      if (c.kind != K::Definite) return wrong + "E";
      return verify_definite(e, p, 1, c);
    case Position::I:
      if (c.kind != K::Definite) return wrong + "I";
      return verify_definite(e, p, -1, c);
    case Position::TE:
      if (c.kind != K::Tangent) return wrong + "TE";
      return verify_tangent(e, p, 1, c);
    case Position::TI:
      if (c.kind == K::Tangent) return verify_tangent(e, p, -1, c);
      if (c.kind == K::HardTangent) return verify_hard_tangent(e, p, c);
      return wrong + "TI";
    case Position::C:
      if (c.kind != K::Crossing) return wrong + "C";
      return verify_crossing(e, p, c);
    default:
      return std::string("not a position");
  }
}

std::optional<std::string> verify_certificate(const Ellipsoid& e, const Paraboloid& p, Position position,
                                              const Certificate& c) {
  return verify_certificate(e.matrix(), p.matrix(), position, c);
}

}  // namespace relpos
