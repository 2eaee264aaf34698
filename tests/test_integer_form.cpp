// integer_form.hpp: each matrix's own integer form, the matrix times the lcm of its denominators,
// from rationals (against rational arithmetic), from the bits of doubles (against the form of their
// exact rationals), in machine words when every entry fits.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "algebra/integer_form.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

TEST_CASE("integer_form of rationals: the entries times the lcm of their denominators", "[integer_form]") {
  // Dyadic matrices (the shifts' path) and general ones: l is the lcm, each entry is q l.
  rt::Rng g(12);
  const long dens[] = {1, 2, 4, 1024, 3, 10, 49, 1000003};
  for (int trial = 0; trial < 3000; ++trial) {
    relpos::Matrix4 m;
    const int top = trial % 2 == 0 ? 4 : 8;  // dyadic denominators only, or all of them
    for (Rational& x : m.a)
      x = g.chance(20) ? Rational(0)
                       : Rational(Integer(g.uniform(-99999, 99999)), Integer(dens[g.uniform(0, top - 1)]));
    Integer l;
    const auto z = relpos::detail::forms::integer_form(m, l);
    Integer want(1);
    for (const Rational& x : m.a) mpz_lcm(want.mpz(), want.mpz(), x.denominator().mpz());
    CHECK(l == want);
    for (std::size_t i = 0; i < 16; ++i) CHECK(Rational(z.a[i]) == m.a[i] * Rational(l));
  }
}

TEST_CASE("integer_form of doubles equals integer_form of their exact rationals", "[integer_form]") {
  rt::Rng g(99);
  std::mt19937_64 bits(5);
  for (int trial = 0; trial < 3000; ++trial) {
    relpos::DoubleMatrix4 d{};
    for (double& x : d) {
      switch (g.uniform(0, 5)) {
        case 0:
          x = 0;
          break;
        case 1:
          x = static_cast<double>(g.uniform(-1000, 1000));
          break;
        case 2:
          x = std::ldexp(static_cast<double>(g.uniform(-(1L << 52), 1L << 52)), static_cast<int>(g.uniform(-1074, 60)));
          break;
        case 3:
          x = std::numeric_limits<double>::denorm_min() * static_cast<double>(g.uniform(1, 7));
          break;
        default:
          x = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits), static_cast<int>(g.uniform(-300, 300)));
      }
    }
    relpos::Matrix4 m;
    for (std::size_t i = 0; i < 16; ++i) m.a[i] = Rational(d[i]);
    Integer l1, l2;
    const auto a = relpos::detail::forms::integer_form(d, l1);
    const auto b = relpos::detail::forms::integer_form(m, l2);
    CHECK(l1 == l2);
    for (std::size_t i = 0; i < 16; ++i) CHECK(a.a[i] == b.a[i]);
  }
}

TEST_CASE("small_integer_form: integer_form in words exactly when every entry is below 2^62", "[integer_form]") {
  // Against integer_form: taken iff its largest entry is below 2^62, then the same entries and
  // l = 2^twos. Exponents spread over windows of 0 to 20 binades around the 2^62 bound, and the
  // bound itself: 2^61 and (2^53 - 1) 2^9 (62 bits: taken), 2^62 and (2^53 - 1) 2^10 (declined).
  rt::Rng g(62);
  auto check = [](const relpos::DoubleMatrix4& d) {
    Integer l;
    const auto a = relpos::detail::forms::integer_form(d, l);
    Integer bound(1);
    mpz_mul_2exp(bound.mpz(), bound.mpz(), 62);
    bool fits = true;
    for (const Integer& x : a.a) fits = fits && CGAL::abs(x) < bound;
    relpos::detail::forms::MatrixOf<std::int64_t> w;
    unsigned long twos = 0;
    const bool taken = relpos::detail::forms::small_integer_form(d, w, twos);
    CHECK(taken == fits);
    if (!taken || !fits) return fits;
    Integer two_to(1);
    mpz_mul_2exp(two_to.mpz(), two_to.mpz(), twos);
    CHECK(l == two_to);
    for (std::size_t i = 0; i < 16; ++i) CHECK(a.a[i] == Integer(static_cast<long>(w.a[i])));
    return fits;
  };
  int taken = 0, declined = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    relpos::DoubleMatrix4 d{};
    const long window = g.uniform(0, 20), base = g.uniform(-80, 40);
    for (double& x : d) {
      if (g.chance(30)) continue;  // 0
      const long m = g.chance(50) ? g.uniform(-(1L << 53) + 1, (1L << 53) - 1) : g.uniform(-9, 9);
      x = std::ldexp(static_cast<double>(m), static_cast<int>(base + g.uniform(0, window)));
    }
    (check(d) ? taken : declined) += 1;
  }
  CHECK(taken > 100);
  CHECK(declined > 100);
  const double full = std::ldexp(static_cast<double>((1L << 53) - 1), -52);  // 53 bits, just below 2
  for (const double a : {1.0, -1.0, full, -full})
    for (const int k : {61, 62}) {
      relpos::DoubleMatrix4 d{};
      d[0] = a;
      d[5] = std::ldexp(1.0, -k);  // lcm 2^k: a becomes a 2^k, 62 bits for k = 61, 63 for k = 62
      CHECK(check(d) == (k == 61));
    }
}
