// write_integer_form (decimal_recipe.hpp): the integer form of a quadric read from decimal text and
// its scale's split, from the exponents and mantissas of the numbers read.
#include <gmp.h>

#include <algorithm>
#include <iterator>

#include "algebra/decimal_recipe.hpp"
#include "algebra/power_of_five.hpp"
#include "algebra/word_arithmetic.hpp"

namespace relpos::detail {
namespace {

/// 5^k for k < 28 (< 2^64): the powers of five of decimal text, multiplied in one word.
constexpr unsigned long kMaxWordPower5 = 28;
constexpr auto kPower5 = [] {
  std::array<unsigned long, kMaxWordPower5> p{};
  p[0] = 1;
  for (std::size_t k = 1; k < kMaxWordPower5; ++k) p[k] = p[k - 1] * 5;
  return p;
}();

/// The upper triangle row by row (00 01 02 03 11 12 13 22 23 33), as row and column.
constexpr std::size_t kAt[10][2] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 1}, {1, 2}, {1, 3}, {2, 2}, {2, 3}, {3, 3}};

/// The integer form of an exact matrix of decimal text from the numbers read: each entry of the
/// upper triangle (row by row, as kAt) is (-1)^neg n 2^t2 5^t5 / D with D one of R_a^2, R_b^2 (the
/// rests of the mantissas of a and b of a standard paraboloid, prime to 10), their lcm, or 1. The lcm
/// of the denominators is 2^u2 5^u5 rest with u2, u5 the largest negative exponents once n's own 2s
/// and 5s are counted and rest = lcm(R_a^2, R_b^2) (1/a^2 and 1/b^2 are entries with n = 1, so the
/// rest is no smaller): no rationals and no gcd but one of two words.
class DecimalForm {
 public:
  DecimalForm() {
    for (auto& x : n_) mpz_init(x);
    for (auto& x : cof_) mpz_init(x);
    mpz_set_ui(cof_[kOverRest], 1);  // an entry over the rest itself: cofactor 1
  }
  ~DecimalForm() {
    for (auto& x : n_) mpz_clear(x);
    for (auto& x : cof_) mpz_clear(x);
  }
  DecimalForm(const DecimalForm&) = delete;
  DecimalForm& operator=(const DecimalForm&) = delete;

  /// Every entry zero, ready for a new matrix; the integers keep their limbs (a form reused by a
  /// thread writes quadric after quadric without malloc).
  void reset() {
    for (auto& x : n_) mpz_set_ui(x, 0);
    std::fill(std::begin(t2_), std::end(t2_), 0L);
    std::fill(std::begin(t5_), std::end(t5_), 0L);
    std::fill(std::begin(which_), std::end(which_), 0);
    std::fill(std::begin(rest_), std::end(rest_), std::uint64_t{1});
  }

  /// Entry k is (-1)^neg m 10^e (zero for m = 0).
  void decimal(std::size_t k, std::uint64_t m, int e, bool neg) {
    mpz_set_ui(n_[k], m);
    if (neg) mpz_neg(n_[k], n_[k]);
    t2_[k] = t5_[k] = e;
  }
  /// Entry k is n 10^e, n already in place (n_ref(k)).
  mpz_ptr n_ref(std::size_t k) { return n_[k]; }
  void exponents(std::size_t k, long t2, long t5) {
    t2_[k] = t2;
    t5_[k] = t5;
  }
  /// Entry k's denominator has the factor rests_[r]^2 (r = 1, 2).
  void over_square(std::size_t k, int r, std::uint64_t rest) {
    which_[k] = r;
    rest_[r] = rest;
  }
  /// Entry k's denominator has the factor lcm(R_a^2, R_b^2) (over_square of both given before).
  void over_rest(std::size_t k) { which_[k] = kOverRest; }

  void write(const forms::IntegerFormOut& out) {
    long u2 = 0, u5 = 0;
    normalize(u2, u5);
    if (!out.scale) {  // the exponents alone: no rest, no lcm
      out.split.twos = static_cast<unsigned long>(u2);
      out.split.fives = static_cast<unsigned long>(u5);
      return;
    }
    const mpz_ptr rest = cofactors();
    if (out.entries) write_entries(out, u2, u5);
    const mpz_ptr l = out.l.mpz();  // fresh: written in place
    forms::set_power_of_five(l, static_cast<unsigned long>(u5));
    mpz_mul_2exp(l, l, static_cast<unsigned long>(u2));
    mpz_mul(l, l, rest);
    if (!out.factors) {
      out.split.twos = static_cast<unsigned long>(u2);
      out.split.fives = static_cast<unsigned long>(u5);
      out.split.rest = Integer(rest);
      return;
    }
    // The rest's factors: R_a and R_b (refined when they share a factor), a coprime base of the
    // rest, which is all divided_by_powers reads. split_scale(l, m) gives the same on the axis; off
    // it, where a vertex's numerator may cancel part of R_a^2 or R_b^2, it may refine the base
    // further along the reduced denominators: the same lowest terms, one gcd per entry more.
    std::vector<forms::SplitScale::Factor> rests;
    for (std::size_t r = 1; r < 3; ++r)
      if (rest_[r] > 1 && (r == 1 || rest_[2] != rest_[1])) rests.push_back({Integer(rest_[r]), 2});
    out.split =
        forms::split_scale(static_cast<unsigned long>(u2), static_cast<unsigned long>(u5), Integer(rest), rests);
  }

