#include "margin/multiplier.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <cmath>
#include <utility>
#include <vector>

#include "algebra/between.hpp"
#include "algebra/flint_poly.hpp"
#include "algebra/flint_thread.hpp"
#include "algebra/power_of_two.hpp"
#include "margin/approximate.hpp"
#include "margin/descartes.hpp"
#include "margin/refine.hpp"

namespace relpos::detail {
namespace {

/// p(x) for rational coefficients.
template <std::size_t N>
Rational value(const std::array<Rational, N>& p, const Rational& x) {
  Rational v = p[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) v = v * x + p[i];
  return v;
}

/// x > 0 rounded to `digits` significant bits, as a dyadic rational.
std::optional<Rational> rounded(long double x, int digits) {
  int e = 0;
  const long double m = std::frexp(x, &e);  // x = m 2^e, 1/2 <= m < 1
  const long double scaled = std::round(std::ldexp(m, digits));
  const std::optional<Rational> whole = rational_near(scaled);  // an integer below 2^digits
  if (!whole) return std::nullopt;
  return *whole * detail::power_of_two(static_cast<long>(e) - digits);
}

/// p(sign * t) for integer coefficients, trailing zeros dropped.
template <std::size_t N>
std::vector<Integer> reflected(const std::array<Integer, N>& p, int sign) {
  std::vector<Integer> out;
  for (std::size_t i = 0; i < N; ++i) out.push_back(sign < 0 && i % 2 == 1 ? Integer(-p[i]) : p[i]);
  while (!out.empty() && out.back() == 0) out.pop_back();
  return out;
}

/// W(sign * t), W = f' s - f s' (the numerator of (f / s)'): its positive roots are the critical
/// points of r on the side `sign` (in m = alpha l / beta).
std::vector<Integer> critical_polynomial(const PointPencil& pencil, int sign) {
  const Quartic<Integer>& f = pencil.f;
  const Quadratic<Integer>& s = pencil.s;
  std::array<Integer, 6> w{};  // f' s - f s'
  for (int i = 1; i <= 4; ++i)
    for (int j = 0; j <= 2; ++j) w[static_cast<std::size_t>(i - 1 + j)] += Integer(i) * f[i] * s[j];
  for (int i = 0; i <= 4; ++i)
    for (int j = 1; j <= 2; ++j) w[static_cast<std::size_t>(i + j - 1)] -= Integer(j) * f[i] * s[j];
  return reflected(w, sign);
}

/// The square-free part of p, primitive (for Descartes' rule, which needs simple roots).
std::vector<Integer> square_free(const std::vector<Integer>& p) {
  fmpz_poly_t q, d, g;
  fmpz_poly_init(q);
  fmpz_poly_init(d);
  fmpz_poly_init(g);
  to_flint(q, p);
  fmpz_poly_derivative(d, q);
  fmpz_poly_gcd(g, q, d);
  fmpz_poly_div(q, q, g);  // exact: g divides q
  fmpz_poly_primitive_part(q, q);
  std::vector<Integer> out = from_flint(q);
  fmpz_poly_clear(q);
  fmpz_poly_clear(d);
  fmpz_poly_clear(g);
  return out;
}

}  // namespace

std::optional<Rational> below_multiplier(const PointPencil& pencil, const Rational& lo, bool inside, long bits) {
  flint_thread_cleanup_at_exit();
  const int sign = inside ? -1 : 1;
  const std::vector<Integer> w = critical_polynomial(pencil, sign);
  const Quartic<Rational> f = pencil.scaled(lo * lo);  // a positive multiple of f_lo, in m
  std::array<Rational, 3> sq, ds;
  for (std::size_t i = 0; i < 3; ++i) sq[i] = Rational(pencil.s[i]);
  ds = {sq[1], 2 * sq[2], Rational(0)};
  // m = sign t: in the domain (m > 0, or m_s < m < 0: right of the larger root of s, where s > 0 and
  // s' > 0), with f_lo(m) > 0.
  auto works = [&](const Rational& t) {
    const Rational m = sign < 0 ? Rational(-t) : t;
    if (inside && !(value(sq, m) > 0 && value(ds, m) > 0)) return false;
    return value(f, m) > 0;
  };
  auto lambda = [&](const Rational& t) { return pencil.lambda_of(sign < 0 ? Rational(-t) : t); };
  // Proposals first: the critical points in long double, rounded to a few significant bits first
  // (a short multiplier), one exact test each; as a rule one of them is enough.
  if (w.size() >= 2)
    for (const long double x : approximate_real_roots(w))
      if (x > 0)
        for (const int digits : {12, 24, 40, 0})
          if (const std::optional<Rational> t = digits ? rounded(x, digits) : rational_near(x);
              t && *t > 0 && works(*t))
            return lambda(*t);
  // Then rationals converging to the critical points, isolated exactly.
  const std::vector<Integer> ws = w.size() >= 2 ? square_free(w) : w;
  if (ws.size() >= 2)
    for (RootInterval r : positive_roots(ws)) {
      for (long precision = 16; precision <= 2 * bits + 64; precision += 8) {
        if (r.lo != r.hi) refine_root(ws, r, precision);
        const Rational t = r.lo == r.hi ? r.lo : rational_inside(r.lo, r.hi, Shortest::Bits);
        if (works(t)) return lambda(t);
        if (r.lo == r.hi) break;
      }
    }
  if (!inside) return std::nullopt;
  // The hard case: the supremum of r is its limit at m_s, so m = -t with t just below t_s = -m_s,
  // the smaller positive root of s(-t), approaching it.
  const std::vector<Integer> sm = reflected(pencil.s, -1);
  if (sm.size() != 3) return std::nullopt;
  const Integer disc = sm[1] * sm[1] - 4 * sm[2] * sm[0];
  std::optional<RootInterval> ts;
  if (disc == 0) {
    const Rational t(-sm[1], 2 * sm[2]);
    ts = RootInterval{t, t};
  } else if (disc > 0) {
    const std::vector<RootInterval> roots = positive_roots(sm);
    if (!roots.empty()) ts = roots.front();
  }
  if (!ts) return std::nullopt;
  for (long precision = 8; precision <= 2 * bits + 64; precision += 8) {
    const Rational below = 1 - detail::power_of_two(-static_cast<long>(precision));
    if (ts->lo != ts->hi) refine_root(sm, *ts, precision);
    const Rational t = ts->lo == ts->hi ? ts->lo * below : ts->lo;
    if (works(t)) return lambda(t);
  }
  return std::nullopt;
}

}  // namespace relpos::detail
