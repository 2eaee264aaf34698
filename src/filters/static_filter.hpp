// Stage 1 of classify(): the decision signs in plain double arithmetic, certified by static error
// bounds (the CGAL static-filter / Shewchuk "fast" stage; math.md §11).
//
// Both matrices must hold exact doubles (Ellipsoid::doubles(), Paraboloid::doubles()). Each matrix
// is scaled by a power of two so its largest entry lies in [1/2, 1) -- exact, and a positive scaling
// changes no decision -- then f and s are evaluated by the same generic code as every other stage.
// Their error bounds are not typed in: they are derived at start-up by running that generic code on
// CGAL's Static_filter_error number type (bound and error propagation for |entries| <= 1). The
// quartic is then balanced by lambda -> 2^b mu (exact), f and s are scaled by powers of two into
// [-1, 1], and the Sturm-Habicht and smallness quantities get the bound A + R * eps, where eps is the
// coefficient error and A, R are again derived from the same formulas on Static_filter_error
// (sound for eps <= eps0 because the propagated error is a polynomial in eps with non-negative
// coefficients). A sign is certain only when |value| exceeds its bound; everything else is left
// uncertain for the interval and exact stages. Compile with -frounding-math and no FP contraction.
#pragma once

#include <array>
#include <optional>

#include "algebra/sturm.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

/// Certified signs from double arithmetic; uncertain where the static bound does not separate the
/// value from zero (or the input is out of the filter's range).
DecisionSigns static_filter_signs(const DoubleMatrix4& p, const DoubleMatrix4& e);

/// The same for matrices already normalized by power_of_two_normalized() (quadric.hpp), e.g.
/// storage_of(ellipsoid).filter_doubles(): the hot path of classify().
DecisionSigns static_filter_signs_normalized(const DoubleMatrix4& p, const DoubleMatrix4& e);

/// Only what the discriminant decision (discriminant_case, algebra/sturm.hpp) reads: the signs of
/// f's coefficients and of Disc(f) (quartic.f and quartic.g0, the latter from the invariants; g2 and
/// g1 stay uncertain -- they are never computed). The
/// smallness signs (vertex, graeffe) are computed only when `need_smallness` is non-null and returns
/// true on those signs (the caller's decision says whether its answer depends on rho); otherwise they
/// stay uncertain. Same input as static_filter_signs_normalized(); the bounds are derived once from
/// the same formulas (discriminant_times_27, SmallnessQuantities).
///
/// When `gap` is non-null and the signs leave only the gap test of math.md §8 open (Disc(f) > 0, no
/// sign change: four distinct negative roots; rho > 1), the gap test runs on the same f and s with
/// bounds derived the same way (anysize/gap.hpp): *gap is set to its answer, or left alone when a
/// sign it needs is uncertain.
DecisionSigns static_filter_discriminant_signs_normalized(const DoubleMatrix4& p, const DoubleMatrix4& e,
                                                          bool (*need_smallness)(const QuarticSigns&) = nullptr,
                                                          std::optional<bool>* gap = nullptr);

/// The signs of the discriminant route as two bit masks: bit i of `positive` (`negative`) is set
/// when quantity i is certified positive (negative), neither when it is uncertain. Quantities in
/// the order f0..f4, 27 Disc(f), vertex, graeffe. The hot path of classify() reads them without
/// unpacking (two small tables, generated from discriminant_case and compare_rho_with_one).
struct DiscriminantSignBits {
  unsigned positive = 0, negative = 0;
  static constexpr int kDisc = 5, kVertex = 6, kGraeffe = 7;
  DecisionSigns signs() const;                 ///< unpacked (g2, g1 uncertain)
  DiscriminantCase discriminant_case() const;  ///< = relpos::discriminant_case(signs().quartic)
  /// compare_rho_with_one(signs().vertex, signs().graeffe) as -1, 0, 1, or 2 when uncertain (a plain
  /// int: an optional returned through memory stalls the hot path on store forwarding).
  int rho_vs_one() const;
  /// The bits discriminant_case() and rho_vs_one() read, as indices into their tables
  /// (detail::discriminant_case_table(), detail::rho_vs_one_table()); of masks of any integer type
  /// (the many-pairs filter forms them lane by lane).
  template <class B>
  static B case_index_of(const B& positive, const B& negative) {
    return (positive & 0x3f) | (negative & 0x3f) << 6;
  }
  template <class B>
  static B rho_index_of(const B& positive, const B& negative) {
    return (positive >> kVertex & 3) | (negative >> kVertex & 3) << 2;
  }
  unsigned case_index() const { return case_index_of(positive, negative); }
  unsigned rho_index() const { return rho_index_of(positive, negative); }
};

