// The static filter's fast path: characteristic_polynomial_lanes and special_polynomial_lanes
// (algebra/pencil.hpp) must equal the generic templates in double bit for bit, since the filter's
// error bounds are derived on the generic templates (math.md §11); and DiscriminantSignBits
// (filters/static_filter.hpp) must read the same case and rho comparison as the unpacked signs.
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "algebra/forms.hpp"
#include "algebra/pencil.hpp"
#include "algebra/smallness.hpp"
#include "filters/static_filter.hpp"
#include "relpos/numbers.hpp"

namespace {

using relpos::DoubleMatrix4;

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

/// Equal bit patterns (so -0 differs from +0); two NaNs count as equal (their payload is not part
/// of any result the filter reads: a NaN coefficient is never certified).
bool same_bits(double x, double y) { return bits(x) == bits(y) || (std::isnan(x) && std::isnan(y)); }

void check_same(const DoubleMatrix4& p, const DoubleMatrix4& e) {
  const auto scalar = relpos::characteristic_polynomial<double>(relpos::detail::forms::DoubleView{p},
                                                                relpos::detail::forms::DoubleView{e});
  const auto lanes = relpos::characteristic_polynomial_lanes(p, e);
  for (std::size_t i = 0; i < 5; ++i) {
    INFO("f coefficient " << i << ": " << scalar[i] << " vs " << lanes[i]);
    CHECK(same_bits(scalar[i], lanes[i]));
  }
  const auto s_scalar =
      relpos::special_polynomial<double>(relpos::detail::forms::DoubleView{p}, relpos::detail::forms::DoubleView{e});
  const auto s_lanes = relpos::special_polynomial_lanes(p, e);
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("s coefficient " << i << ": " << s_scalar[i] << " vs " << s_lanes[i]);
    CHECK(same_bits(s_scalar[i], s_lanes[i]));
  }
}

/// A random entry: sign, a 53-bit mantissa and an exponent in [lo, hi]; zero (either sign) with
/// probability `zeros`.
double entry(std::mt19937_64& g, int lo, int hi, double zeros) {
  std::uniform_real_distribution<double> u(0, 1);
  if (u(g) < zeros) return u(g) < 0.5 ? 0.0 : -0.0;
  const double m = std::uniform_real_distribution<double>(1, 2)(g);
  const int k = std::uniform_int_distribution<int>(lo, hi)(g);
  return (u(g) < 0.5 ? -1 : 1) * std::ldexp(m, k);
}

DoubleMatrix4 random_matrix(std::mt19937_64& g, int lo, int hi, double zeros, bool symmetric) {
  DoubleMatrix4 m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      if (symmetric && c < r) {
        m[static_cast<std::size_t>(4 * r + c)] = m[static_cast<std::size_t>(4 * c + r)];
        continue;
      }
      m[static_cast<std::size_t>(4 * r + c)] = entry(g, lo, hi, zeros);
    }
  return m;
}

}  // namespace

TEST_CASE("the two-lane pencil equals the scalar template bit for bit", "[pencil][lanes][random]") {
  std::mt19937_64 g(20261125);
  struct Range {
    int lo, hi;
    double zeros;
  };
  // Entries in [1/2, 1) as the static filter sees them, wide exponent spreads (cancellation and
  // absorption in every sum), sparse matrices with signed zeros, and extremes whose products of
  // four entries stay normal (2^+-250).
  const Range ranges[] = {{-1, -1, 0.0}, {-30, 0, 0.0},    {-60, 60, 0.1},
                          {-3, 3, 0.5},  {-250, 250, 0.2}, {240, 250, 0.0}};
  for (const Range& r : ranges)
    for (int i = 0; i < 4000; ++i) {
      const bool symmetric = i % 2 == 0;
      check_same(random_matrix(g, r.lo, r.hi, r.zeros, symmetric), random_matrix(g, r.lo, r.hi, r.zeros, symmetric));
    }
}

