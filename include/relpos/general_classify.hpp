// An ellipsoid against any real quadric, decided exactly (math.md §15–§17), with its evidence and
// certificate (math.md §18).
//
// decide_position() first evaluates the decision in doubles with certified error bounds (the
// pencil's quartic and cubic, the Sturm–Habicht counts at the ends of the multipliers' intervals,
// math.md §17); only a pair it cannot certify goes to exact integers (real roots of f and D isolated
// and compared exactly). classify() adds the exact evidence and the certificate.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "relpos/error.hpp"
#include "relpos/general_position.hpp"
#include "relpos/general_quadric.hpp"

namespace relpos {

/// What settled a general pair.
enum class QuadricStage : unsigned char {
  Filter,  ///< doubles with certified error bounds
  Exact,   ///< exact integer pencil, real roots isolated and compared exactly
};
/// "filter", "exact".
std::string to_string(QuadricStage s);

/// The rule that decided (math.md §16): where the real roots of f = det(Q + t E) lie against the ends
/// t_lo, t_hi of the multipliers' intervals (and, for an ellipsoid Q, r3, the largest root of D).
enum class QuadricRule : unsigned char {
  OddRootAboveLo,   ///< E: a root of odd multiplicity in (t_lo, oo)
  EvenRootAboveLo,  ///< TE: a root in (t_lo, oo), each of even multiplicity
  EndpointLo,       ///< TE: f~ = f / gcd(f, D) vanishes at t_lo (the hard case)
  OddRootBelowHi,   ///< I: a root of odd multiplicity in (-oo, t_hi)
  EvenRootBelowHi,  ///< TI: a root in (-oo, t_hi), each of even multiplicity
  EndpointHi,       ///< TI: f~ vanishes at t_hi (the hard case)
  OddRootInner,     ///< O: a root of odd multiplicity in (r3, 0)
  EvenRootInner,    ///< TO: a root in (r3, 0), each of even multiplicity
  EndpointInner,    ///< TO: f~ vanishes at r3 (the hard case)
  Equal,            ///< EQ: TI and TO at once (Q a positive multiple of E)
  NoRoot,           ///< C: none of the above
};
/// The rule in one sentence.
std::string describe(QuadricRule r);

/// The answer without evidence: what the hot path computes.
struct QuadricVerdict {
  QuadricPosition position = QuadricPosition::C;
  QuadricRule rule = QuadricRule::NoRoot;
  QuadricType type = QuadricType::Ellipsoid;  ///< the second body's type
  QuadricStage stage = QuadricStage::Filter;
};

/// Adaptive exact verdict: the certified double filter, then exact integers.
QuadricVerdict decide_position(const Ellipsoid& e, const Quadric& q);
/// The same without the filter (reference path for tests and benchmarks).
QuadricVerdict decide_position_exact(const Ellipsoid& e, const Quadric& q);

/// One distinct real root of f or of D.
struct PencilRoot {
  Rational lower, upper;          ///< isolating interval of the root (in the t of the stored matrices)
  std::optional<Rational> exact;  ///< the root when it is rational
  int multiplicity_f = 0;         ///< as a root of f
  int multiplicity_d = 0;         ///< as a root of D
};

/// The verdict with its exact evidence and certificate.
struct QuadricClassification {
  QuadricVerdict verdict;
  std::array<Rational, 5> f;       ///< det(Q + t E) for the stored matrices, index = power of t
  std::array<Rational, 4> d;       ///< det(B + t M)
  std::vector<PencilRoot> roots;   ///< the distinct real roots of f and of D, increasing
  QuadricCertificate certificate;  ///< checked by verify_certificate
};

/// Exact classification with evidence and certificate.
QuadricClassification classify(const Ellipsoid& e, const Quadric& q);

}  // namespace relpos
