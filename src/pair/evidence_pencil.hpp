// The reported pencil of a pair (the full evidence, math.md §2 and §8): f = det(lambda P + E) and
// s = det(lambda A + M) reduced, their common-lcm integer multiples S^4 f and S^3 s (the root
// isolation and the certificate's exact signs), lambda_s, and rho when closed forms give it --
// computed from each matrix's own integer form (Pz = lp P, Ez = le E; doc/architecture.md, "One batch
// line"), or for a sphere and a standard paraboloid read from decimal text from their
// closed forms (forms::sphere_standard_evidence).
#pragma once

#include <cstdint>
#include <optional>

#include "algebra/forms.hpp"
#include "anysize/exact.hpp"
#include "filters/pooled_integer.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// The integers one pair's evidence writes in place, kept from pair to pair (recycled.hpp): their
/// limbs are warm, and nothing in them is copied into a result.
struct EvidenceScratch {
  forms::MatrixOf<PooledInteger> pz, ez;  ///< the integer forms Pz = lp P, Ez = le E, when not in words
  forms::MatrixOf<std::int64_t> pw, ew;   ///< the same in machine words (doubles whose forms fit)
  Quartic<Integer> f_multiple;            ///< S^4 f, S = lcm(lp, le)
  Quadratic<Integer> s_multiple;          ///< S^3 s
  Integer lp, le;                         ///< the forms' scales (not in words)
  forms::SplitScale sp, se;               ///< their splits
  const forms::SplitScale unit{};         ///< the split of 1, copied into sp and se (never written)
};

/// One pair's reported pencil; scratch's f_multiple and s_multiple hold S^4 f and S^3 s, and its
/// forms what `words` and `forms_written` say.
struct EvidencePencil {
  /// `certificate_reads_forms`: whether the certificate will read the integer forms (the points of
  /// C, TE and TI do, the multipliers of E and I do not); when the closed forms give the evidence
  /// and it will not, only the scales' exponents are written.
  EvidencePencil(const Ellipsoid& e, const Paraboloid& p, bool certificate_reads_forms, EvidenceScratch& scratch);
  EvidencePencil(const EvidencePencil&) = delete;
  EvidencePencil& operator=(const EvidencePencil&) = delete;

  Quartic<Rational> f;              ///< det(lambda P + E), reduced
  Quadratic<Rational> s;            ///< det(lambda A + M), reduced
  std::optional<Rational> rho;      ///< rho when the closed forms gave it (else the caller's, from f, s, lambda_s)
  bool words = false;               ///< the integer forms in scratch.pw, ew (machine words), not in pz, ez
  bool forms_written = false;       ///< scratch.pz, ez hold the integer forms and lp, le their scales
  const anysize::LambdaS lambda_s;  ///< the root of s nearest 0 (last: computed with everything above)

 private:
  anysize::LambdaS compute(const Ellipsoid& e, const Paraboloid& p, bool certificate_reads_forms,
                           EvidenceScratch& scratch);
  void write_integer_forms(const Ellipsoid& e, const Paraboloid& p, const std::optional<DoubleMatrix4>& pd,
                           const std::optional<DoubleMatrix4>& ed, bool closed, bool scales_only,
                           EvidenceScratch& scratch);
};

}  // namespace relpos::detail
