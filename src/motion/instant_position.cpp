#include "motion/instant_position.hpp"

#include <stdexcept>
#include <utility>

namespace relpos::detail {
namespace {

[[noreturn]] void impossible(const std::string& what) {
  throw std::logic_error("internal error: motion: impossible root configuration at an instant (" + what + ")");
}

/// Determinant of the principal submatrix of M(l) on the rows/columns `idx` (Laplace expansion
/// along the first row; sizes <= 3 here).
PencilZ principal_minor(const std::array<PencilZ, 16>& m, const std::vector<int>& idx) {
  if (idx.size() == 1) return m[static_cast<std::size_t>(5 * idx[0])];
  PencilZ det(PolyZ(Integer(0)));
  for (std::size_t k = 0; k < idx.size(); ++k) {
    std::vector<int> rest;
    for (std::size_t i = 1; i < idx.size(); ++i) rest.push_back(idx[i]);
    // Minor of row idx[0], column idx[k]: rows idx[1..], columns idx without idx[k].
    std::vector<int> cols;
    for (std::size_t i = 0; i < idx.size(); ++i)
      if (i != k) cols.push_back(idx[i]);
    // Build the (n-1)x(n-1) determinant of rows `rest`, columns `cols` (not principal in general).
    PencilZ sub(PolyZ(Integer(0)));
    if (rest.size() == 1) {
      sub = m[static_cast<std::size_t>(4 * rest[0] + cols[0])];
    } else {  // 2x2
      sub = m[static_cast<std::size_t>(4 * rest[0] + cols[0])] * m[static_cast<std::size_t>(4 * rest[1] + cols[1])] -
            m[static_cast<std::size_t>(4 * rest[0] + cols[1])] * m[static_cast<std::size_t>(4 * rest[1] + cols[0])];
    }
    const PencilZ term = m[static_cast<std::size_t>(4 * idx[0] + idx[k])] * sub;
    det = (k % 2 == 0) ? det + term : det - term;
  }
  return det;
}

/// A real number (a + b sqrt(D)) / c of K(sqrt D), K = Q(t*), with a, b, c in Z[t] and c(t*) != 0;
/// D is shared by all the numbers of one instant (b = 0 when no square root is involved).
struct Number {
  PolyZ a, b, c;
  int sign_c = 0;  ///< sign of c(t*)
};

PolyZ zero() { return PolyZ(Integer(0)); }
PolyZ constant(long k) { return PolyZ(Integer(k)); }

/// The decision context: the signs of polynomials at t*, with D.
struct Signs {
  const SignAt& at;
  PolyZ D;  ///< D(t*) > 0 whenever some b != 0

