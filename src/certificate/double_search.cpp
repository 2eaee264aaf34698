#include "certificate/double_search.hpp"

#include <algorithm>
#include <cmath>

#include "algebra/cramer.hpp"
#include "algebra/forms.hpp"
#include "certificate/rational_search.hpp"
#include "filters/checked_int.hpp"

namespace relpos::detail::certificate {

std::optional<Enclosure3> enclosure(const V3& x) {
  Enclosure3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    out[i] = forms::tight_interval(x[i]);
    if (!std::isfinite(out[i].first) || !std::isfinite(out[i].second)) return std::nullopt;
  }
  return out;
}

Enclosure3 enclosure(const double x[3]) {
  Enclosure3 out;
  for (std::size_t i = 0; i < 3; ++i) out[i].first = out[i].second = x[i] == 0 ? 0.0 : x[i];
  return out;
}

void difference(mpq_ptr out, mpq_srcptr a, mpq_srcptr b, mp_bitcnt_t shift) {
  const long ka = forms::power_of_two_exponent(mpq_denref(a)), kb0 = forms::power_of_two_exponent(mpq_denref(b));
  if (ka < 0 || kb0 < 0) {
    mpq_div_2exp(out, b, shift);
    mpq_sub(out, a, out);
    return;
  }
  const unsigned long kb = static_cast<unsigned long>(kb0) + shift;
  const unsigned long top = std::max(static_cast<unsigned long>(ka), kb);
  const mpz_ptr num = mpq_numref(out), den = mpq_denref(out);
  if (top - static_cast<unsigned long>(ka) <= 63 && top - kb <= 63 && mpz_fits_slong_p(mpq_numref(a)) &&
      mpz_fits_slong_p(mpq_numref(b))) {  // the same on 128-bit words (both terms below 2^126)
    const Int128 one = 1, n = mpz_get_si(mpq_numref(a)) * (one << (top - static_cast<unsigned long>(ka))) -
                              mpz_get_si(mpq_numref(b)) * (one << (top - kb));
    const auto magnitude = static_cast<Int128>(n < 0 ? -n : n);
    const auto high = static_cast<unsigned long>(magnitude >> 64), low = static_cast<unsigned long>(magnitude);
    const unsigned long zeros = low != 0 ? static_cast<unsigned long>(__builtin_ctzl(low))
                                         : 64 + static_cast<unsigned long>(__builtin_ctzl(high | (1UL << 63)));
    const unsigned long twos = n == 0 ? top : std::min(zeros, top);
    const Int128 m = n == 0 ? 0 : magnitude >> twos;  // exact
    const unsigned long limbs[2] = {static_cast<unsigned long>(m), static_cast<unsigned long>(m >> 64)};
    mpz_import(num, 2, -1, sizeof(unsigned long), 0, 0, limbs);
    if (n < 0) mpz_neg(num, num);
    mpz_set_ui(den, 0);
    mpz_setbit(den, top - twos);
    return;
  }
  mpz_mul_2exp(den, mpq_numref(b), top - kb);  // den as a temporary
  mpz_mul_2exp(num, mpq_numref(a), top - static_cast<unsigned long>(ka));
  mpz_sub(num, num, den);
  const unsigned long twos = mpz_sgn(num) == 0 ? top : std::min<unsigned long>(mpz_scan1(num, 0), top);
  mpz_tdiv_q_2exp(num, num, twos);
  mpz_set_ui(den, 1);
  mpz_mul_2exp(den, den, top - twos);
}

std::optional<V3> approximate_centre(const DoubleMatrix4& e, double doubles[3]) {
  double k[3][4];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) k[i][j] = e[static_cast<std::size_t>(4 * i + j)] * (j == 3 ? -1 : 1);
  const std::array<double, 4> d = detail::cramer(k);
  V3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    const double x = d[i + 1] / d[0];
    if (!std::isfinite(x)) return std::nullopt;
    doubles[i] = x == 0 ? 0.0 : x;       // the rational's double (no -0)
    forms::set_double(out[i].mpq(), x);  // exact; a fresh value, written in place
  }
  return out;
}

namespace {

/// The pair's curve in doubles: x(lambda) by Cramer's rule and e(x).
class DoubleCurve {
 public:
  DoubleCurve(const DoubleMatrix4& em, const DoubleMatrix4& pm) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        E[i][j] = em[static_cast<std::size_t>(4 * i + j)];
        P[i][j] = pm[static_cast<std::size_t>(4 * i + j)];
        if (!std::isfinite(E[i][j]) || !std::isfinite(P[i][j])) finite = false;
      }
  }
  bool x_of(double l, double x[3]) const {
    double k[3][3], r[3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) k[i][j] = l * P[i][j] + E[i][j];
      r[i] = -(l * P[i][3] + E[i][3]);
    }
    const double det = k[0][0] * (k[1][1] * k[2][2] - k[1][2] * k[2][1]) -
                       k[0][1] * (k[1][0] * k[2][2] - k[1][2] * k[2][0]) +
                       k[0][2] * (k[1][0] * k[2][1] - k[1][1] * k[2][0]);
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
    for (int c = 0; c < 3; ++c) {
      double m[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = j == c ? r[i] : k[i][j];
      x[c] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
              m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
             det;
    }
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(x[c])) return false;
    return true;
  }
  double e_of(const double x[3]) const {
    double acc = E[3][3];
    for (int i = 0; i < 3; ++i) {
      acc += 2 * E[i][3] * x[i];
      for (int j = 0; j < 3; ++j) acc += x[i] * E[i][j] * x[j];
    }
    return acc;
  }
  bool finite = true;

 private:
  double E[4][4], P[4][4];
};

