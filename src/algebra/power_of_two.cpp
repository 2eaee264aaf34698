#include "algebra/power_of_two.hpp"

#include <gmp.h>

namespace relpos::detail {

Rational power_of_two(long k) {
  Rational r(1);
  if (k >= 0)
    mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(k));
  else
    mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-k));
  return r;
}

}  // namespace relpos::detail
