// pencil.hpp, exact_pencil.hpp, fixed_pencil.hpp: the polynomials f and s over every number type
// (and, until they move to test files of their own, the exact forms of forms.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <relpos/classify.hpp>
#include <vector>

#include "algebra/exact_pencil.hpp"
#include "algebra/forms.hpp"
#include "algebra/pencil.hpp"
#include "filters/fixed_pencil.hpp"
#include "filters/pooled_integer.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;
using relpos::characteristic_polynomial;
using relpos::exact_characteristic_polynomial;
using relpos::exact_special_polynomial;
using relpos::special_polynomial;

TEST_CASE("characteristic_polynomial is the paper's closed form (eq. 4) for spheres", "[pencil]") {
  const std::uint64_t seed = 0xF00D;
  Rng g(seed);
  CAPTURE(seed);
  for (int i = 0; i < 150; ++i) {
    const Rational a = g.positive_rational(9, 4), b = g.positive_rational(9, 4), r = g.positive_rational(9, 4);
    const Vector3 c{g.rational(-9, 9, 4), g.rational(-9, 9, 4), g.rational(-9, 9, 4)};
    CAPTURE(relpos::to_string(a), relpos::to_string(b), relpos::to_string(r));
    const Matrix4 e = sphere_matrix(c, r), p = paraboloid_matrix(a, b);
    const Quartic<Rational> f = characteristic_polynomial<Rational>(p, e);
    const Quartic<Rational> want = paper_f(a, b, c, r);
    for (std::size_t k = 0; k < 5; ++k) CHECK(f[k] == want[k]);
    CHECK(f[4] == det4(p));  // leading coefficient det P
    CHECK(f[0] == det4(e));  // constant term det E = -r^2
    CHECK(f[0] == -r * r);
    // At a few rational lambdas, f is det(lambda P + E) computed by elimination.
    for (long num : {-3L, -1L, 2L}) {
      const Rational l = Q(num, 2);
      Matrix4 pencil;
      for (std::size_t k = 0; k < 16; ++k) pencil.a[k] = l * p.a[k] + e.a[k];
      CHECK(eval(f, l) == det4(pencil));
    }
    const Quadratic<Rational> s = special_polynomial<Rational>(p, e);
    const Quadratic<Rational> ws = paper_s(a, b);
    for (std::size_t k = 0; k < 3; ++k) CHECK(s[k] == ws[k]);
    CHECK(eval(s, -a * a) == 0);
    CHECK(eval(s, -b * b) == 0);
  }
}

TEST_CASE("f and s are congruence invariants: f_H = det(H)^2 f, s_H = det(L)^2 s", "[pencil][random]") {
  const std::uint64_t seed = 0xBEEF01;
  Rng g(seed);
  CAPTURE(seed);
  for (int i = 0; i < 100; ++i) {
    CAPTURE(i);
    // Arbitrary symmetric matrices: the identity holds for any pencil.
    Matrix4 e, p;
    for (int r = 0; r < 4; ++r)
      for (int c = r; c < 4; ++c) {
        set_sym(e, r, c, g.rational(-6, 6, 3));
        set_sym(p, r, c, g.rational(-6, 6, 3));
      }
    Congruence h = random_congruence(g);
    const auto f = characteristic_polynomial<Rational>(p, e);
    const auto fh = characteristic_polynomial<Rational>(congruence(p, h.h), congruence(e, h.h));
    for (std::size_t k = 0; k < 5; ++k) CHECK(fh[k] == h.det * h.det * f[k]);
    // s drops the cubic term det A, so compare on matrices whose A has rank 2 (paraboloids).
    const Matrix4 par = paraboloid_matrix(g.positive_rational(5, 3), g.positive_rational(5, 3));
    const auto s = special_polynomial<Rational>(par, e);
    const auto sh = special_polynomial<Rational>(congruence(par, h.h), congruence(e, h.h));
    for (std::size_t k = 0; k < 3; ++k) CHECK(sh[k] == h.det * h.det * s[k]);
  }
}

