// Disc(f) = 0 certified by a witness, on machine integers: the fast exact path for exactly
// degenerate inputs (tangencies, special double roots) given as doubles.
//
// A float filter can never certify a zero (math.md §9), and computing Disc(f) exactly is
// expensive: it has degree 6 in the coefficients of f. But Disc(f) = 0 has a short certificate --
// a multiple root. When f has a rational multiple root p/q (always the case for a single double,
// triple or quadruple root; two double roots are rational or a conjugate pair), we
//   1. find candidates numerically: the real roots of f', f'' and f''' in double precision (a
//      multiple root of f of multiplicity m is a simple root of f^(m-1), so it is well conditioned
//      there), turned into small-denominator rationals by continued fractions;
//   2. verify each candidate exactly: divide f by (q lambda - p) with exact integer division
//      (Gauss's lemma: if p/q is a root in lowest terms, the quotient has integer coefficients),
//      as many times as it divides -- that is its multiplicity, exactly;
//   3. read the root facts off the factorisation f = c * prod (q_k lambda - p_k)^(m_k) * h with
//      deg h <= 2 and h square-free (closed forms, detail/small_factor.hpp), and the multiplicities
//      in s by evaluating s and s' at p_k/q_k exactly.
// The numerics only *propose*; every fact is an exact integer identity, so a wrong proposal costs
// time, never correctness. Everything runs on CheckedInt (checked_int.hpp): no allocation. When a
// number overflows, no candidate verifies, or a multiple root is irrational, the functions return
// nullopt and the caller uses the general GMP path (root_facts.hpp).
#pragma once

#include <optional>

#include "algebra/pencil.hpp"
#include "algebra/root_facts.hpp"
#include "filters/checked_int.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

/// f and s of a pair of exact-double matrices, exactly, on machine integers: each matrix is
/// scaled by a power of two to integer entries (a positive scaling of either matrix multiplies f
/// and s by positive constants and scales their roots by a positive factor: no decision changes).
/// nullopt if an entry does not fit in 62 bits or a coefficient overflows 127 bits.
struct MachinePencil {
  Quartic<CheckedInt> f;
  Quadratic<CheckedInt> s;
};
std::optional<MachinePencil> machine_pencil(const DoubleMatrix4& p, const DoubleMatrix4& e);

/// The facts of root_facts.hpp when f has a rational multiple root, certified as above; nullopt when no
/// certificate was found (f square-free, an irrational multiple root, or overflow). sign_disc_f is
/// 0 by construction. degree_ftilde is -1 when computing it would overflow (decisions never use it).
std::optional<RootFacts> rational_multiple_root_facts(const Quartic<CheckedInt>& f, const Quadratic<CheckedInt>& s);

}  // namespace relpos