 private:
  /// Each n's own 2s and 5s moved into its exponents; u2, u5 the largest negative exponents.
  void normalize(long& u2, long& u5) {
    for (std::size_t k = 0; k < 10; ++k) {
      if (mpz_sgn(n_[k]) == 0) continue;
      const mp_bitcnt_t twos = mpz_scan1(n_[k], 0);  // n's own 2s and 5s count in the exponents
      if (twos > 0) mpz_tdiv_q_2exp(n_[k], n_[k], twos);
      t2_[k] += static_cast<long>(twos);
      for (; mpz_divisible_ui_p(n_[k], 5); ++t5_[k]) mpz_divexact_ui(n_[k], n_[k], 5);
      u2 = std::max(u2, -t2_[k]);
      u5 = std::max(u5, -t5_[k]);
    }
  }

  /// rest = lcm(R_a^2, R_b^2) = (R_a R_b / g)^2 (returned, in cof_[0]) multiplies the entries
  /// without R; the others rest / R_a^2 = (R_b / g)^2 (cof_[1]) and rest / R_b^2 = (R_a / g)^2
  /// (cof_[2]), and 1 those over the rest (cof_[kOverRest]).
  mpz_ptr cofactors() {
    const std::uint64_t g = word_gcd(rest_[1], rest_[2]);
    auto& cof = cof_;
    mpz_set_ui(cof[1], rest_[2] / g);
    mpz_set_ui(cof[2], rest_[1] / g);
    for (std::size_t r = 1; r < 3; ++r) mpz_mul(cof[r], cof[r], cof[r]);
    const mpz_ptr rest = cof[0];
    mpz_set_ui(rest, rest_[1]);
    mpz_mul(rest, rest, rest);
    mpz_mul(rest, rest, cof[1]);
    return rest;
  }

  /// The entries n 2^(t2 + u2) 5^(t5 + u5) times their cofactor, each mirrored.
  void write_entries(const forms::IntegerFormOut& out, long u2, long u5) {
    for (std::size_t k = 0; k < 10; ++k) {
      const mpz_ptr z = out.form[4 * kAt[k][0] + kAt[k][1]];
      if (mpz_sgn(n_[k]) == 0) {
        mpz_set_ui(z, 0);
      } else {
        const auto fives = static_cast<unsigned long>(t5_[k] + u5);
        if (fives < kMaxWordPower5)
          mpz_mul_ui(z, n_[k], kPower5[fives]);
        else
          forms::times_power_of_five(z, n_[k], fives);
        mpz_mul_2exp(z, z, static_cast<unsigned long>(t2_[k] + u2));
        if (mpz_cmp_ui(cof_[which_[k]], 1) != 0) mpz_mul(z, z, cof_[which_[k]]);
      }
      if (kAt[k][0] != kAt[k][1]) mpz_set(out.form[4 * kAt[k][1] + kAt[k][0]], z);
    }
  }

  static constexpr int kOverRest = 3;
  mpz_t n_[10];
  mpz_t cof_[4];  // the rest (cof_[0]) and the cofactors of R_a^2, R_b^2 and the rest in it
  long t2_[10] = {}, t5_[10] = {};
  int which_[10] = {};
  std::uint64_t rest_[3] = {1, 1, 1};
};

/// The mantissa m without its factors 2 and 5 (R in DecimalForm), and their counts.
std::uint64_t rest_of(std::uint64_t m, long& twos, long& fives) {
  twos = __builtin_ctzll(m);
  m >>= twos;
  for (fives = 0; m % 5 == 0; ++fives) m /= 5;
  return m;
}

/// The entries of a sphere: the identity block, -c in the last column, the sphere sum.
void sphere_entries(const DecimalRecipe& r, DecimalForm& form) {
  const auto& n = r.n;
  for (std::size_t k : {0, 4, 7}) form.decimal(k, 1, 0, false);
  for (std::size_t i = 0; i < 3; ++i) form.decimal(i == 0 ? 3 : i == 1 ? 6 : 8, n[i].m, n[i].e, !n[i].neg);
  const long low = sphere_sum(r, form.n_ref(9));
  form.exponents(9, 2 * low, 2 * low);
}

