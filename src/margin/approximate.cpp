#include "margin/approximate.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <complex>

namespace relpos::detail {

namespace {

using Complex = std::complex<double>;

/// The coefficients over the leading one in long double (its exponent range, about 2^+-16382, holds
/// every input of the margin); false when one is not finite.
bool over_leading(const std::vector<Integer>& p, std::size_t degree, std::vector<long double>& c) {
  long lead_exp = 0;
  const long double lead = mpz_get_d_2exp(&lead_exp, p[degree].mpz());
  for (std::size_t i = 0; i <= degree; ++i) {
    long e = 0;
    const long double m = mpz_get_d_2exp(&e, p[i].mpz());
    c[i] = std::ldexp(m / lead, static_cast<int>(e - lead_exp));
    if (!std::isfinite(c[i])) return false;
  }
  return true;
}

/// The complex roots of the monic polynomial y (degree `degree`, y[degree] = 1 implied) by
/// Durand-Kerner; false when two approximations meet.
bool durand_kerner(const std::vector<double>& y, std::size_t degree, std::vector<Complex>& z) {
  auto value = [&](Complex x) {
    Complex v = 1;  // monic
    for (std::size_t k = degree; k-- > 0;) v = v * x + y[k];
    return v;
  };
  z.assign(degree, Complex(0));
  for (std::size_t k = 0; k < degree; ++k)
    z[k] = std::polar(1.0, 0.4 + 6.283185307179586 * static_cast<double>(k) / static_cast<double>(degree));
  bool settled = false;
  for (int iteration = 0; iteration < 200 && !settled; ++iteration) {
    settled = true;
    for (std::size_t k = 0; k < degree; ++k) {
      Complex d = 1;
      for (std::size_t j = 0; j < degree; ++j)
        if (j != k) d *= z[k] - z[j];
      if (d == Complex(0)) return false;
      const Complex step = value(z[k]) / d;
      z[k] -= step;
      if (!(std::norm(step) <= 1e-26 * std::norm(z[k]))) settled = false;
    }
  }
  return true;
}

/// The real ones of the roots z (of the polynomial in y, x = 2^shift y), polished by Newton on the
/// real polynomial c in long double, in increasing order.
std::vector<long double> polished_real_roots(const std::vector<Complex>& z, const std::vector<long double>& c,
                                             std::size_t degree, int shift) {
  std::vector<long double> out;
  for (const Complex& r : z) {
    if (!std::isfinite(r.real()) || std::fabs(r.imag()) > 1e-6 * std::max(std::abs(r), 1e-300)) continue;
    long double x = std::ldexp(static_cast<long double>(r.real()), shift);
    for (int i = 0; i < 4; ++i) {  // Newton on the real polynomial, in long double
      long double v = 1, d = 0;
      for (std::size_t k = degree; k-- > 0;) {
        d = d * x + v;
        v = v * x + c[k];
      }
      if (d == 0) break;
      const long double next = x - v / d;
      if (!std::isfinite(next)) break;
      x = next;
    }
    out.push_back(x);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<long double> approximate_real_roots(const std::vector<Integer>& p) {
  std::size_t n = p.size();
  while (n > 0 && p[n - 1] == 0) --n;
  if (n < 2 || n > 17) return {};
  const std::size_t degree = n - 1;
  // The coefficients over the leading one, then x = 2^s y with 2^s near the roots' size (Fujiwara's
  // bound): the monic polynomial in y has coefficients of moderate size, so Durand-Kerner can run in
  // double.
  std::vector<long double> c(n);
  if (!over_leading(p, degree, c)) return {};
  long double radius = 0;
  for (std::size_t i = 1; i <= degree; ++i)
    radius = std::max(radius, std::pow(std::fabs(c[degree - i]), 1.0L / static_cast<long double>(i)));
  int shift = 0;
  if (radius > 0) std::frexp(radius, &shift);
  std::vector<double> y(n);  // y[i] = c[i] 2^(s (i - degree))
  for (std::size_t i = 0; i < n; ++i)
    y[i] = static_cast<double>(std::ldexp(c[i], shift * (static_cast<int>(i) - static_cast<int>(degree))));
  std::vector<Complex> z;
  if (!durand_kerner(y, degree, z)) return {};
  return polished_real_roots(z, c, degree, shift);
}

std::optional<Rational> rational_near(long double x) {
  const double hi = static_cast<double>(x);
  if (!std::isfinite(hi)) return std::nullopt;
  const double lo = static_cast<double>(x - static_cast<long double>(hi));
  return exact_rational(hi) + exact_rational(lo);
}

}  // namespace relpos::detail
