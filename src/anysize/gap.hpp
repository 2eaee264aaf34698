// The one sign test math.md §8 adds to the root counts: where the roots of f lie against
// lambda_s, the root of s(lambda) = det(lambda A + M) nearest 0.
//
// f always has a root in [lambda_s2, lambda_s] and one below lambda_s2 (math.md §8). When the
// Sturm-Habicht counts say that f is square-free with four real roots, none positive, the other two
// lie either both in (lambda_s, 0) -- I -- or both at or below lambda_s -- C. Taylor-expand f at
// lambda_s: f(lambda_s + mu) = c0 + c1 mu + c2 mu^2 + c3 mu^3 + c4 mu^4 with c0 = f(lambda_s) <= 0
// (Sylvester, math.md §8) and c4 = f4 = det P < 0. All its roots are real, so Descartes' rule counts
// the roots in (lambda_s, oo) exactly: there is one iff some c1, c2, c3 is positive (with c0 <= 0 and
// c4 < 0 the sign of c0 never changes whether the count is zero). So
//   I  <=>  f'(lambda_s) > 0 or f''(lambda_s) > 0 or f'''(lambda_s) > 0,   C otherwise.
//
// lambda_s = (-s1 + sqrt(d)) / (2 s2), d = s1^2 - 4 s2 s0 >= 0 (s2 > 0, s1 > 0, s0 = det M > 0). For g
// of degree n, (2 s2)^n g(lambda_s) = U + V sqrt(d) with U, V polynomials in the coefficients of f and
// s, and sign(U + V sqrt d) is read from sign U, sign V and sign(U^2 - V^2 d): ring operations only,
// so the test is written once, generic over the number type, and goes through the same ladder as
// every other decision (semi-static doubles, intervals, exact integers) -- an exact sign at an
// algebraic point by reduction modulo s, never a general algebraic number.
#pragma once

#include <optional>

#include "algebra/pencil.hpp"
#include "algebra/sturm.hpp"

namespace relpos::detail::anysize {

/// Number of quantities of the gap test: d, then U, V, W for f', f'', f''' (GapQuantities::flatten).
inline constexpr int kGapSigns = 10;

/// U, V and W = U^2 - V^2 d for f', f'', f''' at lambda_s, and d = Disc(s).
template <class NT>
struct GapQuantities {
  NT d;
  NT u[3], v[3], w[3];
  GapQuantities(const Quartic<NT>& f, const Quadratic<NT>& s) {
    d = s[1] * s[1] - NT(4) * s[2] * s[0];
    const NT two_s2 = NT(2) * s[2];
    const NT m = NT(0) - s[1];
    // (-s1 + sqrt d)^k = pa[k] + pb[k] sqrt d, and (2 s2)^k.
    NT pa[4] = {NT(1), m, NT(0), NT(0)}, pb[4] = {NT(0), NT(1), NT(0), NT(0)}, t[4] = {NT(1), two_s2, NT(0), NT(0)};
    for (int k = 2; k < 4; ++k) {
      pa[k] = pa[k - 1] * m + pb[k - 1] * d;
      pb[k] = pa[k - 1] + pb[k - 1] * m;
      t[k] = t[k - 1] * two_s2;
    }
    // f' = f1 + 2 f2 l + 3 f3 l^2 + 4 f4 l^3;  f''/2 = f2 + 3 f3 l + 6 f4 l^2;  f'''/6 = f3 + 4 f4 l.
    const NT g1[4] = {f[1], NT(2) * f[2], NT(3) * f[3], NT(4) * f[4]};
    const NT g2[3] = {f[2], NT(3) * f[3], NT(6) * f[4]};
    const NT g3[2] = {f[3], NT(4) * f[4]};
    const NT* g[3] = {g1, g2, g3};
    for (int j = 0; j < 3; ++j) {
      const int n = 3 - j;
      NT a(0), b(0);
      for (int k = 0; k <= n; ++k) {
        a = a + g[j][k] * pa[k] * t[n - k];
        b = b + g[j][k] * pb[k] * t[n - k];
      }
      u[j] = a;
      v[j] = b;
      w[j] = a * a - b * b * d;
    }
  }
  /// d, u[0..2], v[0..2], w[0..2].
  template <class Out>
  void flatten(Out* out) const {
    out[0] = d;
    for (int j = 0; j < 3; ++j) {
      out[1 + j] = u[j];
      out[4 + j] = v[j];
      out[7 + j] = w[j];
    }
  }
};

/// Certain signs as ints (nullopt: uncertain), for any number type the ladder uses.
template <class NT>
std::optional<int> certain_sign(const NT& x) {
  return detail::certain(sign_of(x));
}

/// sign(U + V sqrt d) from the signs of U, V, W = U^2 - V^2 d and d >= 0; nullopt when a needed sign
/// is uncertain.
inline std::optional<int> sign_plus_sqrt(std::optional<int> su, std::optional<int> sv, std::optional<int> sw,
                                         std::optional<int> sd) {
  if (!su || !sv) return std::nullopt;
  if (*sv == 0) return su;
  if (*su == 0) {
    if (!sd) return std::nullopt;
    return *sd > 0 ? *sv : 0;
  }
  if (*su == *sv) return su;
  if (!sw) return std::nullopt;
  return *su * *sw;
}

/// Whether f has roots in (lambda_s, 0), for square-free f with four real roots, none positive
/// (the comment at the top): true (I), false (C), nullopt when a sign is uncertain. `signs` are
/// those of the quantities in GapQuantities::flatten order, nullopt when uncertain.
inline std::optional<bool> roots_above_lambda_s(const std::optional<int> (&signs)[kGapSigns]) {
  bool all_certain = true;
  for (int j = 0; j < 3; ++j) {
    const auto c = sign_plus_sqrt(signs[1 + j], signs[4 + j], signs[7 + j], signs[0]);
    if (!c) {
      all_certain = false;
      continue;
    }
    if (*c > 0) return true;  // one certified positive coefficient decides
  }
  if (all_certain) return false;
  return std::nullopt;
}

/// The same with the signs taken in NT by `sign` (nullopt: uncertain).
template <class NT, class SignOf>
std::optional<bool> roots_above_lambda_s(const GapQuantities<NT>& q, SignOf sign) {
  NT flat[kGapSigns];
  q.flatten(flat);
  std::optional<int> signs[kGapSigns];
  for (int i = 0; i < kGapSigns; ++i) signs[i] = sign(flat[i]);
  return roots_above_lambda_s(signs);
}

template <class NT>
std::optional<bool> roots_above_lambda_s(const Quartic<NT>& f, const Quadratic<NT>& s) {
  return roots_above_lambda_s(GapQuantities<NT>(f, s), [](const NT& x) { return certain_sign(x); });
}

}  // namespace relpos::detail::anysize