TEST_CASE("the two-lane pencil on edge matrices: zeros, negative zeros, near-cancelling terms", "[pencil][lanes]") {
  const DoubleMatrix4 zero{}, negzero = [] {
    DoubleMatrix4 m;
    m.fill(-0.0);
    return m;
  }();
  check_same(zero, zero);
  check_same(negzero, negzero);
  check_same(zero, negzero);
  check_same(negzero, zero);
  DoubleMatrix4 id{}, ones;
  for (int i = 0; i < 4; ++i) id[static_cast<std::size_t>(5 * i)] = 1;
  ones.fill(1.0);
  check_same(id, id);
  check_same(ones, id);  // rank one: most minors cancel to exactly zero
  check_same(id, ones);
  check_same(ones, ones);
  // One entry non-zero at a time, with either sign of zero elsewhere: each term of the expansion
  // alone, so a lane or sign mix-up shows as a wrong coefficient.
  for (std::size_t k = 0; k < 16; ++k)
    for (double z : {0.0, -0.0}) {
      DoubleMatrix4 p, e;
      p.fill(z);
      e.fill(-z);
      p[k] = 3;
      e[15 - k] = -5;
      check_same(p, e);
      check_same(e, p);
      check_same(p, id);
    }
  // Near-singular: the identity perturbed in the last bit.
  DoubleMatrix4 near = ones;
  near[5] = std::nextafter(1.0, 2.0);
  near[10] = std::nextafter(1.0, 0.0);
  check_same(near, ones);
  check_same(near, near);
  // Extremes: largest and smallest normal magnitudes whose products of four stay in range.
  DoubleMatrix4 big, tiny;
  for (std::size_t k = 0; k < 16; ++k) {
    big[k] = (k % 3 == 0 ? -1 : 1) * std::ldexp(1.0 + static_cast<double>(k) / 16, 250);
    tiny[k] = (k % 5 == 0 ? -1 : 1) * std::ldexp(1.0 + static_cast<double>(k) / 16, -250);
  }
  check_same(big, tiny);
  check_same(tiny, big);
  check_same(big, big);
}

TEST_CASE("the two-lane pencil on small integer matrices is the exact polynomial", "[pencil][lanes]") {
  // An independent check of the expansion itself: exact integer arithmetic on the same entries.
  struct MI {
    std::array<relpos::Integer, 16> a;
    const relpos::Integer& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
  };
  std::mt19937_64 g(7);
  std::uniform_int_distribution<int> u(-20, 20);
  for (int i = 0; i < 500; ++i) {
    DoubleMatrix4 pd, ed;
    MI pi, ei;
    for (std::size_t k = 0; k < 16; ++k) {
      const int x = u(g), y = u(g);
      pd[k] = x;
      ed[k] = y;
      pi.a[k] = relpos::Integer(x);
      ei.a[k] = relpos::Integer(y);
    }
    const auto exact = relpos::characteristic_polynomial<relpos::Integer>(pi, ei);
    const auto lanes = relpos::characteristic_polynomial_lanes(pd, ed);
    for (std::size_t k = 0; k < 5; ++k) CHECK(relpos::Integer(static_cast<long>(lanes[k])) == exact[k]);
  }
}

TEST_CASE("DiscriminantSignBits reads its tables as the unpacked signs read discriminant_case and rho",
          "[filters][lanes]") {
  // Every pattern of certain-positive / certain-negative / uncertain over the 8 quantities (3^8).
  for (unsigned k = 0; k < 6561; ++k) {
    relpos::DiscriminantSignBits bits;
    unsigned rest = k;
    for (int i = 0; i < 8; ++i, rest /= 3) {
      if (rest % 3 == 1) bits.positive |= 1u << i;
      if (rest % 3 == 2) bits.negative |= 1u << i;
    }
    const relpos::DecisionSigns d = bits.signs();
    for (int i = 0; i < 5; ++i) {
      const bool pos = (bits.positive >> i) & 1, neg = (bits.negative >> i) & 1;
      CHECK(CGAL::is_certain(d.quartic.f[i]) == (pos || neg));
      if (pos) CHECK(CGAL::get_certain(d.quartic.f[i]) == CGAL::POSITIVE);
      if (neg) CHECK(CGAL::get_certain(d.quartic.f[i]) == CGAL::NEGATIVE);
    }
    CHECK(bits.discriminant_case() == relpos::discriminant_case(d.quartic));
    CHECK(bits.rho_vs_one() == relpos::compare_rho_with_one(d.vertex, d.graeffe).value_or(2));
  }
}
