// Root counting for the characteristic quartic from the signs of its Sturm-Habicht sequence
// (math.md §4: "count real, negative and positive roots with Sturm (or Sturm-Habicht)
// sequences"). The sequence is generated and verified by tools/gen_sturm_habicht.py
// (sturm_habicht_quartic.hpp) and evaluated generically over NT.
//
// For a non-defective sequence (all principal coefficients non-zero) each StHa_j is a positive
// multiple of the classical Sturm sequence, so the number of distinct real roots in (a, b) is
// Var(a) - Var(b) (Sturm's theorem), with Var the number of sign changes ignoring zeros. We evaluate
// at -inf, 0 and +inf; 0 is never a root of f because f(0) = det E < 0 (paper Lemma 3).
//
// Counting works on *signs* (QuarticSigns), so every stage -- static double filter, intervals, exact
// integers, the float baselines -- feeds the same counting code.
#pragma once

#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <array>
#include <optional>
#include <utility>

#include "algebra/pencil.hpp"
#include "algebra/sturm_habicht_quartic.hpp"
#include "relpos/polynomials.hpp"

namespace relpos {

using USign = CGAL::Uncertain<CGAL::Sign>;

/// Sign of a number of any type relpos instantiates: certain for exact and floating types,
/// possibly uncertain for intervals.
template <class T>
USign sign_of(const T& x) {
  return USign(CGAL::sign(x));
}
#ifdef __SIZEOF_FLOAT128__
inline USign sign_of(const __float128& x) {
  return USign(x > 0 ? CGAL::POSITIVE : (x < 0 ? CGAL::NEGATIVE : CGAL::ZERO));
}
#endif

/// Distinct real roots of a quartic and how many are negative / positive (0 is excluded by the caller).
struct RootCounts {
  int real = 0;
  int negative = 0;
  int positive = 0;
};

/// The decision quantities of the quartic: g_j of the Sturm-Habicht sequence (StHa_j = positive *
/// f4^k_j * g_j), evaluated in NT. Disc(f) is g0[0].
template <class NT>
struct SturmHabicht {
  NT g2[3], g1[2], g0[1];
  explicit SturmHabicht(const Quartic<NT>& f) {
    detail::sturm_habicht_quartic(f[0], f[1], f[2], f[3], f[4], g2, g1, g0);
  }
  /// With Disc(f) already known (e.g. from the invariants of f, far fewer products than g0's expansion).
  SturmHabicht(const Quartic<NT>& f, NT discriminant) : g0{std::move(discriminant)} {
    detail::sturm_habicht_quartic_g2_g1(f[0], f[1], f[2], f[3], f[4], g2, g1);
  }
  const NT& discriminant() const { return g0[0]; }
};

/// Signs of f's coefficients and of the g_j: everything root counting looks at.
/// Default: every sign uncertain (CGAL::Uncertain's own default is a *certain* zero, which would
/// read as an exact zero to a caller that never filled the field).
struct QuarticSigns {
  USign f[5] = {USign::indeterminate(), USign::indeterminate(), USign::indeterminate(), USign::indeterminate(),
                USign::indeterminate()};
  USign g2[3] = {USign::indeterminate(), USign::indeterminate(), USign::indeterminate()};
  USign g1[2] = {USign::indeterminate(), USign::indeterminate()};
  USign g0 = USign::indeterminate();
};

/// Every sign the decision uses (root counting and smallness): what every filter stage
/// certifies and the decision table reads.
struct DecisionSigns {
  QuarticSigns quartic;
  USign vertex = USign::indeterminate();
  USign graeffe = USign::indeterminate();
  /// Set by the semi-static stage when Disc(f) is uncertain and its computed value lies far inside
  /// its error bound (below 1/64 of it, semi_static_filter.cpp): the pair is within rounding of a
  /// multiple root, and no other evaluation from the same double data (intervals) is expected to
  /// certify that sign -- the ladder goes straight to the exact stage (math.md §11).
  bool disc_hopeless = false;
};

template <class NT>
QuarticSigns signs_of(const Quartic<NT>& f, const SturmHabicht<NT>& sh) {
  QuarticSigns s;
  for (int i = 0; i < 5; ++i) s.f[i] = sign_of(f[i]);
  for (int i = 0; i < 3; ++i) s.g2[i] = sign_of(sh.g2[i]);
  for (int i = 0; i < 2; ++i) s.g1[i] = sign_of(sh.g1[i]);
  s.g0 = sign_of(sh.g0[0]);
  return s;
}

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

/// A certain sign as an int, or nullopt if it is uncertain.
inline std::optional<int> certain(const USign& s) {
  if (!CGAL::is_certain(s)) return std::nullopt;
  return static_cast<int>(CGAL::get_certain(s));
}

}  // namespace detail