TEST_CASE("the generic pencil code gives the same polynomial over Z, Q and doubles", "[pencil]") {
  // Integer matrices: the Integer and double instantiations must agree exactly (small values), and
  // PooledInteger (its fused add_product / sub_product) with Integer (the generic ones).
  Rng g(31337);
  for (int i = 0; i < 30; ++i) {
    std::array<Integer, 16> ei{}, pi{};
    std::array<double, 16> ed{}, pd{};
    Matrix4 eq, pq;
    for (int r = 0; r < 4; ++r)
      for (int c = r; c < 4; ++c) {
        long x = g.uniform(-9, 9), y = g.uniform(-9, 9);
        for (auto idx : {4 * r + c, 4 * c + r}) {
          const auto k = static_cast<std::size_t>(idx);
          ei[k] = Integer(x);
          pi[k] = Integer(y);
          ed[k] = static_cast<double>(x);
          pd[k] = static_cast<double>(y);
        }
        set_sym(eq, r, c, Q(x));
        set_sym(pq, r, c, Q(y));
      }
    struct MI {
      std::array<Integer, 16> a;
      const Integer& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
    };
    struct MD {
      std::array<double, 16> a;
      const double& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
    };
    struct MP {
      std::array<relpos::PooledInteger, 16> a;
      const relpos::PooledInteger& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
    };
    MP pp, ep;
    for (std::size_t k = 0; k < 16; ++k) pp.a[k] = relpos::PooledInteger(pi[k]), ep.a[k] = relpos::PooledInteger(ei[k]);
    const auto fz = characteristic_polynomial<Integer>(MI{pi}, MI{ei});
    const auto fd = characteristic_polynomial<double>(MD{pd}, MD{ed});
    const auto fq = characteristic_polynomial<Rational>(pq, eq);
    const auto fp = characteristic_polynomial<relpos::PooledInteger>(pp, ep);
    for (std::size_t k = 0; k < 5; ++k) {
      CHECK(Rational(fz[k]) == fq[k]);
      CHECK(Rational(fd[k]) == fq[k]);  // all values are small integers: exact in double
      CHECK(fp[k].to_integer() == fz[k]);
    }
    const auto sz = special_polynomial<Integer>(MI{pi}, MI{ei});
    const auto sp = special_polynomial<relpos::PooledInteger>(pp, ep);
    for (std::size_t k = 0; k < 3; ++k) CHECK(sp[k].to_integer() == sz[k]);
    // The exact-only forms (exact_pencil.hpp), fused and generic, and on entries of some 200 bits
    // (GMP's multi-limb addmul and submul, signs of every kind).
    const auto fe = exact_characteristic_polynomial<relpos::PooledInteger>(pp, ep);
    const auto se = exact_special_polynomial<relpos::PooledInteger>(pp, ep);
    const auto fei = exact_characteristic_polynomial<Integer>(MI{pi}, MI{ei});
    for (std::size_t k = 0; k < 5; ++k) CHECK(fe[k].to_integer() == fz[k]);
    for (std::size_t k = 0; k < 5; ++k) CHECK(fei[k] == fz[k]);
    for (std::size_t k = 0; k < 3; ++k) CHECK(se[k].to_integer() == sz[k]);
    Integer big(1);
    mpz_mul_2exp(big.mpz(), big.mpz(), 200);
    big = big + Integer(g.uniform(1, 1000000));
    MI pl{pi}, el{ei};
    for (std::size_t k = 0; k < 16; ++k) {
      pl.a[k] = pl.a[k] * big + Integer(g.uniform(-9, 9) * (k % 5 == 0));  // symmetric: k % 5 == 0 on the diagonal
      el.a[k] = el.a[k] * big * big;
    }
    MP ppl, epl;
    for (std::size_t k = 0; k < 16; ++k)
      ppl.a[k] = relpos::PooledInteger(pl.a[k]), epl.a[k] = relpos::PooledInteger(el.a[k]);
    const auto fl = characteristic_polynomial<Integer>(pl, el);
    const auto fel = exact_characteristic_polynomial<relpos::PooledInteger>(ppl, epl);
    for (std::size_t k = 0; k < 5; ++k) CHECK(fel[k].to_integer() == fl[k]);
    const auto sl = special_polynomial<Integer>(pl, el);
    const auto sel = exact_special_polynomial<relpos::PooledInteger>(ppl, epl);
    for (std::size_t k = 0; k < 3; ++k) CHECK(sel[k].to_integer() == sl[k]);
  }
}

