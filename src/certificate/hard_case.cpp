// The hard case of math.md §8: f~ vanishes at lambda_s, lambda_s A + M is singular, and the contact
// set is x^ + {w in ker(lambda_s A + M): w^T M w = -e(x^)}, x^ the minimiser of e on the solutions of
// (lambda_s A + M) x = -(lambda_s a + m) -- linear algebra over Q(sqrt d).
#include <array>
#include <utility>
#include <vector>

#include "certificate/kinds.hpp"

namespace relpos::detail::certificate {
namespace {

using anysize::LambdaS;
using anysize::QuadraticReal;
using Q3 = std::array<QuadraticReal, 3>;

/// Kernel basis and a particular solution of K x = r over Q(sqrt d) (3x3), by Gaussian elimination.
struct LinearSolution {
  Q3 particular;
  std::vector<Q3> kernel;
  bool consistent = true;
};

LinearSolution solve3(const LambdaS& ls, std::array<std::array<QuadraticReal, 4>, 3> m) {
  const QuadraticReal zero{Rational(0), Rational(0)};
  int row = 0;
  std::array<int, 3> pivot_of_row{-1, -1, -1};
  std::array<bool, 3> is_pivot{false, false, false};
  for (int c = 0; c < 3 && row < 3; ++c) {
    int r = row;
    while (r < 3 && ls.sign(m[r][c]) == 0) ++r;
    if (r == 3) continue;
    std::swap(m[r], m[row]);
    const QuadraticReal inv = ls.div({Rational(1), Rational(0)}, m[row][c]);
    for (int j = 0; j < 4; ++j) m[row][j] = ls.mul(m[row][j], inv);
    for (int i = 0; i < 3; ++i) {
      if (i == row || ls.sign(m[i][c]) == 0) continue;
      const QuadraticReal factor = m[i][c];
      for (int j = 0; j < 4; ++j) m[i][j] = ls.sub(m[i][j], ls.mul(factor, m[row][j]));
    }
    pivot_of_row[row] = c;
    is_pivot[c] = true;
    ++row;
  }
  LinearSolution out;
  for (int i = row; i < 3; ++i)
    if (ls.sign(m[i][3]) != 0) out.consistent = false;
  out.particular = {zero, zero, zero};
  for (int r = 0; r < row; ++r) out.particular[pivot_of_row[r]] = m[r][3];
  for (int free = 0; free < 3; ++free) {
    if (is_pivot[free]) continue;
    Q3 v{zero, zero, zero};
    v[free] = {Rational(1), Rational(0)};
    for (int r = 0; r < row; ++r) v[pivot_of_row[r]] = {-m[r][free].a, -m[r][free].b};
    out.kernel.push_back(v);
  }
  return out;
}

QuadraticReal q_of(const Rational& x) { return {x, Rational(0)}; }

/// e(x) = x^T M x + 2 m^T x + e0 over Q(sqrt d).
QuadraticReal e_in_field(const LambdaS& ls, const Matrix4& E, const Q3& x) {
  QuadraticReal acc = q_of(E(3, 3));
  for (int i = 0; i < 3; ++i) {
    acc = ls.add(acc, ls.mul(q_of(2 * E(i, 3)), x[i]));
    for (int j = 0; j < 3; ++j) acc = ls.add(acc, ls.mul(ls.mul(x[i], q_of(E(i, j))), x[j]));
  }
  return acc;
}

/// x moved to the minimiser of e on x + span(w): with the gradient g_j = w_j^T (M x + m) and the Gram
/// matrix G_jk = w_j^T M w_k, x + sum c_j w_j for G c = -g.
void minimise_along(const LambdaS& ls, const Matrix4& E, const std::vector<Q3>& w, Q3& x) {
  auto Mv = [&](const Q3& v) {
    Q3 out;
    for (int i = 0; i < 3; ++i) {
      QuadraticReal acc{Rational(0), Rational(0)};
      for (int j = 0; j < 3; ++j) acc = ls.add(acc, ls.mul(q_of(E(i, j)), v[j]));
      out[i] = acc;
    }
    return out;
  };
  auto dot = [&](const Q3& u, const Q3& v) {
    QuadraticReal acc{Rational(0), Rational(0)};
    for (int i = 0; i < 3; ++i) acc = ls.add(acc, ls.mul(u[i], v[i]));
    return acc;
  };
  auto mx = Mv(x);
  for (int i = 0; i < 3; ++i) mx[i] = ls.add(mx[i], q_of(E(i, 3)));
  const std::size_t n = w.size();
  std::array<std::array<QuadraticReal, 4>, 3> g;
  const QuadraticReal zero{Rational(0), Rational(0)};
  for (auto& row : g) row = {zero, zero, zero, zero};
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t k = 0; k < n; ++k) g[j][k] = dot(w[j], Mv(w[k]));
    const QuadraticReal gj = dot(w[j], mx);
    g[j][3] = {-gj.a, -gj.b};
  }
  for (std::size_t j = n; j < 3; ++j) g[j][j] = {Rational(1), Rational(0)};  // pad to 3x3 identity
  const LinearSolution cs = solve3(ls, g);
  for (std::size_t j = 0; j < n; ++j)
    for (int i = 0; i < 3; ++i) x[i] = ls.add(x[i], ls.mul(cs.particular[j], w[j][i]));
}

}  // namespace

bool hard_case(const detail::PairContext& pr, Certificate& c) {
  const LambdaS& ls = pr.lambda_s();
  const Matrix4& E = pr.ellipsoid().matrix();
  const Matrix4& P = pr.paraboloid().matrix();
  std::array<std::array<QuadraticReal, 4>, 3> m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i][j] = ls.add(ls.mul(ls.value(), q_of(P(i, j))), q_of(E(i, j)));
    const QuadraticReal r = ls.add(ls.mul(ls.value(), q_of(P(i, 3))), q_of(E(i, 3)));
    m[i][3] = {-r.a, -r.b};
  }
  const LinearSolution sol = solve3(ls, m);
  if (!sol.consistent) return false;  // not the hard case: x(lambda) leaves every bounded set
  Q3 x = sol.particular;
  const auto& w = sol.kernel;
  if (!w.empty()) minimise_along(ls, E, w, x);
  const QuadraticReal ex = e_in_field(ls, E, x);
  c.kind = Certificate::Kind::HardTangent;
  c.d = ls.d;
  c.lambda_q = {ls.value().a, ls.value().b};
  for (int i = 0; i < 3; ++i) c.centre[i] = {x[i].a, x[i].b};
  c.directions.clear();
  for (const auto& v : w) c.directions.push_back({QuadraticNumber{v[0].a, v[0].b}, {v[1].a, v[1].b}, {v[2].a, v[2].b}});
  c.radius2 = {-ex.a, -ex.b};
  return true;
}

}  // namespace relpos::detail::certificate
