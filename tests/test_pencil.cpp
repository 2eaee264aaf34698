// pencil.hpp, exact_pencil.hpp, fixed_pencil.hpp: the polynomials f and s over every number type.
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
  using Forms = relpos::detail::forms::MatrixOf<PooledInteger>;
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
    const auto fz = characteristic_polynomial<Integer>(relpos::detail::forms::MatrixOf<Integer>{pi},
                                                       relpos::detail::forms::MatrixOf<Integer>{ei});
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
