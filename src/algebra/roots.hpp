// Exact root structure of the characteristic polynomial, for the cases the Sturm-Habicht signs
// cannot settle (Disc(f) = 0 or a defective sequence), and certified root approximations for
// reports. Everything here is exact polynomial arithmetic over Z (CGAL Polynomial, gcd, square-free
// factorisation, the real-root isolation of CGAL's Algebraic_kernel_d_1); no root is computed in
// floating point. The fast path (simple_root_structure, simple_roots.cpp) only proposes roots in
// doubles (approximate_roots.hpp) and certifies each by exact signs (double_sign.hpp) after modular
// tests (modular.hpp); the general path is roots.cpp. The facts when Disc(f) = 0: root_facts.hpp.
//
// The multiplicity rule (math.md §3): with f~ = f / gcd(f, s),
//   tangency  <=>  mult_f(l0) - mult_s(l0) >= 2 for some real l0  <=>  f~ has a multiple real root.
// A multiple root of f that is not multiple in f~ is a "special" root of s (paper Remark 2,
// Theorem 5: -a^2, -b^2 in the normal frame) and is not a tangency.
#pragma once

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "algebra/large_stack.hpp"
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

/// CGAL's algebraic kernel's solve_1 of p (an integer polynomial), its roots appended to `out`, on
/// a stack its recursion fits (large_stack.hpp: isolate_on_fitting_stack), whatever the calling
/// thread's stack. Every isolation of the roots of a pair's f and D (decision, evidence, report) goes
/// through here; a motion's candidate instants, within its limits (doc/cli.md), do not.
template <class AK, class Poly, class Out>
void solve_on_fitting_stack(const AK& ak, const Poly& p, Out out) {
  std::size_t bits = 0;
  for (int i = 0; i <= p.degree(); ++i) bits = std::max(bits, mpz_sizeinbase(p[i].mpz(), 2));
  detail::isolate_on_fitting_stack(p.degree(), bits, [&] { ak.solve_1_object()(p, out); });
}

/// Exact sign of Disc(g) for a polynomial over Z of degree 1..4 (via Res(g, g')); used for f~.
int sign_of_discriminant(const std::vector<Integer>& coefficients);

}  // namespace relpos
