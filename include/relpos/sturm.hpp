// Root counting for the characteristic quartic from the signs of its Sturm-Habicht sequence
// (math.md section 3: "count real, negative and positive roots with Sturm (or Sturm-Habicht)
// sequences"). Generic over the number type; the sequence itself is generated and verified by
// tools/gen_sturm_habicht.py (include/relpos/detail/sturm_habicht_quartic.hpp).
//
// For a non-defective sequence (all principal coefficients non-zero) each StHa_j is a positive
// multiple of the classical Sturm sequence, so the number of distinct real roots in (a, b) is
// Var(a) - Var(b) (Sturm's theorem), with Var the number of sign changes ignoring zeros. We evaluate
// at -inf, 0 and +inf; 0 is never a root of f because f(0) = det E < 0 (paper Lemma 3).
#pragma once

#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <array>
#include <optional>

#include "relpos/detail/sturm_habicht_quartic.hpp"
#include "relpos/pencil.hpp"

namespace relpos {

/// Distinct real roots of a quartic and how many are negative / positive (0 is excluded by the caller).
struct RootCounts {
  int real = 0;
  int negative = 0;
  int positive = 0;
};

/// The decision quantities of the quartic: the principal Sturm-Habicht coefficients and the values
/// of the sequence at 0, as numbers of type NT (Disc(f) is g0).
template <class NT>
struct SturmHabicht {
  NT g2[3], g1[2], g0[1];
  explicit SturmHabicht(const Quartic<NT>& f) {
    detail::sturm_habicht_quartic(f[0], f[1], f[2], f[3], f[4], g2, g1, g0);
  }
  const NT& discriminant() const { return g0[0]; }
};

namespace detail {

/// Number of sign changes in a sequence of signs, zeros skipped.
inline int variations(const int* s, int n) {
  int v = 0, last = 0;
  for (int i = 0; i < n; ++i) {
    if (s[i] == 0) continue;
    if (last != 0 && s[i] != last) ++v;
    last = s[i];
  }
  return v;
}

/// A certain sign as an int, or nullopt if NT could not certify it.
template <class S>
std::optional<int> certain_sign(const S& s) {
  if (!CGAL::is_certain(s)) return std::nullopt;
  return static_cast<int>(CGAL::get_certain(s));
}

}  // namespace detail

/// Root counts from the Sturm-Habicht signs, or nullopt when a needed sign is uncertain (NT =
/// interval) or the sequence is defective (an exact zero principal coefficient; the caller then uses
/// exact factorisation, see roots.hpp). Requires f(0) != 0.
template <class NT>
std::optional<RootCounts> count_roots(const Quartic<NT>& f, const SturmHabicht<NT>& sh) {
  using detail::certain_sign;
  auto s4 = certain_sign(CGAL::sign(f[4]));
  auto s2 = certain_sign(CGAL::sign(sh.g2[0]));
  auto s1 = certain_sign(CGAL::sign(sh.g1[0]));
  auto s0 = certain_sign(CGAL::sign(sh.g0[0]));
  if (!s4 || !s2 || !s1 || !s0 || *s4 == 0 || *s2 == 0 || *s1 == 0 || *s0 == 0) return std::nullopt;
  // StHa_j = (positive) * f4^k_j * g_j
  auto lift = [&](int s, int k) { return (k % 2 && *s4 < 0) ? -s : s; };
  const int p[5] = {*s4, *s4, lift(*s2, detail::kStHaF4Power2), lift(*s1, detail::kStHaF4Power1),
                    lift(*s0, detail::kStHaF4Power0)};
  int at_minus_inf[5];
  for (int j = 0; j < 5; ++j) at_minus_inf[j] = ((4 - j) % 2) ? -p[j] : p[j];  // degree of StHa is 4-j
  auto v0 = certain_sign(CGAL::sign(f[0]));
  auto v1 = certain_sign(CGAL::sign(f[1]));
  auto v2 = certain_sign(CGAL::sign(sh.g2[2]));
  auto v3 = certain_sign(CGAL::sign(sh.g1[1]));
  if (!v0 || !v1 || !v2 || !v3 || *v0 == 0) return std::nullopt;
  const int at_zero[5] = {*v0, *v1, lift(*v2, detail::kStHaF4Power2), lift(*v3, detail::kStHaF4Power1), p[4]};
  RootCounts c;
  c.real = detail::variations(at_minus_inf, 5) - detail::variations(p, 5);
  c.positive = detail::variations(at_zero, 5) - detail::variations(p, 5);
  c.negative = c.real - c.positive;
  return c;
}

}  // namespace relpos
