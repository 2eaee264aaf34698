#include "filters/static_filter_lanes.hpp"

#include <array>
#include <cfloat>
#include <cstring>
#include <optional>
#include <utility>

#include "algebra/pencil.hpp"
#include "algebra/shape_filter.hpp"
#include "algebra/smallness.hpp"
#include "anysize/gap.hpp"
#include "filters/lane_double.hpp"
#include "filters/load_time_copies.hpp"

namespace relpos::detail {
namespace {

using Bounds = StaticFilterBounds;

/// A valid pair, normalized and sign-normalized: what a lane that cannot be taken computes instead of
/// its own input (no NaN, infinity or subnormal to slow the block down). The sphere of radius 1
/// centred at (0, 0, 1/2) and z = x^2 + y^2, each matrix scaled by 1/2.
constexpr double kQuietEllipsoid[16] = {0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, -0.25, 0, 0, -0.25, -0.375};
constexpr double kQuietParaboloid[16] = {0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0, -0.25, 0, 0, -0.25, 0};

/// The gap test's answer for a lane (PairBlockSigns::gap) from the route's bits and the certified
/// signs of the gap quantities (bit i of gap_positive / gap_negative: quantity i of
/// GapQuantities::flatten), as the scalar route takes it: only where the signs leave it open (four
/// distinct negative roots and rho > 1), -1 elsewhere or when a sign it needs is uncertain.
signed char gap_answer(const DiscriminantSignBits& bits, unsigned gap_positive, unsigned gap_negative) {
  if (bits.discriminant_case() != DiscriminantCase::AllNegative || bits.rho_vs_one() != 1) return -1;
  std::optional<int> signs[anysize::kGapSigns];
  for (int i = 0; i < anysize::kGapSigns; ++i) {
    if ((gap_positive >> i) & 1) signs[i] = 1;
    if ((gap_negative >> i) & 1) signs[i] = -1;
  }
  const std::optional<bool> above = anysize::roots_above_lambda_s(signs);
  return above ? static_cast<signed char>(*above) : -1;
}

// The route, once per copy: each inside its own namespace and, but for the baseline one, its own
// target region, so that all of its code is compiled for that ISA (lane_double.hpp says why). The
// generic formulas it instantiates are defined outside, for the baseline ISA: they hold only
// arithmetic, which GCC compiles for the ISA of the function it is inlined into.
namespace baseline {
#include "filters/static_filter_lanes_route.inc"
}  // namespace baseline

[[gnu::flatten]] void lanes_baseline(const PairBlock& block, PairInput input, PairBlockSigns& out) {
  const Bounds& b = static_filter_bounds();
  for (int first = 0; first < kPairLanes; first += 4) baseline::Route<4>::run(block, first, input, b, out);
}

}  // namespace

#if RELPOS_AVX2_COPY

namespace {

#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#include "filters/static_filter_lanes_route.inc"
}  // namespace avx2

[[gnu::flatten]] void lanes_avx2(const PairBlock& block, PairInput input, PairBlockSigns& out) {
  const Bounds& b = static_filter_bounds();
  for (int first = 0; first < kPairLanes; first += 4) avx2::Route<4>::run(block, first, input, b, out);
}
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq")
namespace avx512 {
#include "filters/static_filter_lanes_route.inc"
}  // namespace avx512

[[gnu::flatten]] void lanes_avx512(const PairBlock& block, PairInput input, PairBlockSigns& out) {
  avx512::Route<8>::run(block, 0, input, static_filter_bounds(), out);
}
#pragma GCC pop_options

}  // namespace

using LanesFunction = void(const PairBlock&, PairInput, PairBlockSigns&);

// C linkage: the ifunc attribute names its resolver by the assembler name. Not instrumented, as
// cpu_has_avx2() (load_time_copies.hpp).
extern "C" {
[[gnu::no_sanitize_address, gnu::no_sanitize_undefined, gnu::no_instrument_function]] static LanesFunction*
relpos_resolve_static_filter_lanes() {
  if (cpu_has_avx512f()) return lanes_avx512;
  return cpu_has_avx2() ? lanes_avx2 : lanes_baseline;
}
}

void static_filter_lanes(const PairBlock& block, PairInput input, PairBlockSigns& out)
    __attribute__((ifunc("relpos_resolve_static_filter_lanes")));
#else
void static_filter_lanes(const PairBlock& block, PairInput input, PairBlockSigns& out) {
  lanes_baseline(block, input, out);
}
#endif

bool static_filter_lanes_copy_runs(FilterCopy copy) {
#if RELPOS_AVX2_COPY
  if (copy == FilterCopy::avx2) return cpu_has_avx2();
  if (copy == FilterCopy::avx512) return cpu_has_avx512f();
#endif
  return copy == FilterCopy::baseline;
}

void static_filter_lanes_copy(FilterCopy copy, const PairBlock& block, PairInput input, PairBlockSigns& out) {
#if RELPOS_AVX2_COPY
  if (copy == FilterCopy::avx2) return lanes_avx2(block, input, out);
  if (copy == FilterCopy::avx512) return lanes_avx512(block, input, out);
#endif
  (void)copy;
  lanes_baseline(block, input, out);
}

}  // namespace relpos::detail
