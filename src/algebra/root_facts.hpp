// The root facts of f when Disc(f) = 0, exactly (math.md §3): distinct real roots by sign, the
// multiple roots that are tangencies (mult_f - mult_s >= 2), deg f~ and the sign of Disc(f~). Then
// every square-free factor of the quartic f has degree <= 2 (4 = d1 + 2 d2 + 3 d3 + 4 d4 with some
// d_k > 0, k >= 2, forces d1 <= 2), so each factor's real roots and their signs have closed forms
// (discriminant; Descartes' rule, exact for real-rooted factors). A square-free f (a defective
// Sturm-Habicht sequence with Disc(f) != 0) is not these functions' case: roots.hpp then.
#pragma once

#include <optional>

#include "algebra/pencil.hpp"
#include "relpos/numbers.hpp"

namespace relpos {

/// Root facts from the subresultants, else from exact gcd(f, s) and square-free factorisations;
/// nullopt when f is square-free.
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

}  // namespace relpos
