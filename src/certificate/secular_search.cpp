#include "certificate/secular_search.hpp"

#include <flint/fmpz_poly.h>
#include <gmp.h>

#include <algorithm>

#include "algebra/flint_thread.hpp"
#include "certificate/kinds.hpp"
#include "certificate/rational_search.hpp"

namespace relpos::detail::certificate {

Secular::Secular(const PairContext& pr) {
  detail::flint_thread_cleanup_at_exit();
  fmpz_poly_t f, s, d, gp, ge;  // gp = f' s - f s', ge = f s - lambda gp (d: scratch)
  for (auto* q : {f, s, d, gp, ge}) fmpz_poly_init(q);
  pr.fz().to_flint(f);
  detail::IntegerPoly(pr.s_poly()).to_flint(s);
  fmpz_poly_derivative(d, f);
  fmpz_poly_mul(gp, d, s);
  fmpz_poly_derivative(d, s);
  fmpz_poly_mul(d, f, d);
  fmpz_poly_sub(gp, gp, d);
  fmpz_poly_mul(ge, f, s);
  fmpz_poly_shift_left(d, gp, 1);
  fmpz_poly_sub(ge, ge, d);
  e = detail::IntegerPoly(ge);
  p = detail::IntegerPoly(gp);
  for (auto* q : {f, s, d, gp, ge}) fmpz_poly_clear(q);
  budget = 1024 + 16 * (e.bits() + p.bits() + pr.fz().bits());
}

namespace {

/// What refine_root accepts on the curve: a good end lambda where p(x(lambda)) has the sign `want`
/// gives its point to `consider`; true once `found` holds a point.
auto curve_accept(const PairContext& pr, const Secular& sec, int want, const std::optional<V3>& found,
                  const ConsiderExact& consider) {
  return [&pr, &sec, want, &found, &consider](const Rational& l) {
    if (sec.p.sign(l) == want)
      if (const auto x = x_of(pr, l)) consider(*x);
    return found.has_value();
  };
}

/// A rational in (lambda_s, 0) within about 2^-bits of lambda_s (relative to lambda_s, or to the
/// irrational part's coefficient); nullopt while the approximation is too coarse.
std::optional<Rational> above_lambda_s(const anysize::LambdaS& ls, unsigned bits) {
  Rational l = approximate(ls, ls.value(), bits, true);
  if (ls.rational()) {
    Rational step;  // |l| 2^-bits, fresh: written in place (a copy of l would share l's value)
    mpq_abs(step.mpq(), l.mpq());
    mpq_div_2exp(step.mpq(), step.mpq(), bits);
    l += step;
  }
  if (!(l < 0) || ls.compare(l) <= 0) return std::nullopt;
  return l;
}

/// Hard case of the max side: the maximisers are x^ + w, w in the kernel of lambda_s A + M with
/// w^T M w = -e(x^) (hard_case); x^ and the kernel's basis are rounded to `bits` and the point
/// x0 + t w0 taken with t a rational just inside the roots of e(x0 + t w0) = 0 (exact).
void kernel_walk(const PairContext& pr, const Certificate& hard, unsigned bits, const ConsiderExact& consider) {
  const anysize::LambdaS& ls = pr.lambda_s();
  const Matrix4& E = pr.ellipsoid().matrix();
  V3 x0;
  for (int i = 0; i < 3; ++i) x0[i] = approximate(ls, {hard.centre[i].a, hard.centre[i].b}, bits, true);
  for (const auto& dir : hard.directions) {
    V3 w;
    for (int i = 0; i < 3; ++i) w[i] = approximate(ls, {dir[i].a, dir[i].b}, bits, true);
    // e(x0 + t w) = e(x0) + 2 t w^T (M x0 + m) + t^2 w^T M w <= 0 between its roots.
    Rational mw(0), g(0);
    for (int i = 0; i < 3; ++i) {
      Rational mi = E(i, 3), wi(0);
      for (int j = 0; j < 3; ++j) {
        mi += E(i, j) * x0[j];
        wi += E(i, j) * w[j];
      }
      g += w[i] * mi;
      mw += w[i] * wi;
    }
    const Rational disc = g * g - mw * e_at(pr, x0);
    if (disc < 0 || mw == 0) continue;
    const Rational r = sqrt_below(disc, bits);
    for (int sign : {1, -1}) {
      V3 x;
      const Rational t = (-g + sign * r) / mw;  // |r| <= sqrt(disc): inside the roots
      for (int i = 0; i < 3; ++i) x[i] = x0[i] + t * w[i];
      consider(x);
    }
  }
}

}  // namespace

// Steps start long: the bracket is a double's width, where Newton's step is good to about twice as
// many bits.
bool refine_from_doubles(const PairContext& pr, const Secular& sec, const DoubleBracket& bracket, int want,
                         std::optional<V3>& found, const ConsiderExact& consider) {
  if (!bracket) return false;
  Rational good = exact_rational(bracket->first), bad = exact_rational(bracket->second);
  // At a double's width the doubles' signs are rounding noise: each end moves away from the other
  // by growing multiples of the width until its exact sign holds.
  const Rational width = bad - good;  // signed: from good towards bad
  Rational step = width;
  for (int i = 0; i < 6 && sec.e.sign(good) > 0; ++i, step *= 256) good -= step;
  step = width;
  for (int i = 0; i < 6 && sec.e.sign(bad) <= 0; ++i, step *= 256) bad += step;
  // good past 0 becomes 0 (x(0) is the centre, e < 0 there); bad strictly on the side searched.
  if (want < 0 ? good < 0 : good > 0) good = 0;
  const bool side = want < 0 ? bad > 0 : bad < 0 && pr.lambda_s().compare(bad) > 0;
  if (!side || sec.e.sign(good) > 0 || sec.e.sign(bad) <= 0) return false;
  return refine_root(sec.e, good, bad, curve_accept(pr, sec, want, found, consider), sec.budget, 32);
}

// x(0) is the centre; else the minimiser x(lambda*) lies on the surface, lambda* > 0 the root of
// e(x(lambda)). Its bracket is found on powers of two (galloping exponents: a body of size 2^-k costs
// O(log k) steps to reach its scale), then bisected; every lower end lambda has e(x(lambda)) <= 0, and
// as it tends to lambda* p(x(lambda)) tends to min p < 0, so the first lower end with p(x(lambda)) < 0
// gives the point, exactly on the curve and inside the solid, after as many bits as the margin of p
// needs.
void min_side_point(const PairContext& pr, const Secular& sec, std::optional<V3>& found,
                    const ConsiderExact& consider) {
  if (sec.e.sign(Rational(0)) <= 0 && sec.p.sign(Rational(0)) < 0)
    if (const auto x = x_of(pr, Rational(0))) consider(*x);
  if (found) return;
  // lo, hi > 0 with e(x(lo)) <= 0 < e(x(hi)).
  const int up = sec.e.sign(Rational(1)) <= 0 ? 1 : -1;
  long k = 0, prev = 0;
  for (long step = 1; (sec.e.sign(power_of_two(k)) <= 0) == (up > 0); step *= 2) {
    if (static_cast<std::size_t>(step) > sec.budget) throw internal_error("no bracket of the minimiser's multiplier");
    prev = k;
    k = up * step;
  }
  // Down to one binade: binary search on the exponent between prev and k.
  long lo_exp = std::min(prev, k), hi_exp = std::max(prev, k);
  while (hi_exp - lo_exp > 1) {
    const long mid = lo_exp + (hi_exp - lo_exp) / 2;
    (sec.e.sign(power_of_two(mid)) <= 0 ? lo_exp : hi_exp) = mid;
  }
  refine_root(sec.e, power_of_two(lo_exp), power_of_two(hi_exp), curve_accept(pr, sec, -1, found, consider),
              sec.budget);
}

// As the min side with the order reversed: lambda* in (lambda_s, 0) is bracketed by 0 and rationals
// approaching lambda_s from above with doubling precision. When e(x(lambda)) stays <= 0 up to
// lambda_s (the hard case), the maximiser is a limit point: the approach itself reaches it when p > 0
// at x^ = lim x(lambda), and the walk along the kernel of lambda_s A + M otherwise; both are tried at
// every precision, so the search ends whichever case holds.
void max_side_point(const PairContext& pr, const Secular& sec, std::optional<V3>& found,
                    const ConsiderExact& consider) {
  auto try_lambda = [&](const Rational& l) {
    if (sec.e.sign(l) <= 0 && sec.p.sign(l) > 0)
      if (const auto x = x_of(pr, l)) consider(*x);
  };
  try_lambda(Rational(0));
  if (found) return;
  std::optional<Rational> lo;
  std::optional<Certificate> hard;
  for (unsigned bits = 4; bits <= sec.budget && !found && !lo; bits *= 2) {
    const std::optional<Rational> l = above_lambda_s(pr.lambda_s(), bits);
    if (!l) continue;
    if (sec.e.sign(*l) > 0) {
      lo = l;
      break;
    }
    try_lambda(*l);
    if (found) return;
    if (!hard) {
      hard.emplace();
      if (!hard_case(pr, *hard)) hard->directions.clear();
    }
    kernel_walk(pr, *hard, bits, consider);
  }
  if (!lo) return;
  refine_root(sec.e, Rational(0), *lo, curve_accept(pr, sec, 1, found, consider), sec.budget);
}

}  // namespace relpos::detail::certificate
