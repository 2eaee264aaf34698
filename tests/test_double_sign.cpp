// double_sign.hpp, approximate_roots.hpp and double_bits.hpp: the double layer of root isolation. DoubleSign's
// floating-point stages answer only with the exact sign (computed here in rationals) at and near
// roots known by construction; approximate_real_roots finds, in doubles, the real roots of
// polynomials built from known factors, and only those; the exponent arithmetic on a double's bits
// is std::ilogb's and std::ldexp's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "algebra/approximate_roots.hpp"
#include "algebra/double_bits.hpp"
#include "algebra/double_sign.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

namespace {

/// The exact sign of h (integer coefficients h[0..n]) at a double x, in rationals.
int exact_sign_at(const std::vector<Integer>& h, double x) {
  Rational v(0);
  const Rational q(x);
  for (std::size_t i = h.size(); i-- > 0;) v = v * q + Rational(h[i]);
  return CGAL::sign(v);
}

/// The product of the integer polynomials a and b (coefficients from the constant term up).
std::vector<Integer> times(const std::vector<Integer>& a, const std::vector<Integer>& b) {
  std::vector<Integer> out(a.size() + b.size() - 1, Integer(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return out;
}

}  // namespace

TEST_CASE("DoubleSign: the floating-point stages answer only with the exact sign", "[roots]") {
  using relpos::detail::DoubleSign;
  std::mt19937_64 rng(20261126);
  auto big = [&](int bits) {  // a random odd integer of about `bits` bits, random sign
    Integer z(0);
    for (int b = 0; b < bits; b += 32) z = z * Integer(1L << 32) + Integer(static_cast<long>(rng() >> 32));
    z = 2 * z + 1;
    return (rng() & 1) ? z : Integer(-z);
  };
  int certified = 0, asked = 0;
  SECTION("dyadic roots, their neighbours a few ulps away, and a large common factor") {
    for (int trial = 0; trial < 300; ++trial) {
      // h = K (2^k1 x - m1) (2^k2 x - m2) (x^2 + c) or a cubic / quadratic: the roots m / 2^k are
      // doubles, where h is exactly 0 and no filter may answer.
      const int n = 2 + trial % 3;
      std::vector<double> roots;
      std::vector<Integer> h{big(1 + static_cast<int>(rng() % 150))};
      for (int j = 0; j < 2; ++j) {
        const int k = static_cast<int>(rng() % 60);
        const long m = static_cast<long>(rng() >> 12) | 1;
        roots.push_back(std::ldexp(static_cast<double>(m), -k));
        Integer pk(1);
        for (int b = 0; b < k; ++b) pk *= 2;
        h = times(h, {Integer(-m), pk});
      }
      if (n == 3) h = times(h, {big(40), Integer(1)});
      if (n == 4) h = times(h, {Integer(1) + big(20) * big(20), Integer(0), Integer(1)});
      DoubleSign sign(h.data(), n);
      for (const double r : roots) {
        CHECK(sign.filtered(r) == 0);  // h(r) = 0 exactly
        CHECK(sign(r) == 0);
        double below = r, above = r;
        for (int step = 0; step < 6; ++step) {
          below = std::nextafter(below, -HUGE_VAL);
          above = std::nextafter(above, HUGE_VAL);
          for (const double x : {below, above}) {
            const int exact = exact_sign_at(h, x), s = sign.filtered(x);
            ++asked;
            if (s != 0) ++certified;
            CHECK((s == 0 || s == exact));
            CHECK(sign(x) == exact);
          }
        }
      }
    }
    CHECK(certified > 0);  // one ulp from a simple root of a well-scaled h is usually within reach
  }
  SECTION("two roots 2^-20 apart: points 2^-44 away from them, out of the crude bound's reach") {
    // h = (2^20 x - 2^20)(2^20 x - 2^20 - 1) (x^2 + x + 1) K: near x = 1, h' x is 2^-20 of the magnitude
    // sum |h_i| |x|^i, so h(1 +- 2^-44) is below 2^-48 of it; the compensated bound is 2^-96 of it.
    for (int trial = 0; trial < 100; ++trial) {
      const Integer two20(1L << 20);
      std::vector<Integer> h = times({big(1 + trial)}, {-two20, two20});
      h = times(h, {-two20 - 1, two20});
      h = times(h, {Integer(1), Integer(1), Integer(1)});
      DoubleSign sign(h.data(), 4);
      for (const double r : {1.0, 1.0 + std::ldexp(1.0, -20)})
        for (const double x : {r * (1 - 0x1p-44), r * (1 + 0x1p-44)}) {
          const int exact = exact_sign_at(h, x);
          REQUIRE(exact != 0);
          CHECK(sign.filtered(x) == exact);  // certified by the compensated stage
          CHECK(sign(x) == exact);
        }
    }
  }
  SECTION("random quartics with large coefficients, at random doubles near and far from their roots") {
    for (int trial = 0; trial < 300; ++trial) {
      std::vector<Integer> h;
      for (int i = 0; i <= 4; ++i) h.push_back(big(1 + static_cast<int>(rng() % 200)));
      DoubleSign sign(h.data(), 4);
      for (int j = 0; j < 20; ++j) {
        const double x = std::ldexp(static_cast<double>(static_cast<long>(rng() >> 11)) - 0x1p52,
                                    static_cast<int>(rng() % 400) - 252);
        const int exact = exact_sign_at(h, x), s = sign.filtered(x);
        CHECK((s == 0 || s == exact));
        CHECK(sign(x) == exact);
      }
    }
  }
}

TEST_CASE("approximate_real_roots: the real roots of polynomials built from known factors", "[roots]") {
  // c = K 2^e prod (x - r_i) (x^2 + b)^j with distinct integer roots r_i and b > 0, scaled by 2^k in
  // x: every coefficient is an integer below 2^53 times a power of two (exact in doubles), so the
  // roots are exactly r_i 2^k; each is found to within the noise of c in doubles near it (its
  // magnitude over its slope, times 2^-48: a few units of 2^-50 for well-separated roots), and the
  // non-real pairs add none.
  std::mt19937_64 rng(20261128);
  int checked = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int real = static_cast<int>(rng() % 5), pairs = static_cast<int>(rng() % ((4 - real) / 2 + 1));
    const int n = real + 2 * pairs;
    if (n < 1) continue;
    std::vector<long> roots;
    while (static_cast<int>(roots.size()) < real) {
      const long r = static_cast<long>(rng() % 101) - 50;
      if (r != 0 && std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
    }
    std::sort(roots.begin(), roots.end());
    std::vector<double> c{static_cast<double>(1 + rng() % 7)};  // K
    auto multiply = [&c](const std::vector<double>& q) {
      std::vector<double> out(c.size() + q.size() - 1, 0.0);
      for (std::size_t i = 0; i < c.size(); ++i)
        for (std::size_t j = 0; j < q.size(); ++j) out[i + j] += c[i] * q[j];  // integers below 2^53: exact
      c = out;
    };
    for (long r : roots) multiply({static_cast<double>(-r), 1.0});
    for (int j = 0; j < pairs; ++j) multiply({static_cast<double>(1 + rng() % 50), 0.0, 1.0});
    const int k = static_cast<int>(rng() % 61) - 30;  // roots r 2^k: c_i 2^(-k i)
    for (std::size_t i = 0; i < c.size(); ++i) c[i] = std::ldexp(c[i], -k * static_cast<int>(i));
    double bound = 0;
    for (int i = 0; i < n; ++i) bound = std::max(bound, std::fabs(c[static_cast<std::size_t>(i)] / c[n]));
    bound = 2 * (1 + bound);  // the Cauchy bound, as double_sign.hpp's root_bound
    double out[4];
    const int count = relpos::detail::approximate_real_roots(c.data(), n, bound, out);
    CAPTURE(trial, n, real, k);
    REQUIRE(count == real);
    for (int i = 0; i < count; ++i) {
      const double want = std::ldexp(static_cast<double>(roots[static_cast<std::size_t>(i)]), k);
      // Within 2^-48 of the root plus the rounding noise of c in doubles near it, moved by the slope:
      // the polynomial's magnitude sum |c_j| |x|^j over |c'(x)|, times 2^-48.
      double magnitude = 0, slope = 0;
      for (int j = n; j >= 0; --j) magnitude = magnitude * std::fabs(want) + std::fabs(c[static_cast<std::size_t>(j)]);
      for (int j = n; j >= 1; --j) slope = slope * want + j * c[static_cast<std::size_t>(j)];
      const double tolerance = 0x1p-48 * (std::fabs(want) + magnitude / std::fabs(slope));
      CHECK(std::fabs(out[i] - want) <= tolerance);
      ++checked;
    }
  }
  CHECK(checked > 5000);
  const double quartic[5] = {1, 0, 0, 0, 1};  // x^4 + 1: no real root
  double out[4];
  CHECK(relpos::detail::approximate_real_roots(quartic, 4, 4, out) == 0);
  CHECK_THROWS(relpos::detail::approximate_real_roots(quartic, 5, 4, out));
}

TEST_CASE("double_bits: exponent_of and power_of_two are std::ilogb and std::ldexp on normal numbers", "[roots]") {
  std::mt19937_64 rng(1023);
  for (int k = -1022; k <= 1023; ++k) CHECK(relpos::detail::power_of_two(k) == std::ldexp(1.0, k));
  for (int i = 0; i < 100000; ++i) {
    std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isnormal(x)) continue;
    CHECK(relpos::detail::exponent_of(x) == std::ilogb(x));
  }
}