  /// sign(U + W sqrt D): from sign U, sign W and, when they differ, sign(U^2 - W^2 D) (times sign U).
  int of(const PolyZ& u, const PolyZ& w) const {
    const int sw = CGAL::is_zero(w) ? 0 : at(w);
    const int su = at(u);
    if (sw == 0) return su;
    if (su == 0 || su == sw) return sw;
    return su * at(u * u - w * w * D);
  }
  int of(const Number& x) const { return x.sign_c * of(x.a, x.b); }
  Number make(PolyZ a, PolyZ b, PolyZ c) const {
    const int sc = at(c);
    if (sc == 0) impossible("a root of f with a vanishing denominator");
    return Number{std::move(a), std::move(b), std::move(c), sc};
  }
  /// sign(x - y).
  int compare(const Number& x, const Number& y) const {
    return x.sign_c * y.sign_c * of(x.a * y.c - y.a * x.c, x.b * y.c - y.b * x.c);
  }
  Number midpoint(const Number& x, const Number& y) const {
    return Number{x.a * y.c + y.a * x.c, x.b * y.c + y.b * x.c, constant(2) * x.c * y.c, x.sign_c * y.sign_c};
  }
  /// The sign of a polynomial in l (degree <= k) at x: c^k m(x) = sum m_i (a + b sqrt D)^i c^(k-i).
  int of_at(const PencilZ& m, int k, const Number& x) const {
    PolyZ u = zero(), w = zero();
    PolyZ pu = constant(1), pw = zero();  // (a + b sqrt D)^i = pu + pw sqrt D
    std::vector<PolyZ> cpow{constant(1)};
    for (int i = 1; i <= k; ++i) cpow.push_back(cpow.back() * x.c);
    for (int i = 0; i <= k; ++i) {
      if (i <= m.degree() && !CGAL::is_zero(m[i])) {
        u += m[i] * pu * cpow[static_cast<std::size_t>(k - i)];
        if (!CGAL::is_zero(pw)) w += m[i] * pw * cpow[static_cast<std::size_t>(k - i)];
      }
      if (i < k) {
        const PolyZ nu = pu * x.a + (CGAL::is_zero(pw) || CGAL::is_zero(x.b) ? zero() : pw * x.b * D);
        const PolyZ nw = CGAL::is_zero(x.b) ? pw * x.a : pu * x.b + pw * x.a;
        pu = nu;
        pw = nw;
      }
    }
    const int sc = (k % 2 == 0) ? 1 : x.sign_c;
    return sc * of(u, w);
  }
};

struct Root {
  Number x;
  int multiplicity;
};

int size_of_minor(std::size_t index) { return index < 4 ? 1 : (index < 10 ? 2 : 3); }

/// j = 1: one double root l* = u/v = -S1_0/S1_1; f = (l - l*)^2 g, g = f4 l^2 + g1 l + g0 with
/// g1 = f3 + 2 f4 l* = w/v and g0 = f0 / l*^2: the roots of g are (-w u +- sqrt(dg)) / (2 f4 u v),
/// dg = w^2 u^2 - 4 f4 f0 v^4 = Disc(g) u^2 v^2. Returns the structure's name.
std::string one_double_root(const InstantPencil& ip, Signs& sg, std::vector<Root>& roots) {
  const SignAt& at = sg.at;
  const PolyZ &f0 = ip.f[0], &f3 = ip.f[3], &f4 = ip.f[4];
  const PolyZ u = -ip.g1[1], v = ip.g1[0];
  if (at(u) == 0) impossible("double root at l = 0");
  roots.push_back({sg.make(u, zero(), v), 2});
  const PolyZ w = v * f3 + constant(2) * f4 * u;
  const PolyZ dg = w * w * u * u - constant(4) * f4 * f0 * v * v * v * v;
  const int sdg = at(dg);
  if (sdg == 0) impossible("j = 1 but the cofactor has a double root");
  if (sdg < 0) return "one double root and a non-real pair";
  sg.D = dg;
  const PolyZ a = -w * u, c = constant(2) * f4 * u * v;
  roots.push_back({sg.make(a, constant(1), c), 1});
  roots.push_back({sg.make(a, constant(-1), c), 1});
  return "one double root and two simple real roots";
}

/// j = 2: gcd(f, f') = A l^2 + B l + C at t*: a triple root and a simple one, or two double roots.
std::string quadratic_gcd(const InstantPencil& ip, Signs& sg, std::vector<Root>& roots) {
  const PolyZ &f3 = ip.f[3], &f4 = ip.f[4];
  const PolyZ &A = ip.g2[0], &B = ip.g2[1], &C = ip.g2[2];
  const PolyZ d = B * B - constant(4) * A * C;
  const int sd = sg.at(d);
  if (sd < 0) impossible("f is the square of a quadratic without real roots");  // f has real roots
  if (sd == 0) {
    // Triple root l* = -B / (2A); f = f4 (l - l*)^3 (l - mu), mu = -f3/f4 - 3 l*.
    const PolyZ u = -B, v = constant(2) * A;
    roots.push_back({sg.make(u, zero(), v), 3});
    roots.push_back({sg.make(-f3 * v - constant(3) * f4 * u, zero(), f4 * v), 1});
    return "a triple root and a simple root";
  }
  sg.D = d;  // two real double roots (-B +- sqrt d) / (2A)
  roots.push_back({sg.make(-B, constant(1), constant(2) * A), 2});
  roots.push_back({sg.make(-B, constant(-1), constant(2) * A), 2});
  return "two double roots";
}

/// The distinct real roots of f at t* with their multiplicities, from j = deg gcd(f, f') at t*: the
/// first non-vanishing principal subresultant coefficient (they specialise because f4 = det P is a
/// non-zero constant). Returns j; `structure` names what f has.
int roots_at_instant(const InstantPencil& ip, Signs& sg, std::vector<Root>& roots, std::string& structure) {
  if (sg.at(ip.g1[0]) != 0) {
    structure = one_double_root(ip, sg, roots);
    return 1;
  }
  if (sg.at(ip.g2[0]) != 0) {
    structure = quadratic_gcd(ip, sg, roots);
    return 2;
  }
  // gcd(f, f') = f': f = f4 (l - l*)^4, l* = -f3 / (4 f4)
  roots.push_back({sg.make(-ip.f[3], zero(), constant(4) * ip.f[4]), 4});
  structure = "a quadruple root";
  return 3;
}

/// The roots in increasing order (at most four, all distinct and non-zero: f(0) = det E < 0).
void sort_roots(const Signs& sg, std::vector<Root>& roots) {
  for (const Root& r : roots)
    if (sg.of(r.x) == 0) impossible("a root at l = 0 (f(0) = det E < 0)");
  for (std::size_t i = 1; i < roots.size(); ++i)
    for (std::size_t k = i; k > 0; --k) {
      const int c = sg.compare(roots[k - 1].x, roots[k].x);
      if (c == 0) impossible("two equal roots listed as distinct");
      if (c < 0) break;
      std::swap(roots[k - 1], roots[k]);
    }
}

/// E or I: l P + E(t*) positive definite at the midpoint of two consecutive roots, tried only where
/// f = det M > 0 (f has the sign of f4 above the largest root and changes sign at each root of odd
/// multiplicity). False when no such midpoint is definite.
bool definite_between(const InstantPencil& ip, const Signs& sg, const std::vector<Root>& roots, const std::string& head,
                      InstantDecision& out) {
  std::vector<int> sign_above(roots.size());
  int s = sg.at(ip.f[4]);
  for (std::size_t i = roots.size(); i-- > 0;) {
    sign_above[i] = s;
    if (roots[i].multiplicity % 2 == 1) s = -s;
  }
  for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
    if (sign_above[i] <= 0) continue;
    const Number mid = sg.midpoint(roots[i].x, roots[i + 1].x);
    bool pd = true;
    for (std::size_t k = 0; k < 3 && pd; ++k) pd = sg.of_at(ip.minors[ip.leading[k]], static_cast<int>(k + 1), mid) > 0;
    if (!pd) continue;
    const int side = sg.of(mid);
    out.position = side > 0 ? Position::E : Position::I;
    out.how = head + "l P + E(t*) is positive definite between two consecutive " +
              (side > 0 ? "positive" : "negative") + " roots";
    return true;
  }
  return false;
}

/// TE or TI: with no definite l, the semidefinite set is at most one point, a root of f. False when
/// l P + E(t*) is semidefinite at none.
bool semidefinite_at(const InstantPencil& ip, const Signs& sg, const std::vector<Root>& roots, const std::string& head,
                     InstantDecision& out) {
  for (const Root& r : roots) {
    bool psd = true;
    for (std::size_t k = 0; k < ip.minors.size() && psd; ++k) psd = sg.of_at(ip.minors[k], size_of_minor(k), r.x) >= 0;
    if (!psd) continue;
    const int side = sg.of(r.x);
    out.position = side > 0 ? Position::TE : Position::TI;
    out.how = head + "l P + E(t*) is nowhere definite and positive semidefinite at a " +
              (side > 0 ? "positive" : "negative") + " root of multiplicity " + std::to_string(r.multiplicity);
    return true;
  }
  return false;
}

}  // namespace