/// Root counts from the Sturm-Habicht signs, or nullopt when a needed sign is uncertain or the
/// sequence is defective (an exact zero principal coefficient; the caller then uses exact
/// factorisation, see roots.hpp). Requires f(0) != 0.
inline std::optional<RootCounts> count_roots(const QuarticSigns& q) {
  using detail::certain;
  auto s4 = certain(q.f[4]), s2 = certain(q.g2[0]), s1 = certain(q.g1[0]), s0 = certain(q.g0);
  if (!s4 || !s2 || !s1 || !s0 || *s4 == 0 || *s2 == 0 || *s1 == 0 || *s0 == 0) return std::nullopt;
  auto lift = [&](int s, int k) { return (k % 2 && *s4 < 0) ? -s : s; };  // StHa_j = f4^k_j * g_j
  const int p[5] = {*s4, *s4, lift(*s2, detail::kStHaF4Power2), lift(*s1, detail::kStHaF4Power1),
                    lift(*s0, detail::kStHaF4Power0)};
  int at_minus_inf[5];
  for (int j = 0; j < 5; ++j) at_minus_inf[j] = ((4 - j) % 2) ? -p[j] : p[j];  // deg StHa = 4 - j
  auto v0 = certain(q.f[0]), v1 = certain(q.f[1]), v2 = certain(q.g2[2]), v3 = certain(q.g1[1]);
  if (!v0 || !v1 || !v2 || !v3 || *v0 == 0) return std::nullopt;
  const int at_zero[5] = {*v0, *v1, lift(*v2, detail::kStHaF4Power2), lift(*v3, detail::kStHaF4Power1), p[4]};
  RootCounts c;
  c.real = detail::variations(at_minus_inf, 5) - detail::variations(p, 5);
  c.positive = detail::variations(at_zero, 5) - detail::variations(p, 5);
  c.negative = c.real - c.positive;
  return c;
}

template <class NT>
std::optional<RootCounts> count_roots(const Quartic<NT>& f, const SturmHabicht<NT>& sh) {
  return count_roots(signs_of(f, sh));
}

/// Disc(f) up to the positive factor 27, from the invariants of the quartic f4 x^4 + ... + f0:
/// 27 Disc(f) = 4 I^3 - J^2 with I = 12 f4 f0 - 3 f3 f1 + f2^2 and
/// J = 72 f4 f2 f0 + 9 f3 f2 f1 - 27 f4 f1^2 - 27 f0 f3^2 - 2 f2^3: a dozen products where the
/// expanded Sturm-Habicht g0 (= Disc(f)) takes about eighty.
template <class NT>
NT discriminant_times_27(const Quartic<NT>& f) {
  const NT i = NT(12) * f[4] * f[0] - NT(3) * f[3] * f[1] + f[2] * f[2];
  const NT j = (NT(72) * f[4] * f[0] - NT(2) * f[2] * f[2]) * f[2] + NT(9) * f[3] * f[2] * f[1] -
               NT(27) * (f[4] * f[1] * f[1] + f[0] * f[3] * f[3]);
  return NT(4) * i * i * i - j * j;
}