/// A point found by a bisection, and the same point pulled towards the centre (exact rationals), to
/// `consider`; `wanted`: the point the search is for (inside or outside), the pulls stop once it is.
void try_point(const double x[3], const std::optional<V3>& wanted, const V3& centre, const Consider& consider) {
  // Each point a fresh V3 written in place (`consider` may keep it: its values are then shared).
  V3 q;
  for (int i = 0; i < 3; ++i) forms::set_double(q[i].mpq(), x[i]);  // exact: x is finite
  const std::optional<Enclosure3> at = enclosure(x);
  consider(q, &at);
  if (wanted) return;
  mpq_t diff[3];  // never shared: reused
  for (auto& v : diff) mpq_init(v);
  for (int i = 0; i < 3; ++i) difference(diff[i], q[i].mpq(), centre[i].mpq(), 0);
  for (int k : {40, 20, 10, 4, 1}) {  // pulled towards the centre: inside the solid when x is not
    V3 y;                             // centre + (1 - 2^-k)(q - centre) = q - 2^-k (q - centre)
    for (int i = 0; i < 3; ++i) difference(y[i].mpq(), q[i].mpq(), diff[i], static_cast<mp_bitcnt_t>(k));
    consider(y, nullptr);
    if (wanted) break;
  }
  for (auto& v : diff) mpq_clear(v);
}

/// lo: e(x(lo)) <= 0 side; hi: e(x(hi)) > 0 side (either order on the line). Regula falsi with
/// the Illinois modification (the end that stays has its value halved), bisection when the
/// interpolated point is not strictly inside; down to a bracket of one or two doubles, as plain
/// bisection would, in a fraction of the steps. The last good point goes to try_point.
void bisect(const DoubleCurve& curve, double lo, double hi, const std::optional<V3>& wanted, DoubleBracket& bracket,
            const V3& centre, const Consider& consider) {
  double x[3], best[3];
  bool have = false;
  if (!curve.x_of(lo, x) || !curve.x_of(hi, best)) return;
  double glo = curve.e_of(x), ghi = curve.e_of(best);
  if (!(glo <= 0 && ghi > 0)) glo = ghi = 0;  // no usable values: bisection only
  int side = 0;
  for (int i = 0; i < 200; ++i) {
    const double half = lo + (hi - lo) / 2;
    if (!(half != lo && half != hi)) break;
    double mid = glo < 0 && ghi > 0 ? (lo * ghi - hi * glo) / (ghi - glo) : half;
    if (!(mid > std::min(lo, hi) && mid < std::max(lo, hi))) mid = half;
    if (!curve.x_of(mid, x)) return;
    const double g = curve.e_of(x);
    if (g <= 0) {
      lo = mid;
      glo = g;
      if (side == -1) ghi /= 2;
      side = -1;
      std::copy(x, x + 3, best);
      have = true;
    } else {
      hi = mid;
      ghi = g;
      if (side == 1) glo /= 2;
      side = 1;
    }
  }
  if (have) {
    bracket.emplace(lo, hi);
    try_point(best, wanted, centre, consider);
  }
}

}  // namespace

void double_curve_search(const DoubleMatrix4& em, const DoubleMatrix4& pm, const anysize::LambdaS& lambda_s,
                         const V3& centre, const std::optional<V3>& inside, const std::optional<V3>& outside,
                         const Consider& consider, DoubleBracket (&brackets)[2]) {
  const DoubleCurve curve(em, pm);
  if (!curve.finite) return;
  double x[3];
  if (!inside) {
    double hi = 1;
    for (int k = 0; k < 2000; ++k, hi *= 2) {
      if (!std::isfinite(hi)) return;
      if (curve.x_of(hi, x) && curve.e_of(x) > 0) break;
    }
    bisect(curve, 0, hi, inside, brackets[0], centre, consider);
  }
  if (outside) return;
  // lambda_s from above: the upper end of its stored enclosure (a search needs no more), else a
  // rational approximation.
  const double ls = std::isfinite(lambda_s.hi) && lambda_s.hi - lambda_s.lo <= 0x1p-40 * std::fabs(lambda_s.hi)
                        ? lambda_s.hi
                        : CGAL::to_double(approximate(lambda_s, lambda_s.value(), 64, true));
  if (!(std::isfinite(ls) && ls < 0)) return;
  // approach lambda_s from 0: the first lambda with e(x(lambda)) > 0
  for (double l = ls / 2, step = ls / 4; l > ls && l < 0; l += step, step /= 2) {
    if (curve.x_of(l, x) && curve.e_of(x) > 0) {
      bisect(curve, 0, l, outside, brackets[1], centre, consider);
      break;
    }
    if (step > ls * 1e-15) break;  // step is negative: stop once it is negligible
  }
}

}  // namespace relpos::detail::certificate