namespace detail {
/// The tables behind DiscriminantSignBits, indexed by the bits of f0..f4 and 27 Disc(f) (6 positive,
/// then 6 negative ones) and by those of vertex and graeffe (2 positive, then 2 negative ones).
const std::array<DiscriminantCase, 1 << 12>& discriminant_case_table();
const std::array<signed char, 16>& rho_vs_one_table();
}  // namespace detail

// Inline: called for every pair, between the filter's arithmetic and the decision.
inline DiscriminantCase DiscriminantSignBits::discriminant_case() const {
  static const auto& table = detail::discriminant_case_table();
  return table[case_index()];
}
inline int DiscriminantSignBits::rho_vs_one() const {
  static const auto& table = detail::rho_vs_one_table();
  return table[rho_index()];
}

/// static_filter_discriminant_signs_normalized() with smallness always computed, as bits.
DiscriminantSignBits static_filter_discriminant_bits_normalized(const DoubleMatrix4& p, const DoubleMatrix4& e,
                                                                std::optional<bool>* gap);

namespace detail {
/// The largest coefficient error (for coefficients scaled into [-1, 1]) the second-stage bounds
/// below are derived for.
inline constexpr double kStaticFilterEps0 = 0x1p-20;

/// The static filter's error-bound constants, derived once at start-up from the generic formulas on
/// Static_filter_error (static_filter.cpp): f[i], s[i] bound the absolute errors of f_i, s_i for
/// entries in [-1, 1]; quantity q, evaluated on coefficients with error at most eps <=
/// kStaticFilterEps0, has error at most a[q] + r[q] eps (q: g2[0..2], g1[0..1], g0, vertex, graeffe,
/// 27 Disc(f), then the gap test's quantities in GapQuantities::flatten order). Shared with the
/// many-pairs filter (static_filter_lanes.hpp), which evaluates the same formulas in lanes.
struct StaticFilterBounds {
  static constexpr int kVertex = 6, kGraeffe = 7, kDisc27 = 8, kGap = 9;
  double f[5], s[3];
  double a[19], r[19];
};
const StaticFilterBounds& static_filter_bounds();

/// `bound` with the slack of a certified sign: the bound's own rounding and underflow, whose absolute
/// error is below 2^-1074 per operation (a double or lanes, each rounded alike). A sign is certain
/// when |value| exceeds it.
template <class T>
[[gnu::always_inline]] inline T with_slack(T bound) {
  return bound * (1 + 0x1p-40) + 1e-300;
}

/// The copies of static_filter_discriminant_bits_normalized() the build holds: the baseline one
/// everywhere, an AVX2 one on x86-64 with GCC (the same source and IEEE operations; one of them is
/// chosen when the library is loaded). For tests, which must run both to see they agree. The
/// many-pairs filter (static_filter_lanes.hpp) has an AVX-512 copy too.
enum class FilterCopy { baseline, avx2, avx512 };
/// True when `copy` is built and this CPU can run it.
bool static_filter_copy_runs(FilterCopy copy);
/// static_filter_discriminant_bits_normalized() computed by `copy`; requires
/// static_filter_copy_runs(copy).
DiscriminantSignBits static_filter_discriminant_bits_copy(FilterCopy copy, const DoubleMatrix4& p,
                                                          const DoubleMatrix4& e, std::optional<bool>* gap);
}  // namespace detail

}  // namespace relpos
