// f and s of a pair in the compact integer form (math.md §11, forms::to_compact_integers): the roots
// scaled by one positive constant, so only sign and multiplicity facts may be read from them -- what
// the exact stages of the ladder read (exact signs, the exact gap test, exact roots). On PooledInteger:
// no heap traffic for the temporaries of the generic formulas.
#pragma once

#include <optional>

#include "algebra/sturm.hpp"
#include "filters/pooled_integer.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

class CompactPencil {
 public:
  CompactPencil(const Matrix4& p, const Matrix4& e);
  CompactPencil(const CompactPencil&) = delete;
  CompactPencil& operator=(const CompactPencil&) = delete;

  const Quartic<PooledInteger>& f() const { return f_; }
  const Quadratic<PooledInteger>& s() const { return s_; }
  /// 27 Disc(f), on first use (sturm_habicht() takes it over: asked again after it, recomputed).
  const PooledInteger& discriminant_times_27() const;
  /// f's Sturm-Habicht sequence (sturm.hpp), on first use; its g0 is Disc(f), from discriminant_times_27().
  const SturmHabicht<PooledInteger>& sturm_habicht() const;
  /// f and s as Integer (the factorisation stage's type).
  Quartic<Integer> f_integer() const;
  Quadratic<Integer> s_integer() const;

 private:
  Quartic<PooledInteger> f_;
  Quadratic<PooledInteger> s_;
  mutable std::optional<PooledInteger> disc27_;  // built on first use, as the pair's other values
  mutable std::optional<SturmHabicht<PooledInteger>> sturm_habicht_;
};

}  // namespace relpos::detail
