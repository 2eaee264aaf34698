// The relative position of an ellipsoid and an elliptic paraboloid (math.md §3–§6; paper
// Theorem 1 with the corrections of math.md §3), decided exactly, with its evidence.
//
// Every decision is the sign of a polynomial in the input entries (math.md §4). classify()
// evaluates them first in doubles with static error bounds (static_filter.hpp). When that leaves Disc(f)
// uncertain on exact-double input it looks for a witness of Disc(f) = 0 -- exact rational multiple roots -- on
// machine integers (multiple_roots.hpp). Then interval arithmetic certifies what it can; only the signs no filter
// can certify (exact zeros: tangencies, special roots, rho = 1) go to exact GMP integers, and only Disc(f) = 0 or a
// defective Sturm-Habicht sequence goes to exact factorisation (roots.hpp). classify_exact() skips the filter; the two
// return identical positions on every input.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "relpos/error.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/position.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

/// What settled the answer, in the order the stages run: the scene's certified early-outs (scene.hpp)
/// first, then the contact-only discriminant test (contact.hpp), then the classifier's cascade
/// (decide_position). One enum for pairs, scenes and contact-only answers.
enum class Stage : unsigned char {
  InsideCertificate,    ///< scene early-out: P < 0 on the solid ellipsoid (I, for a small ellipsoid)
  OutsideCertificate,   ///< scene early-out: P > 0 on the solid ellipsoid (E)
  DiscriminantFilter,   ///< contact only: signs of f and Disc(f) in doubles (+ smallness when needed)
  StaticDouble,         ///< double arithmetic with static error bounds (inputs that are exact doubles)
  SemiStaticDouble,     ///< double arithmetic with error bounds from the operands' magnitudes
  MultipleRootWitness,  ///< Disc(f) = 0 certified by exact rational multiple roots, machine integers
  Interval,             ///< all signs certified by interval arithmetic
  ExactSigns,           ///< exact integer signs of the same polynomials
  ExactRoots,           ///< exact gcd / square-free factorisation (Disc(f) = 0 or defective sequence)
};
/// Every stage, in order (tables indexed by Stage take their size from here).
inline constexpr std::array kAllStages{Stage::InsideCertificate, Stage::OutsideCertificate, Stage::DiscriminantFilter,
                                       Stage::StaticDouble,      Stage::SemiStaticDouble,   Stage::MultipleRootWitness,
                                       Stage::Interval,          Stage::ExactSigns,         Stage::ExactRoots};
/// "inside-certificate", "outside-certificate", "discriminant-filter", "static-double", "semi-static-double",
/// "multiple-root-witness", "interval", "exact-signs", "exact-roots".
std::string to_string(Stage s);

/// The rule that decided (describe() gives the sentence).
enum class Rule : unsigned char {
  None,
  NonRealPairCrossing,   ///< C: a non-real pair, f~ square-free
  NegativeMultipleRoot,  ///< TI: f~ has a negative multiple root, all roots real and negative
  PositiveMultipleRoot,  ///< TE: f~ has a positive multiple root (any size)
  AllRootsNegative,      ///< I: f~ square-free, all roots real and negative
  TwoPositiveRoots,      ///< E: two distinct positive roots (any size)
  RootsAboveLambdaS,     ///< I: f square-free, roots real, none positive, two in (lambda_s, 0) (any size)
  NoRootAboveLambdaS,    ///< C: f square-free, roots real, none above lambda_s (any size)
  OddPositiveRoot,       ///< E: a root of odd multiplicity in (0, oo) (math.md §8 rule 1)
  EvenPositiveRoot,      ///< TE: a positive root, every one of even multiplicity (math.md §8 rule 2)
  OddGapRoot,            ///< I: a root of odd multiplicity in (lambda_s, 0) (math.md §8 rule 3)
  EvenGapRoot,           ///< TI: f~ has a multiple root in (lambda_s, 0) (math.md §8 rule 4)
  HardCase,              ///< TI: f~ vanishes at lambda_s, the hard case (math.md §8 rule 4)
  NoRootInGap,           ///< C: no positive root and f~ has no root in [lambda_s, 0) (math.md §8 rule 5)
};
std::string describe(Rule r);

/// The answer without the evidence strings and exact coefficients: what the hot path computes.
/// No heap allocation unless an exact stage runs.
struct Verdict {
  Position position = Position::C;  ///< meaningful once rule != Rule::None (every returned verdict)
  Stage stage = Stage::StaticDouble;
  Rule rule = Rule::None;
  bool small = false;
  signed char rho_vs_one = 0;
  signed char sign_disc_f = 0, sign_disc_ftilde = 0;
  signed char real_roots = 0, negative_roots = 0, positive_roots = 0, nonreal_roots = 0;
  signed char tangent_negative = 0, tangent_positive = 0, nonreal_multiple = 0;
  /// Whether f has roots in (lambda_s, 0) (math.md §8): 1 yes, 0 no, -1 not computed (only
  /// pairs that are not small with four real negative roots need it).
  signed char roots_above_lambda_s = -1;
};