TEST_CASE("the fixed-size pencil equals the GMP one on entries below 2^62 and declines larger ones", "[pencil]") {
  // Against the generic formulas on Integer (another order, other arithmetic): random entries of
  // every length up to 62 bits and every sign, zeros in a paraboloid's places, the largest entries
  // 2^62 - 1 in a Hadamard sign pattern (coefficients near the 2^257 of the overflow proof, and
  // every carry and borrow of the 320-bit sums); 2^62 and two-limb entries take the GMP path.
  using relpos::PooledInteger;
  using Forms = relpos::forms::MatrixOf<PooledInteger>;
  Rng g(6262);
  const long top = (1L << 62) - 1;
  auto check = [](const std::array<long, 16>& pv, const std::array<long, 16>& ev) {
    Forms pp, ep;
    std::array<Integer, 16> pi, ei;
    for (std::size_t k = 0; k < 16; ++k) {
      mpz_set_si(pp.a[k].mpz(), pv[k]);
      mpz_set_si(ep.a[k].mpz(), ev[k]);
      pi[k] = Integer(pv[k]);
      ei[k] = Integer(ev[k]);
    }
    relpos::Quartic<PooledInteger> f;
    relpos::Quadratic<PooledInteger> s;
    REQUIRE(relpos::small_pencil_polynomials(pp, ep, f, s));
    const auto fz =
        characteristic_polynomial<Integer>(relpos::forms::MatrixOf<Integer>{pi}, relpos::forms::MatrixOf<Integer>{ei});
    const auto sz = exact_special_polynomial<PooledInteger>(pp, ep);
    for (std::size_t k = 0; k < 5; ++k) CHECK(f[k].to_integer() == fz[k]);
    for (std::size_t k = 0; k < 3; ++k) CHECK(s[k].to_integer() == sz[k].to_integer());
  };
  static constexpr int hadamard[4][4] = {{1, 1, 1, 1}, {1, -1, 1, -1}, {1, 1, -1, -1}, {1, -1, -1, 1}};
  for (int flip = 0; flip < 16; ++flip) {  // +-(2^62 - 1) with det +-16 (2^62 - 1)^4 at mu = 0 and mu -> oo
    std::array<long, 16> pv{}, ev{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        const auto k = static_cast<std::size_t>(4 * r + c);
        ev[k] = hadamard[r][c] * top * ((flip >> r & 1) ? -1 : 1);
        pv[k] = hadamard[c][r] * top * ((flip >> c & 1) ? -1 : 1) * (r == 3 ? -1 : 1);
      }
    check(pv, ev);
    for (std::size_t k = 0; k < 16; ++k) pv[k] = (k % 5 == 0 || k == 11 || k == 14) ? pv[k] : 0;  // sparse P
    check(pv, ev);
  }
  for (int i = 0; i < 300; ++i) {
    std::array<long, 16> pv{}, ev{};
    for (std::size_t k = 0; k < 16; ++k) {
      const int bits = static_cast<int>(g.uniform(0, 62));
      const long mag = bits == 0 ? 0 : static_cast<long>(g.gen() >> (64 - bits));
      ev[k] = g.chance(50) ? -mag : mag;
      const long pmag = g.chance(20) ? top : static_cast<long>(g.gen() >> 2);
      pv[k] = (i % 2 == 0 && !(k % 5 == 0 || k == 11 || k == 14)) ? 0 : (g.chance(50) ? -pmag : pmag);
    }
    check(pv, ev);
  }
  // 2^62, -2^62 and a two-limb entry: declined, f and s untouched.
  for (int which = 0; which < 3; ++which) {
    Forms pp, ep;
    for (std::size_t k = 0; k < 16; ++k) {
      mpz_set_si(pp.a[k].mpz(), g.uniform(-1000, 1000));
      mpz_set_si(ep.a[k].mpz(), g.uniform(-1000, 1000));
    }
    mpz_set_ui(ep.a[5].mpz(), 1);
    mpz_mul_2exp(ep.a[5].mpz(), ep.a[5].mpz(), which == 2 ? 64 : 62);
    if (which == 1) mpz_neg(ep.a[5].mpz(), ep.a[5].mpz());
    relpos::Quartic<PooledInteger> f{PooledInteger(7), PooledInteger(7), PooledInteger(7), PooledInteger(7),
                                     PooledInteger(7)};
    relpos::Quadratic<PooledInteger> s{PooledInteger(7), PooledInteger(7), PooledInteger(7)};
    CHECK_FALSE(relpos::small_pencil_polynomials(pp, ep, f, s));
    CHECK_FALSE(relpos::small_pencil_polynomials(ep, pp, f, s));
    for (const auto& c : f) CHECK(c.to_integer() == Integer(7));
    for (const auto& c : s) CHECK(c.to_integer() == Integer(7));
    mpz_set_si(ep.a[5].mpz(), which == 1 ? -top : top);  // one less in magnitude: taken
    CHECK(relpos::small_pencil_polynomials(pp, ep, f, s));
  }
}

