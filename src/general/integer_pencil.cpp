#include "general/integer_pencil.hpp"

#include <gmp.h>

namespace relpos::detail::general {

IntegerMatrix primitive_form(const Matrix4& m, Rational& factor) {
  Integer l(1), g(0);
  for (const Rational& x : m.a) {
    const mpz_srcptr den = mpq_denref(x.mpq());
    if (mpz_cmp_ui(den, 1) != 0 && !mpz_divisible_p(l.mpz(), den)) mpz_lcm(l.mpz(), l.mpz(), den);
  }
  IntegerMatrix z;
  for (std::size_t i = 0; i < 16; ++i) {
    const mpq_srcptr x = m.a[i].mpq();
    Integer& out = z.a[i];
    mpz_divexact(out.mpz(), l.mpz(), mpq_denref(x));
    mpz_mul(out.mpz(), out.mpz(), mpq_numref(x));
    mpz_gcd(g.mpz(), g.mpz(), out.mpz());
  }
  if (g == 0) g = Integer(1);  // the zero matrix (never a validated quadric)
  if (g != 1)
    for (Integer& x : z.a) mpz_divexact(x.mpz(), x.mpz(), g.mpz());
  factor = Rational(l, g);
  return z;
}

IntegerPencil integer_pencil(const Matrix4& e, const Matrix4& q) {
  IntegerPencil p;
  Rational alpha, beta;
  p.e = primitive_form(e, beta);
  p.q = primitive_form(q, alpha);
  p.scale = beta / alpha;
  p.f = pencil_quartic<Integer>(p.e, p.q);
  p.d = pencil_cubic<Integer>(p.e, p.q);
  return p;
}

}  // namespace relpos::detail::general
