// An independent exact pipeline written directly on FLINT (relpos_bench method "flint";
// doc/performance.md): a speed reference and a cross-check of relpos's exact answer.
//
// From the exact rational matrices it computes, with FLINT types only (fmpz, fmpz_poly):
//   * E and P with their denominators cleared (each matrix times the lcm of its own denominators:
//     f and s become c^4 f(k lambda), c^3 s(k lambda) with c, k > 0, which keeps root signs,
//     multiplicities, gcd(f, s) and rho);
//   * f(lambda) = det(lambda P + E) by a Laplace expansion in fmpz 2x2 minors of the pencil, and
//     s(lambda) = det(lambda A + M) along the first row;
//   * whether Disc(f) = 0: first modulo a 62-bit prime p (nmod_poly_discriminant; a non-zero residue
//     with p not dividing f4 proves Disc(f) != 0), else exactly with fmpz_poly_discriminant; when it is
//     non-zero, the negative and positive real roots with FLINT's Sturm sequence
//     (_fmpz_poly_num_real_roots_sturm, square-free input), and sign Disc(f) = (-1)^(non-real pairs);
//   * when Disc(f) = 0: gcd(f, s) (fmpz_poly_gcd), f~ = f / gcd (exact division, checked), the
//     square-free factorisations of f and of f~ (fmpz_poly_factor_squarefree) and Sturm counts on
//     each square-free factor: every real root fact, and the multiple real roots of f~ (tangencies);
//   * rho <= 1 with its own derivation (not smallness.hpp's): with K = (f0 s2)/(f4 s0) and
//     u1 <= u2 the roots of s(-u), rho = K / u1^2, so rho <= 1 iff sqrt(K) <= u1, decided by the
//     sign of s(-sqrt(K)) (times the positive conjugate: (s2 K + s0)^2 - s1^2 K) and the side of
//     the vertex (s1^2 - 4 s2^2 K), in fmpz after clearing K's denominator.
// The facts go to relpos's classification table, decide_from_root_facts (decide/decision.hpp): the
// table is shared, the arithmetic and the root facts are not.
#pragma once

#include <string>

#include "algebra/roots.hpp"
#include "relpos/classify.hpp"
#include "relpos/quadric.hpp"

namespace bench {

struct FlintAnswer {
  relpos::Position position = relpos::Position::C;  ///< meaningful when ok
  relpos::RootFacts facts;
  int rho_vs_one = 0;
  bool ok = false;  ///< false when the input is not in the expected normal form (never for valid quadrics), or when
                    ///< the facts do not decide (not small: math.md §8)
};

/// The FLINT pipeline on the exact matrices of a validated ellipsoid and paraboloid.
FlintAnswer flint_classify(const relpos::Matrix4& e, const relpos::Matrix4& p);

/// Untimed self-checks of the pipeline with other FLINT routines: f and s against
/// fmpz_poly_mat_det of the polynomial matrices lambda P + E and lambda A + M (the lambda^3
/// coefficient of s must vanish), and, when Disc(f) != 0, the real-root count against
/// fmpz_poly_num_real_roots and the exact sign of Disc(f) against the one read off the count.
/// Returns "" when every check passes, else what failed.
std::string flint_self_check(const relpos::Matrix4& e, const relpos::Matrix4& p);

}  // namespace bench
