// compact_integers.hpp: the compact integer forms of a pair, checked against their definition on
// random rational matrices. With D = diag(1, 1, 1, t), t the lcm of the denominators of both
// translation columns, each form is a positive multiple of D M D (beta D P D, alpha D E D) with
// integer entries and content 1; and the identity the exact decisions rely on (math.md §11),
// det(lambda beta DPD + alpha DED) = t^2 alpha^4 f(beta lambda / alpha), holds coefficient by
// coefficient: g_i = t^2 alpha^(4-i) beta^i f_i, so every root of f is scaled by alpha / beta > 0.
#include <gmp.h>

#include <array>
#include <catch2/catch.hpp>

#include "algebra/compact_integers.hpp"
#include "algebra/matrix_view.hpp"
#include "algebra/pencil.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

namespace {

/// A random symmetric rational matrix (entries often zero, denominators sharing primes).
relpos::Matrix4 random_symmetric(rt::Rng& g) {
  const long dens[] = {1, 2, 3, 4, 5, 6, 7, 10, 12, 49, 1000003};
  relpos::Matrix4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j) {
      const Rational x =
          g.chance(25) ? Rational(0) : Rational(Integer(g.uniform(-999, 999)), Integer(dens[g.uniform(0, 10)]));
      m(i, j) = x;
      m(j, i) = x;
    }
  if (m(0, 0) == 0) m(0, 0) = Rational(1, 3);  // not the zero matrix
  return m;
}

/// The positive factor c with form = c D m D entry by entry (0 when there is none), checking that the
/// form is integer and primitive.
Rational factor_of(const relpos::detail::forms::MatrixOf<Integer>& form, const relpos::Matrix4& m, const Integer& t) {
  Rational c(0);
  Integer content(0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational dmd = m(i, j);
      if (i == 3) dmd *= Rational(t);
      if (j == 3) dmd *= Rational(t);
      const Integer& z = form(i, j);
      mpz_gcd(content.mpz(), content.mpz(), z.mpz());
      if (dmd == 0) {
        if (z != 0) return Rational(0);
        continue;
      }
      const Rational ratio = Rational(z) / dmd;
      if (c == 0) c = ratio;
      if (ratio != c) return Rational(0);
    }
  CHECK(content == 1);  // primitive
  return c;
}

}  // namespace

TEST_CASE("to_compact_integers: positive multiples of D M D, primitive, with f's roots scaled alike",
          "[compact_integers]") {
  rt::Rng g(1111);
  for (int trial = 0; trial < 500; ++trial) {
    const relpos::Matrix4 p = random_symmetric(g), e = random_symmetric(g);
    relpos::detail::forms::MatrixOf<Integer> pz, ez;  // fresh entries: written through mpz()
    relpos::detail::forms::to_compact_integers(p, e, relpos::detail::forms::entries(pz),
                                               relpos::detail::forms::entries(ez));
    Integer t(1);
    for (const relpos::Matrix4* m : {&p, &e})
      for (int i = 0; i < 3; ++i) mpz_lcm(t.mpz(), t.mpz(), (*m)(i, 3).denominator().mpz());
    const Rational beta = factor_of(pz, p, t), alpha = factor_of(ez, e, t);
    CAPTURE(trial, relpos::to_string(t));
    REQUIRE(beta > 0);
    REQUIRE(alpha > 0);
    // g_i = t^2 alpha^(4-i) beta^i f_i.
    const auto f = relpos::characteristic_polynomial<Rational>(p, e);
    const auto gz = relpos::characteristic_polynomial<Integer>(pz, ez);
    for (std::size_t i = 0; i < 5; ++i) {
      Rational want = Rational(t) * Rational(t) * f[i];
      for (std::size_t k = 0; k < 4 - i; ++k) want *= alpha;
      for (std::size_t k = 0; k < i; ++k) want *= beta;
      CHECK(Rational(gz[i]) == want);
    }
  }
}
