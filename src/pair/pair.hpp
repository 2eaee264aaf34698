// One home for the data of a pair (doc/architecture.md, "One home for a pair"): the quadrics'
// approximations, always there, and every exact value the ladder, the evidence and the certificate
// read -- the intervals, the compact integer pencil, the reported f and s with their integer
// multiples, the integer forms with their scales, lambda_s, the isolated roots -- each built once,
// on first use (CGAL's Lazy: the approximation always at hand, the exact value built on demand;
// math.md §11). A PairContext lives for one call on one thread: what the ladder finds exact once,
// the evidence and the certificate read again without recomputing it.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "algebra/double_sign.hpp"
#include "algebra/forms.hpp"
#include "algebra/recycled.hpp"
#include "algebra/roots.hpp"
#include "anysize/exact.hpp"
#include "pair/compact_pencil.hpp"
#include "pair/evidence_pencil.hpp"
#include "pair/integer_poly.hpp"
#include "pair/point_form.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// The entries of both matrices as intervals (the interval stage), scaled by powers of two.
struct IntervalEntries {
  forms::MatrixOf<forms::Interval> p, e;
};

/// Certified double enclosures of both matrices' entries (the semi-static stage on entries that are
/// not doubles).
struct Enclosures {
  EnclosureMatrix4 p, e;
};

/// The integer forms Ez = le E and Pz = lp P with their scales (forms::integer_form), as Integers.
struct IntegerForms {
  forms::MatrixOf<Integer> ez, pz;
  Integer le, lp;
};

/// What a PairContext builds on first use, in one place: the hot path constructs and destroys an
/// empty optional only.
struct PairCold {
  int sign_disc_f = 0;
  bool certificate_reads_forms = true;
  std::optional<IntervalEntries> intervals;
  std::optional<Enclosures> enclosures;
  std::optional<CompactPencil> compact;
  std::optional<Recycled<EvidenceScratch>> scratch;
  std::optional<EvidencePencil> evidence;
  std::optional<RootStructure> roots;
  std::optional<IntegerForms> forms;
  std::optional<PointForm> e_point, p_point;
  std::optional<anysize::Poly> f_poly, s_poly;
  std::optional<IntegerPoly> fz, f_multiple;
  std::optional<DoubleSign> f_at_doubles;  // reads f_multiple in place: declared after it
};

class PairContext {
 public:
  PairContext(const Ellipsoid& e, const Paraboloid& p) : e_(e), p_(p) {}
  PairContext(const PairContext&) = delete;
  PairContext& operator=(const PairContext&) = delete;

  const Ellipsoid& ellipsoid() const { return e_; }
  const Paraboloid& paraboloid() const { return p_; }

  // ---- The approximations, always there: the quadrics' own storage (no computation). ----
  const QuadricMatrix& e_storage() const { return storage_of(e_); }
  const QuadricMatrix& p_storage() const { return storage_of(p_); }
  /// Whether every entry of both matrices is a double.
  bool both_doubles() const { return e_storage().has_doubles() && p_storage().has_doubles(); }
  /// Whether either quadric was read from decimal text (its entries known by enclosures).
  bool any_enclosure() const { return e_storage().enclosure() || p_storage().enclosure(); }

  // ---- The ladder's values, built once, on first use. ----
  /// The entries as intervals: from the doubles, the stored enclosures, else the rationals. Call with
  /// the rounding mode towards +inf (CGAL::Protect_FPU_rounding<true>).
  const IntervalEntries& intervals() const;
  /// The entries' enclosures: the stored ones, degenerate ones of doubles, else certified ones of the
  /// rationals.
  const Enclosures& enclosures() const;
  /// f and s in the compact integer form (exact signs and multiplicities only).
  const CompactPencil& compact() const;

  // ---- The evidence's values (the certificate reads them too). ----
  /// What the decision knows that the evidence reuses: the certified sign of Disc(f) (0: unknown),
  /// and whether the certificate will read the integer forms (C, TE, TI). Before the evidence is built.
  void expect(int sign_disc_f, bool certificate_reads_forms) {
    cold().sign_disc_f = sign_disc_f;
    cold().certificate_reads_forms = certificate_reads_forms;
  }
  /// The reported f and s, S^4 f and S^3 s, lambda_s (and rho from closed forms).
  const EvidencePencil& evidence() const;
  const Quartic<Integer>& f_multiple() const {
    evidence();
    return (*cold().scratch)->f_multiple;
  }
  const Quadratic<Integer>& s_multiple() const {
    evidence();
    return (*cold().scratch)->s_multiple;
  }
  const anysize::LambdaS& lambda_s() const { return evidence().lambda_s; }
  /// The real roots of f with multiplicities and isolating intervals (exact_root_structure on S^4 f).
  const RootStructure& roots() const;
  /// The reported f and s and the root structure, moved into the caller's (after the last read).
  void move_evidence(Quartic<Rational>& f, Quadratic<Rational>& s, RootStructure& roots);

  // ---- The certificate's values. ----
  /// The entries as doubles for the certificate's searches (CGAL::to_double of each): the quadric's
  /// own doubles, those its exact source writes from the numbers read, else the rationals truncated.
  DoubleMatrix4 e_search_doubles() const;
  DoubleMatrix4 p_search_doubles() const;
  /// The integer forms with their scales: the evidence's when it wrote them, else from the doubles or
  /// the rationals.
  const IntegerForms& integer_forms() const;
  /// Exact signs of e and p at rational points: on the evidence's integer forms, else on the
  /// doubles', else on integer_forms().
  const PointForm& e_point_form() const;
  const PointForm& p_point_form() const;
  /// f and s as polynomials over Q.
  const anysize::Poly& f_poly() const;
  const anysize::Poly& s_poly() const;
  /// f times the lcm of its denominators (its size sets the searches' budgets).
  const IntegerPoly& fz() const;
  /// sign f(x), on S^4 f: at a double by floating-point stages that answer only when certain
  /// (DoubleSign), else exactly.
  int f_sign(const Rational& x) const;

 private:
  using Cold = PairCold;
  Cold& cold() const;
  const Ellipsoid& e_;
  const Paraboloid& p_;
  mutable std::optional<Cold> cold_;
};

inline PairContext::Cold& PairContext::cold() const {
  if (!cold_) cold_.emplace();
  return *cold_;
}

}  // namespace relpos::detail