TEST_CASE("divided_by_power: z / scale^k in lowest terms, as rational division gives it", "[forms]") {
  // Scales of the three kinds the reports meet: doubles (2^a), decimal text (2^a 5^b) and rationals
  // (another factor, shared with z to various powers); z zero, negative, and with many fives.
  rt::Rng g(4242);
  const long rests[] = {1, 3, 7, 9, 21, 1000003, 3 * 3 * 11};
  for (int trial = 0; trial < 2000; ++trial) {
    // Every 4th scale without fives: with rest 1 (every 7th), a double's power of two alone.
    const auto a = static_cast<unsigned long>(g.uniform(0, 40)), b = static_cast<unsigned long>(g.uniform(0, 40));
    Integer scale = Integer(rests[trial % 7]);
    for (unsigned long i = 0; i < a; ++i) scale *= Integer(2);
    for (unsigned long i = 0; i < (trial % 4 == 0 ? 0 : b); ++i) scale *= Integer(5);
    Integer z(static_cast<long>(g.uniform(-1000000, 1000000)));
    const auto extra = g.uniform(0, 6);
    for (long i = 0; i < extra; ++i) z *= Integer(trial % 3 == 0 ? 5 : trial % 3 == 1 ? 2 : rests[trial % 7]);
    if (trial % 5 == 0) z *= scale * scale;  // common factors beyond one power of the scale
    const relpos::forms::SplitScale split = relpos::forms::split_scale(scale);
    for (unsigned long k = 0; k <= 4; ++k) {
      Rational expected(z);
      for (unsigned long i = 0; i < k; ++i) expected /= Rational(scale);
      const Rational got = relpos::forms::divided_by_power(z, split, k);
      CAPTURE(relpos::to_string(z), relpos::to_string(scale), k);
      CHECK(got == expected);
      CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(expected.mpq())) == 0);  // canonical
      CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(expected.mpq())) == 0);
    }
  }
}

