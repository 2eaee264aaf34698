// The float codes relpos is compared with (doc/oracle.md, "Baselines"; doc/performance.md): the
// library's generic formulas instantiated with a float type NT, and the decision table a user would
// write on top of the float signs, nothing certified. `relpos judge` runs the double and long double
// ones on the float code's matrices of each case (float_rules.cpp, compiled as plain float code);
// the benchmarks time them (benchmarks/float_baseline.hpp).
#pragma once

#include <array>
#include <optional>

#include "algebra/pencil.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "relpos/classify.hpp"

namespace relpos::detail::oracle {

template <class NT>
struct Mat {
  std::array<NT, 16> a;
  const NT& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

template <class T>
USign usign(const T& x) {
  return relpos::sign_of(x);
}
inline USign usign(const long double& x) {
  return USign(x > 0 ? CGAL::POSITIVE : (x < 0 ? CGAL::NEGATIVE : CGAL::ZERO));
}

/// What a user would write on top of the float signs. nullopt = undecided (a zero / uncertain sign
/// where the table needs a strict one, or a pair outside the paper's small-ellipsoid table).
inline std::optional<Position> naive_table(const QuarticSigns& q, const USign& vertex, const USign& graeffe) {
  auto rho = compare_rho_with_one(vertex, graeffe);
  if (!rho) return std::nullopt;
  const bool small = *rho <= 0;
  auto disc = detail::certain(q.g0);
  if (!disc) return std::nullopt;
  if (*disc == 0) {
    // Disc(f) == 0 exactly: a tangency. The sign of the multiple root is unknown to a float code;
    // count with the discriminant taken positive and call it TE if a positive root shows up.
    QuarticSigns q2 = q;
    q2.g0 = USign(CGAL::POSITIVE);
    auto c = count_roots(q2);
    if (!c) return std::nullopt;
    if (c->positive > 0) return Position::TE;
    if (!small) return std::nullopt;  // outside the paper's table
    return Position::TI;
  }
  auto c = count_roots(q);
  if (!c) return std::nullopt;
  const int nonreal = 4 - c->real;
  if (nonreal == 0 && c->positive == 2) return Position::E;
  if (!small) return std::nullopt;  // outside the paper's table
  if (nonreal == 2 && c->positive == 0) return Position::C;
  if (nonreal == 0 && c->positive == 0) return Position::I;
  return std::nullopt;
}

template <class NT, class Conv>
std::optional<Position> float_classify(const std::array<double, 16>& pd, const std::array<double, 16>& ed, Conv conv) {
  Mat<NT> P, E;
  for (std::size_t i = 0; i < 16; ++i) {
    P.a[i] = conv(pd[i]);
    E.a[i] = conv(ed[i]);
  }
  const Quartic<NT> f = characteristic_polynomial<NT>(P, E);
  const Quadratic<NT> s = special_polynomial<NT>(P, E);
  SturmHabicht<NT> sh(f);
  SmallnessQuantities<NT> sq(f, s);
  QuarticSigns q;
  for (int i = 0; i < 5; ++i) q.f[i] = usign(f[static_cast<std::size_t>(i)]);
  for (int i = 0; i < 3; ++i) q.g2[i] = usign(sh.g2[i]);
  for (int i = 0; i < 2; ++i) q.g1[i] = usign(sh.g1[i]);
  q.g0 = usign(sh.g0[0]);
  return naive_table(q, usign(sq.vertex), usign(sq.graeffe));
}

/// The cheapest float decision: the characteristic quartic, its discriminant from the invariants
/// (27 Disc = 4 I^3 - J^2) and the sign rule: Disc < 0 is C (a non-real pair beside the two real
/// roots every pair has, math.md §8); Disc > 0 means four real roots, and the sign changes of f's
/// coefficients count the positive ones: 2 is E, 0 is I. No smallness, no Sturm-Habicht sequence,
/// no certification: what a float program would do.
template <class NT>
Position minimal_float(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  Mat<NT> P, E;
  for (std::size_t i = 0; i < 16; ++i) {
    P.a[i] = pd[i];
    E.a[i] = ed[i];
  }
  const Quartic<NT> f = characteristic_polynomial<NT>(P, E);
  const NT a = f[4], b = f[3], c = f[2], d = f[1], e = f[0];
  const NT I = 12 * a * e - 3 * b * d + c * c;
  const NT J = 72 * a * c * e + 9 * b * c * d - 27 * a * d * d - 27 * e * b * b - 2 * c * c * c;
  const NT disc27 = 4 * I * I * I - J * J;
  if (disc27 < 0) return Position::C;
  int changes = 0;
  for (int i = 0; i < 4; ++i)
    changes += (f[static_cast<std::size_t>(i)] < 0) != (f[static_cast<std::size_t>(i + 1)] < 0);
  return changes >= 2 ? Position::E : Position::I;
}

/// The baselines of `relpos judge`, compiled in their own translation unit without -frounding-math
/// (float_rules.cpp): the paper's rule (Sturm-Habicht counts and smallness) in double and in long
/// double, nullopt when undecided, and the minimal rule (discriminant and sign rule) in double.
std::optional<Position> paper_rule_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed);
std::optional<Position> paper_rule_long_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed);
Position minimal_rule_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed);

}  // namespace relpos::detail::oracle
