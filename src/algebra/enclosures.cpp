#include "algebra/enclosures.hpp"

#include <gmp.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace relpos::detail::forms {
namespace {

/// The power of two that brings mx into [1/2, 1) (1 for zero or a non-finite mx), as an interval.
Interval scale_below_one(double mx) {
  int e = 0;
  if (mx > 0 && std::isfinite(mx)) std::frexp(mx, &e);
  return Interval(std::ldexp(1.0, -e));
}

}  // namespace

MatrixOf<Interval> to_intervals(const DoubleMatrix4& m) {
  double mx = 0;
  for (double x : m) mx = std::max(mx, std::fabs(x));
  const Interval scale = scale_below_one(mx);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = Interval(m[i]) * scale;
  return out;
}

MatrixOf<Interval> to_intervals(const detail::EnclosureMatrix4& m) {
  double mx = 0;
  for (std::size_t i = 0; i < 16; ++i) mx = std::max({mx, std::fabs(m.lo[i]), std::fabs(m.hi[i])});
  const Interval scale = scale_below_one(mx);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = Interval(m.lo[i], m.hi[i]) * scale;
  return out;
}

MatrixOf<Interval> to_intervals(const Matrix4& m) {
  std::array<double, 16> v;
  double mx = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    v[i] = mpq_get_d(m.a[i].mpq());
    mx = std::max(mx, std::fabs(v[i]));
  }
  const Interval scale = scale_below_one(mx);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) {
    const double x = v[i];
    const mpq_srcptr q = m.a[i].mpq();
    if (mpq_sgn(q) == 0) {
      out.a[i] = Interval(0);
      continue;
    }
    const mp_bitcnt_t den_bits = mpz_sizeinbase(mpq_denref(q), 2);
    if (mpz_sizeinbase(mpq_numref(q), 2) <= 53 && mpz_scan1(mpq_denref(q), 0) == den_bits - 1 &&
        std::fabs(x) >= DBL_MIN) {  // a double (53-bit numerator over a power of two): exact
      out.a[i] = Interval(x) * scale;
    } else if (std::fabs(x) >= DBL_MIN && std::isfinite(x)) {
      const double next = std::nextafter(x, x > 0 ? HUGE_VAL : -HUGE_VAL);  // away from zero
      out.a[i] = Interval(std::min(x, next), std::max(x, next)) * scale;
    } else if (std::isfinite(x)) {  // |q| below DBL_MIN
      out.a[i] = Interval(x - DBL_TRUE_MIN, x + DBL_TRUE_MIN) * scale;
    } else {  // beyond the double range: no information
      out.a[i] = Interval::largest();
    }
  }
  return out;
}

}  // namespace relpos::detail::forms