/// What the signs of f's coefficients and of Disc(f) alone say about the roots of f for a valid
/// pair (math.md §8: f always has two distinct real roots at or below lambda_s < 0, so g2 and g1
/// of the Sturm-Habicht sequence are not needed when Disc(f) != 0).
enum class DiscriminantCase : unsigned char {
  Undecided,    ///< a needed sign is uncertain, Disc(f) = 0, or f0, f4 not certified negative
  NonRealPair,  ///< Disc(f) < 0: two distinct negative roots and a non-real pair
  TwoPositive,  ///< Disc(f) > 0 and V = 2: four distinct real roots, two of them positive
  AllNegative,  ///< Disc(f) > 0 and V = 0: four distinct negative roots
};

/// The case from the signs of f[0..4] and of Disc(f) (q.g0); q.g2 and q.g1 are not read.
inline DiscriminantCase discriminant_case(const QuarticSigns& q) {
  using detail::certain;
  const auto f4 = certain(q.f[4]), f0 = certain(q.f[0]), disc = certain(q.g0);
  // f4 = det P < 0 and f0 = det E < 0 always; a source that cannot certify them is not trusted further.
  if (!f4 || !f0 || !disc || *f4 >= 0 || *f0 >= 0 || *disc == 0) return DiscriminantCase::Undecided;
  // Disc < 0: exactly one non-real pair (f has >= 2 negative roots, so never four non-real ones);
  // the two real roots are the (distinct) negative ones.
  if (*disc < 0) return DiscriminantCase::NonRealPair;
  // Disc > 0: four distinct real roots, and Descartes' rule is exact: #positive = V.
  int s[5] = {*f4, 0, 0, 0, *f0};
  bool all_certain = true, some_positive = false;
  for (int i = 1; i <= 3; ++i) {
    const auto si = certain(q.f[4 - i]);
    if (!si) {
      all_certain = false;
      continue;
    }
    s[i] = *si;
    some_positive = some_positive || *si > 0;
  }
  if (all_certain) {
    const int v = detail::variations(s, 5);
    if (v == 0) return DiscriminantCase::AllNegative;
    if (v == 2) return DiscriminantCase::TwoPositive;
    return DiscriminantCase::Undecided;  // V = 4 is impossible (>= 2 negative roots): never trust it
  }
  // A certain positive f_i between f4 < 0 and f0 < 0 gives V >= 2, and V <= 2 always.
  return some_positive ? DiscriminantCase::TwoPositive : DiscriminantCase::Undecided;
}

/// The root facts a decided case stands for: f is square-free (Disc(f) != 0), so f~ = f has no
/// multiple root and Disc(f~) has the sign of Disc(f) (math.md §3). Undecided: no facts (zeros).
inline RootFacts root_facts_of(DiscriminantCase c) {
  RootFacts x;
  x.degree_ftilde = 4;
  switch (c) {
    case DiscriminantCase::NonRealPair:
      x.real = 2, x.negative = 2, x.positive = 0, x.nonreal = 2, x.sign_disc_f = -1;
      break;
    case DiscriminantCase::TwoPositive:
      x.real = 4, x.negative = 2, x.positive = 2, x.nonreal = 0, x.sign_disc_f = 1;
      break;
    case DiscriminantCase::AllNegative:
      x.real = 4, x.negative = 4, x.positive = 0, x.nonreal = 0, x.sign_disc_f = 1;
      break;
    case DiscriminantCase::Undecided:
      break;
  }
  x.sign_disc_ftilde = x.sign_disc_f;
  return x;
}

/// Whether the answer for this case depends on rho (NonRealPair and AllNegative; TwoPositive is E
/// for any size).
inline bool discriminant_case_needs_rho(DiscriminantCase c) {
  return c == DiscriminantCase::NonRealPair || c == DiscriminantCase::AllNegative;
}

}  // namespace relpos