/// v_x^2/a^2 + v_y^2/b^2 + v_z of a standard paraboloid off the axis as n 2^t2 5^t5 / lcm(R_a^2,
/// R_b^2), n into `sum` (the vertex's squares over a^2 and b^2 put over the lcm by (R_b / g)^2 and
/// (R_a / g)^2, g = gcd(R_a, R_b), then every term over the smallest powers of 2 and 5).
void vertex_sum(const DecimalRecipe& r, const std::uint64_t rest[2], const long twos[2], const long fives[2],
                mpz_ptr sum, long& t2, long& t5) {
  struct Term {
    mpz_t z;
    long t2, t5;
    Term() { mpz_init(z); }
    ~Term() { mpz_clear(z); }
  };
  thread_local Term terms[3];  // their limbs kept from quadric to quadric
  const auto& n = r.n;
  const std::uint64_t g = word_gcd(rest[0], rest[1]);
  const std::uint64_t cofactor[2] = {rest[1] / g, rest[0] / g};  // lcm / R^2 = cofactor^2
  int count = 0;
  for (std::size_t i = 0; i < 2; ++i) {
    if (n[i].m == 0) continue;
    Term& t = terms[count++];  // (m 10^e)^2 / (R 2^(ea + twos) 5^(ea + fives))^2, over the lcm
    mpz_set_ui(t.z, n[i].m);
    mpz_mul_ui(t.z, t.z, cofactor[i]);
    mpz_mul(t.z, t.z, t.z);
    t.t2 = 2 * (n[i].e - n[3 + i].e - twos[i]);
    t.t5 = 2 * (n[i].e - n[3 + i].e - fives[i]);
  }
  if (n[2].m != 0) {
    Term& t = terms[count++];  // v_z over the lcm
    mpz_set_ui(t.z, rest[0] / g);
    mpz_mul_ui(t.z, t.z, rest[1]);
    mpz_mul(t.z, t.z, t.z);
    mpz_mul_ui(t.z, t.z, n[2].m);
    if (n[2].neg) mpz_neg(t.z, t.z);
    t.t2 = t.t5 = n[2].e;
  }
  t2 = t5 = 0;
  for (int k = 0; k < count; ++k) {
    t2 = k == 0 ? terms[k].t2 : std::min(t2, terms[k].t2);
    t5 = k == 0 ? terms[k].t5 : std::min(t5, terms[k].t5);
  }
  mpz_set_ui(sum, 0);
  for (int k = 0; k < count; ++k) {
    Term& t = terms[k];
    mpz_mul_2exp(t.z, t.z, static_cast<unsigned long>(t.t2 - t2));
    if (t.t5 > t5) forms::times_power_of_five(t.z, t.z, static_cast<unsigned long>(t.t5 - t5));
    mpz_add(sum, sum, t.z);
  }
}

/// The entries of a standard paraboloid (Paraboloid::standard's matrix without rotation): 1/a^2,
/// 1/b^2, -1/2, and the vertex's -v_x/a^2, -v_y/b^2 and v_x^2/a^2 + v_y^2/b^2 + v_z (v_z on the axis).
void standard_entries(const DecimalRecipe& r, DecimalForm& form) {
  const auto& n = r.n;
  // 1/a^2 for a = m 10^e = R 2^(e + twos) 5^(e + fives): 2^(-2 (e + twos)) 5^(-2 (e + fives)) / R^2,
  // and -v_x / a^2 the same times -v_x.
  std::uint64_t rest[2];
  long twos[2], fives[2];
  for (std::size_t i = 0; i < 2; ++i) {
    rest[i] = rest_of(n[3 + i].m, twos[i], fives[i]);
    const long t2 = -2 * (n[3 + i].e + twos[i]), t5 = -2 * (n[3 + i].e + fives[i]);
    const std::size_t k = i == 0 ? 0 : 4;
    form.decimal(k, 1, 0, false);
    form.exponents(k, t2, t5);
    form.over_square(k, static_cast<int>(i) + 1, rest[i]);
    if (n[i].m == 0) continue;
    const std::size_t kv = i == 0 ? 3 : 6;
    form.decimal(kv, n[i].m, 0, !n[i].neg);
    form.exponents(kv, t2 + n[i].e, t5 + n[i].e);
    form.over_square(kv, static_cast<int>(i) + 1, rest[i]);
  }
  form.decimal(8, 1, 0, true);  // -1/2
  form.exponents(8, -1, 0);
  if (n[0].m == 0 && n[1].m == 0) {
    form.decimal(9, n[2].m, n[2].e, n[2].neg);
    return;
  }
  long t2 = 0, t5 = 0;
  vertex_sum(r, rest, twos, fives, form.n_ref(9), t2, t5);
  form.exponents(9, t2, t5);
  form.over_rest(9);
}

}  // namespace

bool write_integer_form(const DecimalRecipe& r, const forms::IntegerFormOut& out) {
  if (r.doubles) return false;
  thread_local DecimalForm form;
  form.reset();
  switch (r.form) {
    case DecimalRecipe::Form::Sphere:
      sphere_entries(r, form);
      break;
    case DecimalRecipe::Form::Standard:
      standard_entries(r, form);
      break;
    case DecimalRecipe::Form::Matrix: {
      const bool minus = r.orientation < 0;
      for (std::size_t k = 0; k < 10; ++k) {
        const Decimal& x = r.n[4 * kAt[k][0] + kAt[k][1]];
        form.decimal(k, x.m, x.e, x.neg != minus);
      }
      break;
    }
  }
  form.write(out);
  return true;
}

}  // namespace relpos::detail