InstantPencil::InstantPencil(const forms::MatrixOf<PolyZ>& p, const forms::MatrixOf<PolyZ>& e,
                             const std::array<PolyZ, 5>& f_, const PolyZ (&g2_)[3], const PolyZ (&g1_)[2],
                             const PolyZ& disc_)
    : f(f_), g2{g2_[0], g2_[1], g2_[2]}, g1{g1_[0], g1_[1]}, disc(disc_) {
  std::array<PencilZ, 16> m;
  for (std::size_t i = 0; i < 16; ++i) m[i] = PencilZ(e.a[i], p.a[i]);  // E(t) + l P
  // Sizes 1, 2, 3 in lexicographic order of the index sets; the leading ones are {0}, {0,1}, {0,1,2}.
  const std::vector<std::vector<int>> sets{{0},    {1},    {2},    {3},       {0, 1},    {0, 2},    {0, 3},
                                           {1, 2}, {1, 3}, {2, 3}, {0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  for (const auto& s : sets) minors.push_back(principal_minor(m, s));
  leading = {0, 4, 10};
}

std::optional<InstantDecision> decide_at_instant(const InstantPencil& ip, const SignAt& at, bool known_multiple) {
  if (!known_multiple && !CGAL::is_zero(ip.disc) && at(ip.disc) != 0) return std::nullopt;
  InstantDecision out;
  Signs sg{at, zero()};
  std::vector<Root> roots;
  std::string structure;
  out.j = roots_at_instant(ip, sg, roots, structure);
  sort_roots(sg, roots);
  const std::string head = "Disc f = 0 at t* (" + structure + " of f, j = " + std::to_string(out.j) + "): ";
  if (definite_between(ip, sg, roots, head, out) || semidefinite_at(ip, sg, roots, head, out)) return out;
  out.position = Position::C;
  out.how = head + "l P + E(t*) is positive semidefinite for no l";
  return out;
}

}  // namespace relpos::detail