TEST_CASE("divided_by_powers: two scales with shared prime factors, as rational division gives it", "[forms]") {
  // The reported f_i = g_i / (lp^i le^(4-i)): the two matrices' scales may share any prime.
  rt::Rng g(777);
  const long parts[] = {1, 2, 3, 5, 6, 10, 12, 15, 49, 1000003};
  for (int trial = 0; trial < 1500; ++trial) {
    Integer a(1), b(1);
    for (int i = 0; i < 4; ++i) {
      a *= Integer(parts[g.uniform(0, 9)]);
      b *= Integer(parts[g.uniform(0, 9)]);
    }
    Integer z(static_cast<long>(g.uniform(-100000, 100000)));
    for (long i = g.uniform(0, 4); i > 0; --i) z *= Integer(parts[g.uniform(0, 9)]);
    if (trial % 4 == 0) z *= a * a * b;
    const relpos::forms::SplitScale sa = relpos::forms::split_scale(a), sb = relpos::forms::split_scale(b);
    for (unsigned long i = 0; i <= 4; ++i) {
      Rational expected(z);
      for (unsigned long k = 0; k < i; ++k) expected /= Rational(a);
      for (unsigned long k = i; k < 4; ++k) expected /= Rational(b);
      const Rational got = relpos::forms::divided_by_powers(z, {{sa, i}, {sb, 4 - i}});
      CAPTURE(relpos::to_string(z), relpos::to_string(a), relpos::to_string(b), i);
      CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(expected.mpq())) == 0);  // same canonical form
      CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(expected.mpq())) == 0);
    }
  }
}

TEST_CASE("split_scale along a matrix's denominators: a coprime base of the rest, same reductions", "[forms]") {
  // Denominators of the kinds a standard paraboloid with decimal a, b has (squares of mantissas
  // that may share primes, times 2s and 5s) and others (not squares, powers of one another, shared
  // primes): the split rest is a product of pairwise coprime bases, and z / scale^k reduces as
  // rational division does.
  rt::Rng g(31337);
  const long parts[] = {3, 7, 9, 11, 21, 1000003, 99991, 6, 10, 25};
  for (int trial = 0; trial < 1500; ++trial) {
    relpos::Matrix4 m;
    for (std::size_t i = 0; i < 16; ++i) {
      Integer den(1);
      for (long k = g.uniform(0, 3); k > 0; --k) den *= Integer(parts[g.uniform(0, 9)]);
      if (trial % 2 == 0) den *= den;  // squares, as 1/a^2 has
      m.a[i] = g.uniform(0, 3) == 0 ? Rational(0) : Rational(Integer(g.uniform(-50, 50)) * Integer(2), den);
    }
    Integer scale;
    relpos::forms::integer_form(m, scale);
    const relpos::forms::SplitScale split = relpos::forms::split_scale(scale, m);
    const relpos::forms::SplitScale plain = relpos::forms::split_scale(scale);
    CHECK(split.twos == plain.twos);
    CHECK(split.fives == plain.fives);
    Integer product(1);
    for (const auto& f : split.factors)
      for (unsigned long k = 0; k < f.power; ++k) product *= f.base;
    CHECK(product == split.rest);
    for (std::size_t i = 0; i < split.factors.size(); ++i)
      for (std::size_t j = i + 1; j < split.factors.size(); ++j) {
        Integer c;
        mpz_gcd(c.mpz(), split.factors[i].base.mpz(), split.factors[j].base.mpz());
        CHECK(c == 1);
      }
    Integer z(static_cast<long>(g.uniform(-100000, 100000)));
    for (long i = g.uniform(0, 6); i > 0; --i) z *= Integer(parts[g.uniform(0, 9)]);
    if (trial % 3 == 0) z *= scale;
    for (unsigned long k = 0; k <= 4; ++k) {
      Rational expected(z);
      for (unsigned long i = 0; i < k; ++i) expected /= Rational(scale);
      const Rational got = relpos::forms::divided_by_power(z, split, k);
      CAPTURE(relpos::to_string(z), relpos::to_string(scale), k);
      CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(expected.mpq())) == 0);  // same canonical form
      CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(expected.mpq())) == 0);
    }
  }
}

