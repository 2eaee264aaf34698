// The float decisions of float_decisions.hpp, in their own translation unit so that the benchmark
// loop calls them as it calls the library: across a translation unit, not inlined into the loop.
#include "float_decisions.hpp"

namespace ordinary {

namespace {

using relpos::Position;

int sign(double x) { return (x > 0) - (x < 0); }

/// Sign changes of a sequence of signs, zeros skipped.
template <std::size_t N>
int variations(const std::array<int, N>& s) {
  int v = 0, last = 0;
  for (int x : s) {
    if (x == 0) continue;
    if (last != 0 && x != last) ++v;
    last = x;
  }
  return v;
}

/// The 2x2 minor on rows (r0, r1), columns (c0, c1) of E + λP: a quadratic in λ.
std::array<double, 3> pencil_minor(const Matrix& p, const Matrix& e, int r0, int r1, int c0, int c1) {
  auto at = [](const Matrix& m, int i, int j) { return m[static_cast<std::size_t>(4 * i + j)]; };
  const double a0 = at(e, r0, c0), b0 = at(e, r0, c1), c0_ = at(e, r1, c0), d0 = at(e, r1, c1);
  const double a1 = at(p, r0, c0), b1 = at(p, r0, c1), c1_ = at(p, r1, c0), d1 = at(p, r1, c1);
  return {a0 * d0 - b0 * c0_, a0 * d1 + a1 * d0 - b0 * c1_ - b1 * c0_, a1 * d1 - b1 * c1_};
}

/// Sign of Disc(f) from the invariants of the quartic: 27 Disc(f) = 4 I^3 - J^2.
int discriminant_sign(const std::array<double, 5>& f) {
  const double a = f[4], b = f[3], c = f[2], d = f[1], e = f[0];
  const double i = 12 * a * e - 3 * b * d + c * c;
  const double j = 72 * a * c * e + 9 * b * c * d - 27 * a * d * d - 27 * e * b * b - 2 * c * c * c;
  return sign(4 * i * i * i - j * j);
}

/// s(λ) = det(λA + M) for the leading 3x3 blocks (the λ^3 coefficient det A = 0 is dropped).
std::array<double, 3> special_quadratic(const Matrix& p, const Matrix& e) {
  std::array<double, 3> s{0, 0, 0};
  for (int j = 0; j < 3; ++j) {
    const int c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
    const std::array<double, 3> m = pencil_minor(p, e, 1, 2, c0, c1);
    const double x0 = e[static_cast<std::size_t>(j)], x1 = p[static_cast<std::size_t>(j)];
    const double t[3] = {x0 * m[0], x0 * m[1] + x1 * m[0], x0 * m[2] + x1 * m[1]};
    for (int i = 0; i < 3; ++i) s[static_cast<std::size_t>(i)] += j == 1 ? -t[i] : t[i];
  }
  return s;
}

struct Counts {
  int real, positive;
};

/// Real and positive roots of f from the signs of its Sturm-Habicht sequence at -oo, 0, +oo
/// (math.md §4); nullopt when the sequence is defective. `disc` is the sign of g0 = Disc(f).
std::optional<Counts> sturm_habicht_counts(const std::array<double, 5>& f, int disc) {
  const double f0 = f[0], f1 = f[1], f2 = f[2], f3 = f[3], f4 = f[4];
  // g2 and g1 with StHa_j = (positive) * f4 * g_j (math.md §4).
  const double g20 = -8 * f2 * f4 + 3 * f3 * f3, g22 = -16 * f0 * f4 + f1 * f3;
  const double g10 = 32 * f0 * f2 * f4 * f4 - 12 * f0 * f3 * f3 * f4 - 36 * f1 * f1 * f4 * f4 + 28 * f1 * f2 * f3 * f4 -
                     6 * f1 * f3 * f3 * f3 - 8 * f2 * f2 * f2 * f4 + 2 * f2 * f2 * f3 * f3;
  const double g11 = -48 * f0 * f1 * f4 * f4 + 32 * f0 * f2 * f3 * f4 - 9 * f0 * f3 * f3 * f3 + 3 * f1 * f1 * f3 * f4 -
                     4 * f1 * f2 * f2 * f4 + f1 * f2 * f3 * f3;
  const int s4 = sign(f4);
  if (s4 == 0 || sign(g20) == 0 || sign(g10) == 0 || disc == 0) return std::nullopt;
  auto lift = [&](double g) { return s4 * sign(g); };
  const std::array<int, 5> at_plus_inf{s4, s4, lift(g20), lift(g10), s4 * disc};
  const std::array<int, 5> at_minus_inf{at_plus_inf[0], -at_plus_inf[1], at_plus_inf[2], -at_plus_inf[3],
                                        at_plus_inf[4]};
  const std::array<int, 5> at_zero{sign(f0), sign(f1), lift(g22), lift(g11), s4 * disc};
  const int v_plus = variations(at_plus_inf);
  return Counts{variations(at_minus_inf) - v_plus, variations(at_zero) - v_plus};
}

}  // namespace

std::array<double, 5> characteristic_quartic(const Matrix& p, const Matrix& e) {
  // Laplace expansion along rows (0, 1): each term a minor of rows (0, 1) times the complementary
  // minor of rows (2, 3), both quadratics in λ.
  static constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr double kSign[6] = {1, -1, 1, 1, -1, 1};
  std::array<double, 5> f{0, 0, 0, 0, 0};
  for (int k = 0; k < 6; ++k) {
    const std::array<double, 3> u = pencil_minor(p, e, 0, 1, kPairs[k][0], kPairs[k][1]);
    const std::array<double, 3> v = pencil_minor(p, e, 2, 3, kPairs[5 - k][0], kPairs[5 - k][1]);
    f[0] += kSign[k] * (u[0] * v[0]);
    f[1] += kSign[k] * (u[0] * v[1] + u[1] * v[0]);
    f[2] += kSign[k] * (u[0] * v[2] + u[1] * v[1] + u[2] * v[0]);
    f[3] += kSign[k] * (u[1] * v[2] + u[2] * v[1]);
    f[4] += kSign[k] * (u[2] * v[2]);
  }
  return f;
}

std::optional<Position> minimal_float_decision(const Matrix& p, const Matrix& e) {
  const std::array<double, 5> f = characteristic_quartic(p, e);
  const int disc = discriminant_sign(f);
  if (disc < 0) return Position::C;
  const int changes = variations(std::array<int, 5>{sign(f[4]), sign(f[3]), sign(f[2]), sign(f[1]), sign(f[0])});
  if (disc == 0) return changes > 0 ? Position::TE : Position::TI;
  if (changes == 2) return Position::E;
  if (changes == 0) return Position::I;
  return std::nullopt;
}

std::optional<Position> paper_float_decision(const Matrix& p, const Matrix& e) {
  const std::array<double, 5> f = characteristic_quartic(p, e);
  const std::array<double, 3> s = special_quadratic(p, e);
  // Smallness (math.md §5): rho <= 1 iff vertex >= 0 and graeffe >= 0.
  const double n = -f[0] * s[2], d = -f[4] * s[0], w = s[1] * s[1] - 2 * s[0] * s[2];
  const double vertex = w * d - 2 * n * s[2] * s[2];
  const double graeffe = n * n * s[2] * s[2] - w * n * d + s[0] * s[0] * d * d;
  const bool small = vertex >= 0 && graeffe >= 0;
  const int disc = discriminant_sign(f);
  if (disc == 0) {
    // A multiple root: a tangency for a small body (math.md §3). Its sign is unknown to float
    // code; count as if Disc(f) > 0 and call it TE when a positive root shows.
    const std::optional<Counts> c = sturm_habicht_counts(f, 1);
    if (!c) return std::nullopt;
    if (c->positive > 0) return Position::TE;
    return small ? std::optional<Position>(Position::TI) : std::nullopt;
  }
  const std::optional<Counts> c = sturm_habicht_counts(f, disc);
  if (!c) return std::nullopt;
  const int nonreal = 4 - c->real;
  if (nonreal == 0 && c->positive == 2) return Position::E;  // any size (math.md §6)
  if (!small) return std::nullopt;                           // outside the table of math.md §3
  if (nonreal == 2 && c->positive == 0) return Position::C;
  if (nonreal == 0 && c->positive == 0) return Position::I;
  return std::nullopt;
}

}  // namespace ordinary
