#include "algebra/decimal_recipe.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>

#include "algebra/denominators.hpp"
#include "algebra/exact_doubles.hpp"
#include "algebra/power_of_five.hpp"

namespace relpos::detail {
namespace {

static_assert(sizeof(unsigned long) >= sizeof(std::uint64_t), "GMP's _ui functions take the 19-digit m");

/// r = n 2^t2 5^t5 in canonical form, n the integer in r's numerator (not zero). The factors 2 and 5
/// of n cancel against negative powers and the denominator has no other prime: no gcd is needed.
void times_powers_of_2_and_5(mpq_ptr r, long t2, long t5) {
  const mpz_ptr num = mpq_numref(r), den = mpq_denref(r);
  if (t2 < 0) {
    const long v = std::min<long>(static_cast<long>(mpz_scan1(num, 0)), -t2);
    mpz_tdiv_q_2exp(num, num, static_cast<unsigned long>(v));
    t2 += v;
  }
  for (; t5 < 0 && mpz_divisible_ui_p(num, 5); ++t5) mpz_divexact_ui(num, num, 5);
  if (t5 > 0) forms::times_power_of_five(num, num, static_cast<unsigned long>(t5));
  forms::set_power_of_five(den, static_cast<unsigned long>(t5 < 0 ? -t5 : 0));
  if (t2 > 0) mpz_mul_2exp(num, num, static_cast<unsigned long>(t2));
  if (t2 < 0) mpz_mul_2exp(den, den, static_cast<unsigned long>(-t2));
}

/// The value m 10^e of a decimal number x != 0, negated when `minus`, written into r in canonical form.
void decimal_value(const Decimal& x, bool minus, mpq_ptr r) {
  mpz_set_ui(mpq_numref(r), x.m);
  if (x.neg != minus) mpz_neg(mpq_numref(r), mpq_numref(r));
  times_powers_of_2_and_5(r, x.e, x.e);
}

/// The exact value of a number as read, negated when `minus`: m 10^e, or the double itself.
Rational exact(Decimal x, bool doubles, bool minus = false) {
  x.neg = x.neg != minus;
  if (doubles) return Rational(std::ldexp(x.neg ? -double(x.m) : double(x.m), x.e - 53));
  if (x.m == 0) return Rational(0);
  Rational q;  // fresh: its mpq is not shared
  decimal_value(x, false, q.mpq());
  return q;
}

/// The entry c0^2 + c1^2 + c2^2 - r^2 of Ellipsoid::sphere for decimal numbers, written into q: the
/// integer sum over the smallest power of ten, then reduced by its factors 2 and 5 alone (no rational
/// additions). False (q unspecified) when the entry is zero.
bool sphere_constant_value(const DecimalRecipe& r, mpq_ptr q) {
  const int low = sphere_sum(r, mpq_numref(q));
  if (mpz_sgn(mpq_numref(q)) == 0) return false;
  times_powers_of_2_and_5(q, 2 * low, 2 * low);
  return true;
}

/// sphere_constant_value() as a Rational.
Rational sphere_constant(const DecimalRecipe& r) {
  Rational q;  // fresh: its mpq is not shared
  return sphere_constant_value(r, q.mpq()) ? q : Rational(0);
}

/// The symmetric matrix of an upper triangle given row by row (00 01 02 03 11 12 13 22 23 33): each
/// entry made once and shared with its mirror, no default entries made and replaced.
Matrix4 symmetric(const std::array<Rational, 10>& u) {
  return Matrix4{{u[0], u[1], u[2], u[3], u[1], u[4], u[5], u[6], u[2], u[5], u[7], u[8], u[3], u[6], u[8], u[9]}};
}

/// A standard paraboloid with its vertex on the axis, for the closed forms.
bool on_axis(const DecimalRecipe& r) { return r.n[0].m == 0 && r.n[1].m == 0; }

}  // namespace

int sphere_sum(const DecimalRecipe& r, mpz_ptr sum) {
  const auto& n = r.n;
  int low = 0;
  bool any = false;
  for (std::size_t i = 0; i < 4; ++i)
    if (n[i].m != 0) low = any ? std::min(low, n[i].e) : n[i].e, any = true;
  struct Term {  // one per thread: its limbs are kept
    mpz_t z;
    Term() { mpz_init(z); }
    ~Term() { mpz_clear(z); }
    Term(const Term&) = delete;
    Term& operator=(const Term&) = delete;
  };
  thread_local Term scratch;
  const mpz_ptr term = scratch.z;
  mpz_set_ui(sum, 0);
  for (std::size_t i = 0; i < 4; ++i) {
    if (n[i].m == 0) continue;
    mpz_set_ui(term, n[i].m);
    mpz_mul(term, term, term);
    if (n[i].e != low) {  // times 10^(2 (e - low))
      const auto k = static_cast<unsigned long>(2 * (n[i].e - low));
      forms::times_power_of_five(term, term, k);
      mpz_mul_2exp(term, term, k);
    }
    (i < 3 ? mpz_add : mpz_sub)(sum, sum, term);  // the radius is n[3]
  }
  return low;
}

Matrix4 exact_matrix(const DecimalRecipe& r) {
  const auto& n = r.n;
  const bool d = r.doubles;
  auto q = [&](std::size_t k, bool minus = false) { return exact(n[k], d, minus); };
  const Rational zero(0);
  switch (r.form) {
    case DecimalRecipe::Form::Sphere: {
      if (d) return Ellipsoid::sphere(Vector3{q(0), q(1), q(2)}, q(3)).matrix();
      const Rational one(1);
      return symmetric({one, zero, zero, q(0, true), one, zero, q(1, true), one, q(2, true), sphere_constant(r)});
    }
    case DecimalRecipe::Form::Standard:
      if (d || !on_axis(r)) return Paraboloid::standard(Vector3{q(0), q(1), q(2)}, q(3), q(4)).matrix();
      return symmetric({forms::inverse_square(q(3)), zero, zero, zero, forms::inverse_square(q(4)), zero, zero, zero,
                        Rational(-1, 2), q(2)});
    case DecimalRecipe::Form::Matrix:
      break;
  }
  const bool minus = r.orientation < 0;
  return symmetric({q(0, minus), q(1, minus), q(2, minus), q(3, minus), q(5, minus), q(6, minus), q(7, minus),
                    q(10, minus), q(11, minus), q(15, minus)});
}

bool has_closed_form(const DecimalRecipe& r) {
  return !r.doubles &&
         (r.form == DecimalRecipe::Form::Sphere || (r.form == DecimalRecipe::Form::Standard && on_axis(r)));
}

bool truncated_doubles(const DecimalRecipe& r, DoubleMatrix4& out) {
  if (r.doubles) return false;
  // Each entry made canonical in one scratch rational (decimal_value() and sphere_constant_value(),
  // as exact() and sphere_constant() make it) and truncated.
  thread_local Rational scratch;  // one per thread, never copied (so written in place): its limbs are kept
  const mpq_ptr q = scratch.mpq();
  const mpz_ptr num = mpq_numref(q), den = mpq_denref(q);
  // The entry (-1)^minus x of a decimal x, truncated.
  auto decimal = [&](const Decimal& x, bool minus) {
    if (x.m == 0) return 0.0;
    decimal_value(x, minus, q);
    return forms::truncated_double(scratch);
  };
  const auto& n = r.n;
  if (r.form == DecimalRecipe::Form::Matrix) {  // the numbers with the orientation (exactly symmetric)
    for (std::size_t k = 0; k < 16; ++k)
      out[k] = k % 4 < k / 4 ? out[4 * (k % 4) + k / 4] : decimal(n[k], r.orientation < 0);
    return true;
  }
  out.fill(0.0);
  if (r.form == DecimalRecipe::Form::Sphere) {
    out[0] = out[5] = out[10] = 1.0;
    for (std::size_t i = 0; i < 3; ++i) out[4 * i + 3] = out[12 + i] = decimal(n[i], true);
    if (sphere_constant_value(r, q)) out[15] = forms::truncated_double(scratch);
    return true;
  }
  thread_local Rational inverse[2], sum;  // 1/a^2 and 1/b^2 kept for a vertex off the axis
  for (std::size_t i = 0; i < 2; ++i) {   // 1/a^2, 1/b^2 (forms::inverse_square): a > 0 canonical, inverted, squared
    decimal(n[3 + i], false);
    mpz_swap(num, den);
    mpz_mul(num, num, num);
    mpz_mul(den, den, den);
    out[5 * i] = forms::truncated_double(scratch);
    mpq_swap(inverse[i].mpq(), q);
  }
  out[11] = out[14] = -0.5;
  if (on_axis(r)) {
    out[15] = decimal(n[2], false);
    return true;
  }
  // Paraboloid::standard's entries -v_x/a^2, -v_y/b^2 and v_x^2/a^2 + v_y^2/b^2 + v_z, each exact
  // (rational products and sums, no matrix) and then truncated.
  if (n[2].m == 0) {
    mpq_set_ui(sum.mpq(), 0, 1);
  } else {
    decimal_value(n[2], false, sum.mpq());
  }
  for (std::size_t i = 0; i < 2; ++i) {
    if (n[i].m == 0) continue;
    decimal_value(n[i], true, q);  // -v
    mpq_mul(inverse[i].mpq(), inverse[i].mpq(), q);
    out[4 * i + 3] = out[12 + i] = forms::truncated_double(inverse[i]);
    mpq_mul(q, q, inverse[i].mpq());  // v^2 / a^2
    mpq_add(sum.mpq(), sum.mpq(), q);
  }
  out[15] = forms::truncated_double(sum);
  return true;
}

}  // namespace relpos::detail