TEST_CASE("tight_interval equals CGAL::to_interval bit for bit", "[forms]") {
  // Doubles (exact: a point), dyadics with more than 53 bits, general rationals, subnormal and
  // huge values (CGAL's own path), of either sign.
  rt::Rng g(314);
  std::mt19937_64 bits(15);
  for (int trial = 0; trial < 20000; ++trial) {
    Rational q;
    const double d =
        std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits), static_cast<int>(g.uniform(-1100, 1100)));
    switch (trial % 4) {
      case 0:
        q = Rational(std::isfinite(d) ? d : 1.0);
        break;
      case 1:
        q = Rational(std::isfinite(d) ? d : 1.0) + Rational(Integer(1), Integer(1) << 200);
        break;
      case 2:
        q = Rational(Integer(g.uniform(-(1L << 60), 1L << 60)), Integer(g.uniform(1, 1L << 60)));
        break;
      default:
        q = Rational(Integer(g.uniform(1, 1000)), Integer(3)) * Rational(std::isfinite(d) && d != 0 ? d : 1.0);
    }
    CAPTURE(relpos::to_string(q));
    const std::pair<double, double> got = relpos::forms::tight_interval(q), want = CGAL::to_interval(q);
    CHECK(got.first == want.first);
    CHECK(got.second == want.second);
  }
}

TEST_CASE("set_double writes the canonical rational mpq_set_d writes", "[forms]") {
  // Zero, integers, dyadic fractions, subnormals and the extremes, of either sign, into values
  // that held something else before (the caller's fresh or reused rationals).
  rt::Rng g(27);
  std::mt19937_64 bits(8);
  const double special[] = {0.0,
                            -0.0,
                            1.0,
                            -3.0,
                            0.5,
                            std::numeric_limits<double>::denorm_min(),
                            -std::numeric_limits<double>::min(),
                            std::numeric_limits<double>::max(),
                            0x1p52,
                            0x1.8p-1074};
  for (int trial = 0; trial < 20000; ++trial) {
    const double x = trial < 10 ? special[trial]
                                : std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits),
                                             static_cast<int>(g.uniform(-1080, 1024)));
    if (!std::isfinite(x)) continue;
    Rational got(Integer(g.uniform(-99, 99)), Integer(g.uniform(1, 99))), want;
    relpos::forms::set_double(got.mpq(), x);
    mpq_set_d(want.mpq(), x);
    CAPTURE(x);
    CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(want.mpq())) == 0);
    CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(want.mpq())) == 0);
  }
}

TEST_CASE("integer_form of doubles equals integer_form of their exact rationals", "[forms]") {
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
    const auto a = relpos::forms::integer_form(d, l1);
    const auto b = relpos::forms::integer_form(m, l2);
    CHECK(l1 == l2);
    for (std::size_t i = 0; i < 16; ++i) CHECK(a.a[i] == b.a[i]);
  }
}

TEST_CASE("small_integer_form: integer_form in words exactly when every entry is below 2^62", "[forms]") {
  // Against integer_form: taken iff its largest entry is below 2^62, then the same entries and
  // l = 2^twos. Exponents spread over windows of 0 to 20 binades around the 2^62 bound, and the
  // bound itself: 2^61 and (2^53 - 1) 2^9 (62 bits: taken), 2^62 and (2^53 - 1) 2^10 (declined).
  rt::Rng g(62);
  auto check = [](const relpos::DoubleMatrix4& d) {
    Integer l;
    const auto a = relpos::forms::integer_form(d, l);
    Integer bound(1);
    mpz_mul_2exp(bound.mpz(), bound.mpz(), 62);
    bool fits = true;
    for (const Integer& x : a.a) fits = fits && CGAL::abs(x) < bound;
    relpos::forms::MatrixOf<std::int64_t> w;
    unsigned long twos = 0;
    const bool taken = relpos::forms::small_integer_form(d, w, twos);
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
