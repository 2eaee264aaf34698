// Exact forms of a quadric's matrix: the one matrix view the generic formulas read, and the
// conversions every stage needs -- double enclosures for the interval stage, the common-lcm integer
// form of the reported evidence, and the compact integer form of the exact decisions
// (math.md §11). Computed here once, for every caller.
#pragma once

#include <CGAL/Interval_nt.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

#include "relpos/numbers.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/quadric.hpp"

namespace relpos::forms {

/// Matrix view with entries converted to NT, for the generic pencil code (m(i, j), row-major).
template <class NT>
struct MatrixOf {
  std::array<NT, 16> a;
  const NT& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// The entries of a matrix of exact doubles in NT (exact conversions).
template <class NT>
MatrixOf<NT> converted(const DoubleMatrix4& m) {
  MatrixOf<NT> out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = NT(m[i]);
  return out;
}

/// A DoubleMatrix4 read in place (no copy): the static filter's hot path.
struct DoubleView {
  const DoubleMatrix4& a;
  const double& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

using Interval = CGAL::Interval_nt<false>;

/// lcm(l, d) into l (d > 0): a divisibility test first, since most denominators of a matrix or a
/// polynomial are equal or divide one already taken (powers of 2 and 5), and lcm costs a gcd.
inline void fold_lcm(mpz_ptr l, mpz_srcptr d) {
  if (mpz_cmp_ui(d, 1) != 0 && !mpz_divisible_p(l, d)) mpz_lcm(l, l, d);
}

/// The lcm of the denominators of a range of rationals, folded into `l` (one loop for every caller).
template <class It>
void lcm_of_denominators(It first, It last, Integer& l) {
  for (; first != last; ++first) fold_lcm(l.mpz(), mpq_denref(first->mpq()));
}

/// 1 / a^2 for a != 0: the squares of its coprime numerator and denominator, swapped, are already
/// in lowest terms (no gcd, where rational division computes two).
inline Rational inverse_square(const Rational& a) {
  Rational out;  // fresh: its mpq is not shared, so it is written in place
  mpz_mul(mpq_numref(out.mpq()), mpq_denref(a.mpq()), mpq_denref(a.mpq()));
  mpz_mul(mpq_denref(out.mpq()), mpq_numref(a.mpq()), mpq_numref(a.mpq()));
  return out;
}

/// The integer q l, for l a multiple of q's denominator (lcm_of_denominators), written into `out`
/// (a fresh Integer's mpz, or an mpz_t: Gmpz shares its value on copy and mpz() does not unshare).
inline void scaled_numerator(const Rational& q, const Integer& l, mpz_ptr out) {
  mpz_divexact(out, l.mpz(), mpq_denref(q.mpq()));
  mpz_mul(out, out, mpq_numref(q.mpq()));
}

/// A positive integer scale split as 2^twos 5^fives rest, and rest^k for the powers a caller
/// divides by: 2 and 5 are what doubles and decimal text put in denominators. The rest is also
/// kept as a product of pairwise coprime factors base^power (one factor, rest itself, unless the
/// scale was split along its denominators), so that a gcd with it is a gcd with a short base.
struct SplitScale {
  struct Factor {
    Integer base;
    unsigned long power = 1;
  };
  unsigned long twos = 0, fives = 0;
  Integer rest{1};
  std::vector<Integer> rest_power;  ///< rest^k for k = 0..4; empty for rest 1 (doubles, decimal text)
  std::vector<Factor> factors;      ///< rest = prod base^power, bases pairwise coprime; empty for rest 1
};

/// Splits a positive integer.
SplitScale split_scale(const Integer& scale);

/// Splits scale = the lcm of the denominators of m's entries (integer_form), its rest kept as a
/// coprime base of those denominators' rests (square ones by their roots), with the lcm's powers:
/// for a standard paraboloid with decimal a and b, the rest of lcm(den(1/a^2), den(1/b^2)) becomes
/// ma^2 mb^2 (or ma'^2 c^2 mb'^2 when ma and mb share c) with one-limb bases instead of one
/// four-limb number.
SplitScale split_scale(const Integer& scale, const Matrix4& m);

/// split_scale(scale, m) from parts of the scale its caller knows: scale = 2^twos 5^fives rest, rest
/// prime to 10 and the lcm of `rests`, the distinct rests of m's denominators (2s and 5s removed), each
/// base^power with power 2 for a square.
SplitScale split_scale(unsigned long twos, unsigned long fives, const Integer& rest,
                       const std::vector<SplitScale::Factor>& rests);

/// out = 5^k: copied from a per-thread table of the powers met so far (k up to 512; beyond, computed):
/// the reductions by decimal scales need the same few powers line after line, and mpz_ui_pow_ui
/// recomputes one with a temporary allocation each time.
void set_power_of_five(mpz_ptr out, unsigned long k);
/// out = x 5^k (out may be x), from the same table.
void times_power_of_five(mpz_ptr out, mpz_srcptr x, unsigned long k);

/// One divisor of divided_by_powers: scale^k, k <= 4.
struct ScalePower {
  const SplitScale& scale;
  unsigned long k;
};

/// z / (scale_1^k_1 scale_2^k_2 ...) in lowest terms without a gcd of the long numbers: the twos
/// by a bit scan, the fives by single-limb remainders, and the common factor with each rest^k as
/// at most k e gcds with each factor b^e of rest, usually one that is 1 (a general gcd per
/// coefficient of the reported f and s costs a tenth to a sixth of a decimal batch line's full
/// evidence).
Rational divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors);
/// The same written into `out` (e.g. a fresh Rational's unshared mpq): no temporary Rational.
void divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors, mpq_ptr out);
inline Rational divided_by_powers(const Integer& z, std::initializer_list<ScalePower> divisors) {
  return divided_by_powers(z.mpz(), divisors);
}
inline Rational divided_by_power(const Integer& z, const SplitScale& scale, unsigned long k) {
  return divided_by_powers(z, {{scale, k}});
}

/// out = x exactly for a finite double x (as mpq_set_d), from its bits: an odd significand over a
/// power of two is already in lowest terms, so no gcd and each part is sized once.
void set_double(mpq_ptr out, double x);

/// The exponent k of a positive z = 2^k, or -1 when z is not a power of two (a dyadic rational's
/// denominator).
inline long power_of_two_exponent(mpz_srcptr z) {
  const mp_bitcnt_t k = mpz_scan1(z, 0);
  return k + 1 == mpz_sizeinbase(z, 2) ? static_cast<long>(k) : -1;
}

/// mpq_get_d(q) (CGAL::to_double): q truncated towards zero to a double. For a dyadic q in the
/// normal range without mpq_get_d's division (the searches' points and pulls are dyadic).
double truncated_double(const Rational& q);

/// CGAL::to_interval(q), the tightest interval of doubles around q, bit for bit: in the normal
/// range from mpq_get_d (q truncated towards zero) and the next double away from zero, or the point
/// when q is a double (a power-of-two denominator and at most 53 significant bits); else CGAL's
/// (MPFR). Independent of the rounding mode.
std::pair<double, double> tight_interval(const Rational& q);
/// Entries of a matrix of exact doubles, scaled by a power of two that brings the largest near 1
/// (guards interval overflow and underflow; a positive scaling of either matrix changes no decision,
/// math.md §1): a point interval times a power of two encloses the scaled entry even if the
/// product underflows. Call with the rounding mode towards +inf (CGAL::Protect_FPU_rounding).
MatrixOf<Interval> to_intervals(const DoubleMatrix4& m);

/// The stored enclosures of a quadric read from text, scaled by 2^k (largest bound near 1). Call
/// with the rounding mode towards +inf.
MatrixOf<Interval> to_intervals(const detail::EnclosureMatrix4& m);

/// Enclosures of the entries of m scaled by 2^k (largest near 1) without rational temporaries
/// (mpq_get_d truncates towards zero, so q lies between v and the next double away from zero).
MatrixOf<Interval> to_intervals(const Matrix4& m);

/// The matrix times the lcm of its own denominators (returned in `l`): the integer form of one
/// quadric. The reported evidence is computed on the two forms, each with its own scale:
/// det(lambda P + E) = sum_i g_i lambda^i / (lp^i le^(4-i)) with g = det(mu Pz + Ez), which keeps
/// every product shorter than one common lcm of both matrices would.
MatrixOf<Integer> integer_form(const Matrix4& m, Integer& l);
/// The same for a matrix of exact doubles, read from their bits (no rationals): equal to
/// integer_form of the matrix of Rational(d[i]).
MatrixOf<Integer> integer_form(const DoubleMatrix4& d, Integer& l);
/// The same written into the caller's integers (16 distinct mpz, row-major), e.g. pooled ones.
void integer_form(const DoubleMatrix4& d, const std::array<mpz_ptr, 16>& out, Integer& l);
/// The same in machine words when every entry is below 2^62 in absolute value (the integer forms of
/// doubles nearly always are: 53-bit significands shifted to a common power of two), with the lcm
/// as its exponent: l = 2^twos. False (out and twos unspecified) otherwise.
bool small_integer_form(const DoubleMatrix4& d, MatrixOf<std::int64_t>& out, unsigned long& twos);

/// The 16 entries' integers (row-major) of a matrix of fresh Integers (their values not shared) or
/// PooledIntegers, for the functions that write a form in place.
template <class NT>
std::array<mpz_ptr, 16> entries(MatrixOf<NT>& m) {
  std::array<mpz_ptr, 16> out;
  for (std::size_t i = 0; i < 16; ++i) out[i] = m.a[i].mpz();
  return out;
}

/// Where integer_form_of writes: integer_form(m, l) into 16 distinct integers (row-major, e.g.
/// entries() of pooled ones) and split_scale(l, m) of a quadric's matrix m.
struct IntegerFormOut {
  std::array<mpz_ptr, 16> form;
  Integer& l;
  SplitScale& split;
  /// False when the caller reads only the split's twos, fives and rest: a source may then leave
  /// rest_power and factors empty.
  bool factors = true;
  /// False when the caller reads only l and the split: a source may then leave `form` unwritten.
  bool entries = true;
  /// False when the caller reads only the split's twos and fives (and neither the form nor the
  /// factors): a source may then leave l and the split's rest unwritten too.
  bool scale = true;
};

/// integer_form(q.matrix(), l) and split_scale(l, q.matrix()): written by q's exact source from the
/// numbers it was read from when it can (decimal text: the lcm and the split from the exponents and
/// the mantissas, no rationals and no gcd of long numbers), else from the matrix.
void integer_form_of(const detail::QuadricMatrix& q, const IntegerFormOut& out);

/// A number read from decimal text: (-1)^neg m 10^e.
struct Decimal {
  std::uint64_t m = 0;
  int e = 0;
  bool neg = false;
};

/// The numbers a sphere or a standard paraboloid with its vertex on the z axis was read from: the
/// centre x, y, z and the radius r; or a, b and the vertex's z (n[3] unused). Written by the fast
/// reader's exact source (ExactSource::decimal_shape).
struct DecimalShape {
  bool sphere = true;
  std::array<Decimal, 4> n;
};

/// Where sphere_standard_evidence writes: f and s in lowest terms, lambda_s and rho.
/// With the exponents of 2 and 5 in S = lcm(lp, le), the lcm of the two integer forms' scales
/// (their rest is lcm(R_a^2, R_b^2), R the parts of a's and b's mantissas prime to 10), also the
/// common-lcm integer forms S^4 f and S^3 s.
struct ClosedEvidence {
  Quartic<Rational>& f;
  Quadratic<Rational>& s;
  Rational& lambda_s;
  Rational& rho;
  unsigned long s_twos, s_fives;
  Quartic<Integer>& f_multiple;    ///< S^4 f (fresh Integers: written in place)
  Quadratic<Integer>& s_multiple;  ///< S^3 s
};

/// The reported f = det(lambda P + E) and s = det(lambda A + M), lambda_s and rho of a sphere E
/// and a standard paraboloid P with its vertex on the axis, from closed forms (math.md §2, §5).
/// With A = 1/a^2, B = 1/b^2, w = vz - z, E's block is the identity and P's is diag(A, B, 0):
///   f0 = -r^2,  f1 = A (x^2 - r^2) + B (y^2 - r^2) + w,  f2 = A B (x^2 + y^2 - r^2) + (A + B) w - 1/4,
///   f3 = A B w - (A + B) / 4,  f4 = -A B / 4,  s = (1 + A lambda)(1 + B lambda),
/// so lambda_s, the root of s nearest 0, is -min(a, b)^2 and rho = (f0 / f4)(s2 / s0) / lambda_s^2
/// = (2 r / min(a, b)^2)^2. Each coefficient is a short integer over 2^i 5^j and the squares of the
/// parts of a's and b's mantissas prime to 10, reduced by a bit scan, single-limb remainders and
/// word gcds with those two parts: the same rationals as the general path (the integer forms'
/// determinants reduced along their scales), without their long integers. S^k times a coefficient
/// n 2^i 5^j / (R_a^2 R_b^2) is n 2^(k s_twos + i) 5^(k s_fives + j) lcm(R_a^2, R_b^2)^(k-1) / g^2,
/// g = gcd(R_a, R_b): products, no division of long integers.
void sphere_standard_evidence(const DecimalShape& sphere, const DecimalShape& paraboloid, const ClosedEvidence& out);

/// The smallest integer form the *decisions* need (not the evidence: the roots move). With
/// D = diag(1, 1, 1, t), t the lcm of the denominators of both translation columns, and positive
/// alpha, beta clearing the remaining denominators of D E D and D P D and dividing out each form's
/// content (each matrix's scale is forgotten):
///   det(lambda beta DPD + alpha DED) = t^2 alpha^4 f(beta lambda / alpha),
///   det(lambda beta A + alpha M)     = alpha^3 s(beta lambda / alpha),
/// so every root of f and s is multiplied by the same alpha / beta > 0: signs, multiplicities,
/// common roots and rho are unchanged, with far smaller integers than one common lcm.
/// The two forms are written into the caller's integers (16 distinct mpz each, row-major).
void to_compact_integers(const Matrix4& p, const Matrix4& e, const std::array<mpz_ptr, 16>& pz,
                         const std::array<mpz_ptr, 16>& ez);

}  // namespace relpos::forms
