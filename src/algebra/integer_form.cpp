#include "algebra/integer_form.hpp"

#include <algorithm>

#include "algebra/decimal_recipe.hpp"
#include "algebra/denominators.hpp"
#include "algebra/exact_doubles.hpp"

namespace relpos::detail::forms {
namespace {

/// The entries of a dyadic matrix (every denominator a power of two) over the largest, 2^top.
void dyadic_form(const Matrix4& m, mp_bitcnt_t top, MatrixOf<Integer>& out) {
  for (std::size_t i = 0; i < 16; ++i)
    mpz_mul_2exp(out.a[i].mpz(), mpq_numref(m.a[i].mpq()), top - mpz_scan1(mpq_denref(m.a[i].mpq()), 0));
}

/// The entries of m over the lcm of its denominators.
void general_form(const Matrix4& m, const Integer& lcm, MatrixOf<Integer>& out) {
  // Most entries share their denominator with the previous one, or have the lcm itself.
  Integer q;  // fresh: written through mpz()
  mpz_srcptr last = nullptr;
  for (std::size_t i = 0; i < 16; ++i) {
    const mpz_srcptr d = mpq_denref(m.a[i].mpq());
    if (mpz_cmp(d, lcm.mpz()) == 0) {
      mpz_set(out.a[i].mpz(), mpq_numref(m.a[i].mpq()));
      continue;
    }
    if (!last || mpz_cmp(d, last) != 0) {
      mpz_divexact(q.mpz(), lcm.mpz(), d);
      last = d;
    }
    mpz_mul(out.a[i].mpz(), q.mpz(), mpq_numref(m.a[i].mpq()));
  }
}

/// d[i] = m_i 2^k_i with m_i odd (|m_i| < 2^53), or m_i = k_i = 0 for d[i] = 0: the lcm of the
/// denominators is 2^top with top = max(0, -k_i) (returned), and the integer entries are
/// m_i 2^(k_i + top).
long dyadic_entries(const DoubleMatrix4& d, std::int64_t (&m)[16], long (&k)[16]) {
  long top = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    if (d[i] == 0) {
      m[i] = 0;
      k[i] = 0;
      continue;
    }
    const Dyadic x = dyadic_of(d[i]);
    m[i] = x.m;
    k[i] = x.k;
    top = std::max(top, -k[i]);
  }
  return top;
}

}  // namespace

MatrixOf<Integer> integer_form(const Matrix4& m, Integer& l) {
  MatrixOf<Integer> out;  // fresh entries: written through mpz()
  // Dyadic entries (exact doubles): the lcm is the largest power of two, the entries shifts.
  mp_bitcnt_t top = 0;
  bool dyadic = true;
  for (const Rational& q : m.a) {
    const mpz_srcptr d = mpq_denref(q.mpq());
    const mp_bitcnt_t k = mpz_scan1(d, 0);
    if (k + 1 != mpz_sizeinbase(d, 2)) {
      dyadic = false;
      break;
    }
    top = std::max(top, k);
  }
  Integer lcm(1);  // fresh: written through mpz()
  if (dyadic) {
    mpz_mul_2exp(lcm.mpz(), lcm.mpz(), top);
    dyadic_form(m, top, out);
  } else {
    lcm_of_denominators(m.a.begin(), m.a.end(), lcm);
    general_form(m, lcm, out);
  }
  l = lcm;
  return out;
}

void integer_form_of(const detail::QuadricMatrix& q, const IntegerFormOut& out) {
  if (const detail::DecimalRecipe* recipe = q.recipe(); recipe && detail::write_integer_form(*recipe, out)) return;
  const MatrixOf<Integer> form = integer_form(q.matrix(), out.l);
  for (std::size_t i = 0; i < 16; ++i) mpz_set(out.form[i], form.a[i].mpz());
  out.split = split_scale(out.l, q.matrix());
}

bool small_integer_form(const DoubleMatrix4& d, MatrixOf<std::int64_t>& out, unsigned long& twos) {
  std::int64_t m[16];
  long k[16];
  const long top = dyadic_entries(d, m, k);
  for (std::size_t i = 0; i < 16; ++i) {
    if (m[i] == 0) {
      out.a[i] = 0;
      continue;
    }
    // |m_i| 2^shift < 2^62 iff bit_length(|m_i|) + shift <= 62 (|m_i| < 2^53: no overflow below).
    const long shift = k[i] + top;
    const auto magnitude = static_cast<std::uint64_t>(m[i] < 0 ? -m[i] : m[i]);
    if (64 - __builtin_clzll(magnitude) + shift > 62) return false;
    out.a[i] = m[i] * (std::int64_t{1} << shift);
  }
  twos = static_cast<unsigned long>(top);
  return true;
}

void integer_form(const DoubleMatrix4& d, const std::array<mpz_ptr, 16>& out, Integer& l) {
  std::int64_t m[16];
  long k[16];
  const long top = dyadic_entries(d, m, k);
  for (std::size_t i = 0; i < 16; ++i) {
    mpz_set_si(out[i], static_cast<long>(m[i]));
    if (m[i] != 0) mpz_mul_2exp(out[i], out[i], static_cast<mp_bitcnt_t>(k[i] + top));
  }
  Integer lcm(1);  // fresh: written through mpz()
  mpz_mul_2exp(lcm.mpz(), lcm.mpz(), static_cast<mp_bitcnt_t>(top));
  l = lcm;
}

MatrixOf<Integer> integer_form(const DoubleMatrix4& d, Integer& l) {
  MatrixOf<Integer> out;  // fresh entries: written through mpz()
  integer_form(d, entries(out), l);
  return out;
}

}  // namespace relpos::detail::forms
