// The certificates' searches over the rationals (math.md §8): points converging to the real roots
// of a polynomial (search_near_roots), the refinement of one sign change with Newton steps and
// dyadic probes (refine_root), and the dyadic tools they share. Every point they return is exact;
// the caller's `accept` decides what a point is good for.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "algebra/power_of_two.hpp"
#include "anysize/exact.hpp"
#include "pair/integer_poly.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail::certificate {

using detail::power_of_two;
/// floor(log2 |x|) up to one, for x != 0.
long log2_of(const Rational& x);
/// x rounded down to a multiple of 2^e.
Rational floor_to(const Rational& x, long e);
/// floor(sqrt(x) 2^bits) / 2^bits for rational x >= 0.
Rational sqrt_below(const Rational& x, unsigned bits);
/// A rational within 2^-bits |b| of a + b sqrt(d) (d of `ls`), above it (up = true) or below it.
Rational approximate(const anysize::LambdaS& ls, const anysize::QuadraticReal& x, unsigned bits, bool up);
/// Rational roots of a polynomial of degree <= 2 (after removing repeated factors).
std::vector<Rational> rational_roots(const anysize::Poly& q);

/// Dyadic boxes isolating every real root of q's square-free part (Cauchy bound, bisection on Sturm
/// counts), for search_near_roots.
class RootBoxes {
 public:
  explicit RootBoxes(const anysize::Poly& q);
  /// One round: the midpoint of every box, then the halves that keep a root; `accept` is tried on
  /// each midpoint, and the first accepted is returned.
  template <class Accept>
  std::optional<Rational> round(Accept& accept) {
    std::vector<Box> next;
    for (const Box& box : boxes_) {
      const Rational mid = (box.lo + box.hi) / 2;
      if (accept(mid)) return mid;
      for (const Box& half : {Box{box.lo, mid}, Box{mid, box.hi}})
        if (variations(half.lo) - variations(half.hi) > 0) next.push_back(half);
    }
    boxes_ = std::move(next);
    return std::nullopt;
  }
  bool empty() const { return boxes_.empty(); }

 private:
  struct Box {
    Rational lo, hi;
  };
  int variations(const Rational& x);  ///< sign changes of the Sturm sequence at x
  std::vector<anysize::Poly> sturm_;
  std::vector<int> signs_;
  std::vector<Box> boxes_;
};

/// The real roots of q (any degree <= 3 here) refined jointly: returns, level by level, dyadic
/// points converging to every real root; `accept` is tried on each and the first accepted is returned.
template <class Accept>
std::optional<Rational> search_near_roots(const anysize::Poly& q, Accept accept, std::size_t max_bits) {
  RootBoxes boxes(q);
  // Isolate (bisection on Sturm counts), then refine every isolating interval one bit per round.
  for (std::size_t round = 0; round < max_bits && !boxes.empty(); ++round)
    if (std::optional<Rational> found = boxes.round(accept)) return found;
  return std::nullopt;
}

/// One round of refine_root on the bracket (good, bad) of width `width`: moves its ends towards the
/// sign change of q (`k`: the probes' width exponent, doubled after a bracketing round, halved
/// otherwise). True when `accept` took a new good end.
template <class Accept>
bool refine_round(const detail::IntegerPoly& q, Rational& good, Rational& bad, const Rational& width, Accept& accept,
                  long& k) {
  auto inside = [&](const Rational& x) { return good < bad ? good < x && x < bad : bad < x && x < good; };
  auto step = [&](const Rational& x) {  // moves one end to x (inside the bracket); true if `good` moved
    if (q.sign(x) <= 0) {
      good = x;
      return true;
    }
    bad = x;
    return false;
  };
  const Rational mid = (good + bad) / 2;
  const long e = log2_of(width) - k;
  const Rational delta = power_of_two(e);
  std::optional<Rational> x0 = q.newton_floor(mid, e);
  if (!x0 || !inside(*x0)) x0 = floor_to(mid, e);
  // The probes in the order from good to bad.
  Rational a = *x0 - delta, b = *x0 + 2 * delta;
  if (bad < good) std::swap(a, b);
  bool moved = false, bracketed = false;
  if (inside(a)) {
    moved = step(a);
    if (moved && inside(b)) bracketed = !step(b), moved = true;
  }
  if (moved && accept(good)) return true;
  const Rational now = good < bad ? bad - good : good - bad;
  k = bracketed ? 2 * k : std::max(2L, k / 2);
  return 2 * now > width && step((good + bad) / 2) && accept(good);
}

/// Shrinks the bracket of the one sign change of q between `good` (q <= 0) and `bad` (q > 0),
/// calling `accept` at every new good end until it returns true; false after `budget` rounds or
/// once the bracket is `budget` bits below the scale of `bad`.
/// Each round takes a Newton step from the midpoint (exact) and probes a dyadic neighbourhood of
/// width |bad - good| 2^-k around it: when the probes bracket the sign change, the bracket becomes
/// that neighbourhood and k doubles (quadratic convergence at a simple root), otherwise k halves
/// and a bisection keeps the bracket at least halving. A root wanted to b bits costs O(log b)
/// rounds near a simple root, and never more than b. `k` is the first round's: a bracket already
/// narrow (from doubles) starts with long steps.
template <class Accept>
bool refine_root(const detail::IntegerPoly& q, Rational good, Rational bad, Accept accept, std::size_t budget,
                 long k = 2) {
  if (accept(good)) return true;
  const long top = log2_of(bad);  // bad != 0 (good may be 0): the scale the budget counts bits from
  for (std::size_t round = 0; round < budget; ++round) {
    const Rational width = good < bad ? bad - good : good - bad;
    if (log2_of(width) < top - static_cast<long>(budget)) return false;  // as many bits as allowed
    if (refine_round(q, good, bad, width, accept, k)) return true;
  }
  return false;
}

}  // namespace relpos::detail::certificate
