// kind_filter.hpp.
#include "algebra/kind_filter.hpp"

#include <array>
#include <climits>
#include <cmath>

#include "algebra/shape_filter.hpp"

namespace relpos::detail::shape_filter {

namespace {

using impl::I;

/// mpz_t variables for one call, cleared on the way out (GMP allocates their limbs lazily, and the
/// CLI's and the module's GMP block cache recycles them: no CGAL handle per temporary).
template <std::size_t N>
struct Integers {
  mpz_t v[N];
  Integers() {
    for (auto& x : v) mpz_init(x);
  }
  ~Integers() {
    for (auto& x : v) mpz_clear(x);
  }
  Integers(const Integers&) = delete;
  Integers& operator=(const Integers&) = delete;
};

/// The signs of d1, d2, d3 and det exactly, on the integers m_k 2^(e_k - e_min) of the doubles:
/// the 2x2 minors s of rows 0, 1 and c of rows 2, 3 (det = sum of +-s c over complementary column
/// pairs), d2 = s01 and d3 = m22 s01 - m21 s02 + m20 s12.
std::array<int, 4> exact_signs(const DoubleMatrix4& d) {
  std::array<long, 16> exponent{};
  std::array<long long, 16> significand{};
  long low = LONG_MAX;
  for (std::size_t k = 0; k < 16; ++k) {
    if (d[k] == 0) continue;
    int e = 0;
    const double m = std::frexp(d[k], &e);  // d = m 2^e, 1/2 <= |m| < 1: m 2^53 is an integer
    significand[k] = static_cast<long long>(std::ldexp(m, 53));
    exponent[k] = e - 53;
    low = std::min(low, exponent[k]);
  }
  Integers<16> z;
  for (std::size_t k = 0; k < 16; ++k) {
    if (significand[k] == 0) continue;
    mpz_set_si(z.v[k], significand[k]);
    mpz_mul_2exp(z.v[k], z.v[k], static_cast<mp_bitcnt_t>(exponent[k] - low));
  }
  const auto m = [&](int i, int j) { return z.v[4 * i + j]; };
  Integers<14> t;  // s01 s02 s03 s12 s13 s23, c01 c02 c03 c12 c13 c23, d3, det
  const int cols[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (int k = 0; k < 6; ++k) {
    const int a = cols[k][0], b = cols[k][1];
    mpz_mul(t.v[k], m(0, a), m(1, b));
    mpz_submul(t.v[k], m(0, b), m(1, a));
    mpz_mul(t.v[6 + k], m(2, a), m(3, b));
    mpz_submul(t.v[6 + k], m(2, b), m(3, a));
  }
  mpz_mul(t.v[12], m(2, 2), t.v[0]);
  mpz_submul(t.v[12], m(2, 1), t.v[1]);
  mpz_addmul(t.v[12], m(2, 0), t.v[3]);
  mpz_mul(t.v[13], t.v[0], t.v[11]);  // s01 c23 - s02 c13 + s03 c12 + s12 c03 - s13 c02 + s23 c01
  mpz_submul(t.v[13], t.v[1], t.v[10]);
  mpz_addmul(t.v[13], t.v[2], t.v[9]);
  mpz_addmul(t.v[13], t.v[3], t.v[8]);
  mpz_submul(t.v[13], t.v[4], t.v[7]);
  mpz_addmul(t.v[13], t.v[5], t.v[6]);
  return {mpz_sgn(m(0, 0)), mpz_sgn(t.v[0]), mpz_sgn(t.v[12]), mpz_sgn(t.v[13])};
}

}  // namespace

std::optional<QuadricKind> certified_kind(const DoubleMatrix4& d) {
  if (!impl::symmetric(d)) return std::nullopt;
  for (const double x : d)
    if (!std::isfinite(x)) return std::nullopt;
  std::array<int, 4> s;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const std::array<I, 16> e = impl::interval_entries(d);
    s = {d[0] > 0 ? 1 : (d[0] < 0 ? -1 : 0), impl::certain_sign(e[0] * e[5] - e[1] * e[1]),
         impl::certain_sign(impl::det3<I>(e)), impl::certain_sign(impl::det4<I>(e))};
  }
  if (s[0] == 0) return std::nullopt;
  if (s[1] == 0 || s[2] == 0 || s[3] == 0) s = exact_signs(d);
  if (s[0] == 0 || s[1] == 0 || s[2] == 0 || s[3] == 0) return std::nullopt;
  const int negative = (s[0] < 0) + (s[1] != s[0]) + (s[2] != s[1]);  // sign changes in 1, d1, d2, d3
  if (negative == 0 || negative == 3) return s[3] < 0 ? QuadricKind::Ellipsoid : QuadricKind::ImaginaryEllipsoid;
  return s[3] > 0 ? QuadricKind::HyperboloidOneSheet : QuadricKind::HyperboloidTwoSheets;
}

}  // namespace relpos::detail::shape_filter
