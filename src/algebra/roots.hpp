// Exact root structure of the characteristic polynomial, for the cases the Sturm-Habicht signs
// cannot settle (Disc(f) = 0 or a defective sequence), and certified root approximations for
// reports. Everything here is exact polynomial arithmetic over Z (CGAL Polynomial, gcd, square-free
// factorisation, the real-root isolation of CGAL's Algebraic_kernel_d_1); no root is computed in
// floating point.
//
// The multiplicity rule (math.md §3): with f~ = f / gcd(f, s),
//   tangency  <=>  mult_f(l0) - mult_s(l0) >= 2 for some real l0  <=>  f~ has a multiple real root.
// A multiple root of f that is not multiple in f~ is a "special" root of s (paper Remark 2,
// Theorem 5: -a^2, -b^2 in the normal frame) and is not a tangency.
#pragma once

#include <gmp.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "algebra/pencil.hpp"
#include "relpos/numbers.hpp"

namespace relpos {

/// Everything exact about the roots of f and of f~ = f / gcd(f, s).
struct RootStructure {
  std::vector<RealRoot> real_roots;  ///< distinct real roots, increasing
  int nonreal = 0;                   ///< number of non-real roots of f, with multiplicity
  int nonreal_multiple = 0;          ///< non-real roots of f of multiplicity >= 2 (never seen in theory)
  int degree_ftilde = 4;
  int sign_disc_f = 0;
  int sign_disc_ftilde = 0;
  int negative() const;
  int positive() const;
};

/// Root facts from exact gcd(f, s) and square-free factorisations when Disc(f) = 0. Then every
/// square-free factor of the quartic f has degree <= 2 (4 = d1 + 2 d2 + 3 d3 + 4 d4 with some
/// d_k > 0, k >= 2, forces d1 <= 2), so each factor's real roots and their signs have closed forms
/// (discriminant; Descartes' rule, exact for real-rooted factors). nullopt when f is square-free
/// (defective Sturm-Habicht sequence with Disc(f) != 0): use exact_root_structure() then.
std::optional<RootFacts> exact_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s);

/// The fast case of exact_root_facts(), without any polynomial gcd: Disc(f) = 0 and every multiple
/// root of f rational. gcd(f, f') is the first non-zero subresultant of the Sturm-Habicht sequence
/// (linear: one double root; quadratic g2: a triple root when Disc(g2) = 0, two double roots when
/// Disc(g2) is a non-zero square; cubic: a quadruple root), so the multiple roots are read off it,
/// divided out exactly, and every fact follows in closed form from them and the square-free
/// cofactor. nullopt when f is square-free or has irrational or non-real multiple roots.
std::optional<RootFacts> subresultant_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s);

/// The same with f's Sturm-Habicht coefficients already computed (g2, g1 and g0 = Disc(f) as in
/// sturm_habicht_quartic.hpp), e.g. by the exact-sign stage.
std::optional<RootFacts> subresultant_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s,
                                                 const Integer g2[3], const Integer g1[2], const Integer& disc);

/// The general case: gcd(f, s) and square-free factorisations (CGAL). nullopt when f is square-free.
std::optional<RootFacts> exact_root_facts_by_factorisation(const Quartic<Integer>& f, const Quadratic<Integer>& s);

/// The common case of exact_root_structure() without CGAL's algebraic kernel: f square-free
/// (Disc(f) != 0, FLINT), coprime to s (Res(f, s) != 0), without rational roots (a prime p for which
/// f mod p has no root in F_p), its real roots approximated in doubles and each certified by exact
/// opposite signs of f at the (dyadic) ends of disjoint intervals, as many as Disc(f) says there are
/// real roots. nullopt when any of this fails (then the general path decides). `sign_disc_f`, when
/// not 0, is the already certified sign of Disc(f) (e.g. a Verdict's), saving its computation.
std::optional<RootStructure> simple_root_structure(const Quartic<Integer>& f, const Quadratic<Integer>& s,
                                                   int sign_disc_f = 0);

/// Exact root structure of f (integer coefficients, f(0) != 0) relative to s (`sign_disc_f`: as
/// for simple_root_structure).
RootStructure exact_root_structure(const Quartic<Integer>& f, const Quadratic<Integer>& s, int sign_disc_f = 0);

/// Certified decimal approximations of the real roots of f: each string has `digits` significant
/// digits and the true root lies within one unit of the last digit (the isolating interval is
/// refined until it is that narrow).
std::vector<std::string> real_root_decimals(const Quartic<Integer>& f, int digits);

/// Exact sign of Disc(g) for a polynomial over Z of degree 1..4 (via Res(g, g')); used for f~.
int sign_of_discriminant(const std::vector<Integer>& coefficients);

namespace detail {

/// The residue of z modulo a compile-time constant M < 2^32, in [0, M) (mpz_fdiv_ui's value), from
/// its limbs by Horner in base 2^GMP_NUMB_BITS: every product stays below 2^64 and every remainder
/// is by a constant (a multiplication), without mpz_fdiv_ui's set-up for a run-time divisor.
template <unsigned long long M>
unsigned long residue(mpz_srcptr z) {
  static_assert(M > 1 && M < (1ULL << 32) && GMP_NAIL_BITS == 0 && GMP_NUMB_BITS <= 64);
  constexpr unsigned long long base = (static_cast<unsigned long long>(GMP_NUMB_MAX) % M + 1) % M;  // 2^bits mod M
  const mp_limb_t* limbs = mpz_limbs_read(z);
  unsigned long long r = 0;
  for (mp_size_t i = static_cast<mp_size_t>(mpz_size(z)); i-- > 0;)
    r = (r * base + static_cast<unsigned long long>(limbs[i]) % M) % M;  // < M^2 + M <= 2^64
  return static_cast<unsigned long>(mpz_sgn(z) < 0 && r != 0 ? M - r : r);
}

/// The exact sign of an integer polynomial h (h[0..n], n <= 4, h[n] != 0) at doubles, as the root
/// certification asks for it: the double Horner value against a crude bound (2^-48 of the
/// magnitude), then a compensated Horner evaluation on h's leading 53 bits plus the leading 53 bits
/// of the rest (each coefficient split in two doubles) with a rigorous bound
/// (round-to-nearest only), then exactly in integers. Each stage answers only when certain, so the
/// result is always the exact sign; the cheaper stages only save work.
class DoubleSign {
 public:
  DoubleSign(const Integer* h, int n);
  int operator()(double x);
  /// The two floating-point stages only: the exact sign, or 0 when neither is certain.
  int filtered(double x);
  /// h / 2^top in doubles (each coefficient truncated to 53 bits), c[0..n].
  const double* coefficients() const { return c_; }
  /// The Cauchy bound on the roots of c, or 0 when it is not a finite double.
  double root_bound() const { return bound_; }

 private:
  bool split();
  int compensated(double x, double mag);
  const Integer* h_;
  int n_;
  long top_ = 0;
  double c_[5] = {}, lo_[5] = {}, bound_ = 0;
  bool relative_ = true;
  int split_ = 0;  // lo_ filled: 1, impossible: -1, not yet: 0
};

}  // namespace detail

}  // namespace relpos