/// Adaptive exact verdict (static double filter, intervals, exact integers, exact roots).
/// Throws InputError for a pair beyond the size limit (SizeLimit, quadric.hpp),
/// as classify() and classify_exact() do.
Verdict decide_position(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit = {});

/// decide_position(Ellipsoid::from_doubles(e), Paraboloid::from_doubles(p)) in one call (row-major
/// 4x4 doubles, each taken exactly): the same verdict, and the same InputError for an invalid
/// matrix (the ellipsoid's first). Cheaper: the validation's last signs, det E < 0 and det P < 0,
/// are f(0) and the leading coefficient of f (math.md §2), which the decision certifies anyway;
/// when they or any other sign stay uncertain, it runs the two steps.
Verdict decide_position(const DoubleMatrix4& e, const DoubleMatrix4& p);

/// What decide_positions() did with one pair.
enum class PairStatus : unsigned char {
  Decided,            ///< its position (and stage) are decide_position()'s for the pair
  InvalidEllipsoid,   ///< decide_position() throws InputError for the pair's ellipsoid
  InvalidParaboloid,  ///< decide_position() throws InputError for the pair's paraboloid (its ellipsoid is valid)
  TooLarge,           ///< decide_position() throws InputError: the pair is beyond the size limit
};

/// decide_position() on many pairs at once (math.md §11, "Many pairs at once"): `e` and `p` hold n
/// row-major 4x4 matrices of doubles each (16 n doubles apiece, pair i at e + 16 i and p + 16 i: a
/// C-ordered array of shape (n, 4, 4)), every entry taken exactly. For every pair, status[i] is
/// Decided and positions[i] (and stages[i], when `stages` is not null) are those of
/// decide_position(e_i, p_i); or, where decide_position would throw InputError, status[i] says which
/// matrix is invalid (the ellipsoid's error first, as decide_position; its message is the one
/// decide_position throws for that pair) and positions[i], stages[i] are not written. Returns the
/// number of pairs not decided. One thread; pairs are independent, so callers may split the arrays
/// between threads.
///
/// The static filter's discriminant route runs on blocks of pairs, one pair per lane of a vector
/// (AVX-512 or AVX2 where the CPU has it: the copy is chosen when the library is loaded), together
/// with the input checks of decide_position on doubles; a pair whose signs it cannot all certify goes
/// to decide_position itself.
std::size_t decide_positions(const double* e, const double* p, std::size_t n, Position* positions, PairStatus* status,
                             Stage* stages = nullptr);

/// The same for quadrics already built: positions[i] = decide_position(e[i], p[i]).position, status[i]
/// TooLarge where that throws (the size limit, SizeLimit).
std::size_t decide_positions(const Ellipsoid* e, const Paraboloid* p, std::size_t n, Position* positions,
                             PairStatus* status, Stage* stages = nullptr);

/// The same for n ellipsoids against one paraboloid: decide_position(e[i], p).
std::size_t decide_positions(const Ellipsoid* e, std::size_t n, const Paraboloid& p, Position* positions,
                             PairStatus* status, Stage* stages = nullptr);

/// How much evidence to assemble. Minimal is what the fast path needs; Full adds the exact
/// coefficients of f and s, deg f~, the multiple roots and rho itself.
enum class Evidence { Minimal, Full };

/// The verdict with its evidence: what classify() returns and the reports render. Its numbers are
/// CGAL::Gmpq handles, which share their value with the handles they were copied from; the ones a
/// result leaves at their defaults share the library's default zeros. Assign a new value to change
/// one; never write through mpq() in place (that would change every number sharing it).
struct Classification {
  Verdict verdict;  ///< position, stage, rule, smallness, contact and the root counts (the one copy)
  /// The rule that decided, in one sentence (describe(verdict.rule)).
  std::string rule_text() const { return describe(verdict.rule); }

  // Full evidence (Evidence::Full).
  bool has_full_evidence = false;
  Quartic<Rational> f;          ///< det(lambda P + E) for the sign-normalized matrices
  Quadratic<Rational> s;        ///< det(lambda A + M)
  int degree_ftilde = 4;        ///< degree of f~ = f / gcd(f, s)
  std::vector<RealRoot> roots;  ///< distinct real roots of f with multiplicities (Full only)
  std::optional<Rational> rho;  ///< rho exactly, when it is rational
  double rho_approx = 0;        ///< rho to double precision: the nearest double when rho is rational
  /// Evidence anyone can check with rational arithmetic (position.hpp; Evidence::Full only).
  Certificate certificate;
};

/// Adaptive exact classification (interval filter, then exact integers). `limit`: the pair size
/// limit (quadric.hpp), a safe default that a caller can raise.
Classification classify(const Ellipsoid& e, const Paraboloid& p, Evidence evidence = Evidence::Full,
                        const SizeLimit& limit = {});

/// Exact classification without the filter (reference path for tests and benchmarks).
Classification classify_exact(const Ellipsoid& e, const Paraboloid& p, Evidence evidence = Evidence::Full,
                              const SizeLimit& limit = {});

}  // namespace relpos
