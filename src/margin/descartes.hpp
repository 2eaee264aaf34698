// Real roots of an integer polynomial on a rational interval, by Descartes' rule of signs after the
// Moebius map x -> (a + b x) / (1 + x) that sends (0, oo) onto (a, b) (math.md §19): the number of
// sign variations V of (1 + x)^n p((a + b x) / (1 + x)) bounds the number of roots of p in the open
// interval (a, b) and has its parity, so V = 0 proves there is none and V = 1 that there is exactly
// one (Vincent's theorem: for a square-free p, narrow enough intervals always give 0 or 1).
#pragma once

#include <vector>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// V for p on (a, b), a < b (p non-zero).
int descartes_bound(const std::vector<Integer>& p, const Rational& a, const Rational& b);

/// An interval holding exactly one real root of a polynomial: open (lo, hi) with lo < hi and a sign
/// change of p between the ends, or lo == hi, the root itself (a rational root met by a split).
struct RootInterval {
  Rational lo, hi;
};

/// The positive real roots of a square-free integer polynomial of degree >= 1, in increasing order,
/// each in its own interval (bisection from (0, 2^e), 2^e above every root, until Descartes' bound is
/// 0 or 1 on each piece).
std::vector<RootInterval> positive_roots(const std::vector<Integer>& p);

/// Whether (a, b) holds exactly one root of pi and it is a root of f: f divides pi (over Z), Descartes'
/// bound of f on (a, b) is 1, and that of the cofactor pi / f^j (f divided out as often as it divides)
/// is 0. f non-constant, a < b.
bool isolates(const std::vector<Integer>& pi, const std::vector<Integer>& f, const Rational& a, const Rational& b);

/// Halves `r`'s interval on the exact sign of p at the midpoint (a no-op when lo == hi; the root
/// itself when the midpoint is the root).
void bisect(const std::vector<Integer>& p, RootInterval& r);

}  // namespace relpos::detail
