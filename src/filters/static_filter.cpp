#include "filters/static_filter.hpp"

#include <CGAL/Filtered_kernel/internal/Static_filters/Static_filter_error.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "algebra/double_bits.hpp"
#include "algebra/forms.hpp"
#include "algebra/smallness.hpp"
#include "anysize/gap.hpp"
#include "filters/load_time_copies.hpp"

namespace relpos {
namespace {

using Sfe = CGAL::internal::Static_filter_error;

template <class NT>
struct Mat {
  std::array<NT, 16> a;
  const NT& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

constexpr double kEps0 = detail::kStaticFilterEps0;

using Bounds = detail::StaticFilterBounds;

constexpr int kDisc27 = Bounds::kDisc27, kGap = Bounds::kGap, kSecondStage = kGap + detail::anysize::kGapSigns;
static_assert(kSecondStage == sizeof Bounds::a / sizeof(double), "one bound per second-stage quantity");

void second_stage(const Sfe& in, double out[kSecondStage]) {
  Quartic<Sfe> f;
  Quadratic<Sfe> s;
  for (auto& c : f) c = in;
  for (auto& c : s) c = in;
  SturmHabicht<Sfe> sh(f);
  SmallnessQuantities<Sfe> sq(f, s);
  const Sfe q[9] = {
      sh.g2[0], sh.g2[1], sh.g2[2], sh.g1[0], sh.g1[1], sh.g0[0], sq.vertex, sq.graeffe, discriminant_times_27(f)};
  for (int i = 0; i < 9; ++i) out[i] = q[i].error();
  Sfe gap[detail::anysize::kGapSigns];
  detail::anysize::GapQuantities<Sfe>(f, s).flatten(gap);
  for (int i = 0; i < detail::anysize::kGapSigns; ++i) out[kGap + i] = gap[i].error();
}

// noinline: computed once; kept out of the flattened hot functions below (it is large).
[[gnu::noinline]] const Bounds& bounds() {
  static const Bounds b = [] {
    Bounds r{};
    Mat<Sfe> one;
    for (auto& x : one.a) x = Sfe(1.0, 0.0, 1);
    const auto f = characteristic_polynomial<Sfe>(one, one);
    const auto s = special_polynomial<Sfe>(one, one);
    for (int i = 0; i < 5; ++i) r.f[i] = f[static_cast<std::size_t>(i)].error();
    for (int i = 0; i < 3; ++i) r.s[i] = s[static_cast<std::size_t>(i)].error();
    double exact_in[kSecondStage], noisy_in[kSecondStage];
    second_stage(Sfe(1.0, 0.0, 1), exact_in);
    second_stage(Sfe(1.0, kEps0, 1), noisy_in);
    for (int i = 0; i < kSecondStage; ++i) {
      r.a[i] = exact_in[i];
      r.r[i] = (noisy_in[i] - exact_in[i]) / kEps0 * (1 + 0x1p-30);  // round the ratio up
    }
    return r;
  }();
  return b;
}

using detail::with_slack;

/// Sign of v certified by |v| > bound (with slack for the rounding of the bound itself and for
/// underflow, whose absolute error is below 2^-1074 per operation).
/// Branch-free: the signs of random inputs are unpredictable, and 13 mispredicted branches per
/// pair cost as much as the arithmetic. Certain positive is [+, +], certain negative [-, -],
/// uncertain (also NaN) the interval [-, +].
USign certified(double v, double bound) {
  const double b = with_slack(bound);
  const int pos = v > b, neg = v < -b;
  return USign(static_cast<CGAL::Sign>(2 * pos - 1), static_cast<CGAL::Sign>(1 - 2 * neg));
}

using detail::exponent_of;
using detail::power_of_two;
inline bool normal_range(double x) { return x >= DBL_MIN && x <= DBL_MAX; }

/// The step 2^t of the balancing lambda = 2^t mu that makes |f4| 2^(4t) ~ |f0|, or 0 when f0 or f4
/// is out of the normal range.
double balancing_step(const Quartic<double>& f) {
  if (!normal_range(std::fabs(f[0])) || !normal_range(std::fabs(f[4]))) return 0;
  return power_of_two((exponent_of(f[0]) - exponent_of(f[4])) / 4);
}

/// Scale values and their error bounds by one power of two so that every |v| + err is below 1;
/// false if out of the normal range.
bool scale_into_unit(double* v, double* err, int n) {
  double mx = 0;
  for (int i = 0; i < n; ++i) mx = std::max(mx, std::fabs(v[i]) + err[i]);
  if (!normal_range(mx) || exponent_of(mx) >= 1022) return false;  // 2^-(e+1) must be normal
  const double scale = power_of_two(-exponent_of(mx) - 1);
  for (int i = 0; i < n; ++i) {
    v[i] *= scale;
    err[i] *= scale;
  }
  return true;
}

/// std::fabs and std::max in each lane.
inline detail::Lanes2 lanes_abs(detail::Lanes2 x) {
  typedef long long Bits2 __attribute__((vector_size(16)));
  return reinterpret_cast<detail::Lanes2>(reinterpret_cast<Bits2>(x) & Bits2{INT64_MAX, INT64_MAX});
}
inline detail::Lanes2 lanes_max(detail::Lanes2 x, detail::Lanes2 y) { return x < y ? y : x; }

/// The power of two scale_into_unit() multiplies by for the maximum mx, in both lanes, or 0 where
/// it returns false. Computed on the bits in the vector register (2^-(e+1) has the biased exponent
/// 2045 - (e + 1023)): a move to an integer register and back costs more than the arithmetic, and
/// the filter waits on this number. The range test is a branch, off that path.
detail::Lanes2 unit_scale(double mx) {
  if (!normal_range(mx) || exponent_of(mx) >= 1022) return detail::Lanes2{0.0, 0.0};
  typedef long long Bits2 __attribute__((vector_size(16)));
  constexpr long long kExponent = 0x7ffLL << 52, kScale = 2045LL << 52;
  const Bits2 e = reinterpret_cast<Bits2>(detail::Lanes2{mx, mx}) & Bits2{kExponent, kExponent};
  return reinterpret_cast<detail::Lanes2>(Bits2{kScale, kScale} - e);
}

/// Scale a matrix so its largest entry is in [1/2, 1); false if an entry would lose bits (subnormal)
/// or the input is not finite (detail::normalize_doubles, quadric_matrix.hpp).
bool normalize(const DoubleMatrix4& in, Mat<double>& out) {
  int exponent;
  bool plain;
  return detail::normalize_doubles(in, out.a, exponent, plain);
}

DecisionSigns uncertain() { return DecisionSigns{}; }

}  // namespace

const detail::StaticFilterBounds& detail::static_filter_bounds() { return bounds(); }

DecisionSigns static_filter_signs(const DoubleMatrix4& pin, const DoubleMatrix4& ein) {
  Mat<double> p, e;
  if (!normalize(pin, p) || !normalize(ein, e)) return uncertain();
  return static_filter_signs_normalized(p.a, e.a);
}

namespace {

using View = detail::forms::DoubleView;

}  // namespace

DecisionSigns static_filter_signs_normalized(const DoubleMatrix4& pn, const DoubleMatrix4& en) {
  const Bounds& b = bounds();
  const View p{pn}, e{en};
  auto f = characteristic_polynomial_lanes(pn, en);  // bit for bit the generic template
  auto s = special_polynomial<double>(p, e);
  double ef[5], es[3];
  for (int i = 0; i < 5; ++i) ef[i] = b.f[i];
  for (int i = 0; i < 3; ++i) es[i] = b.s[i];
  // Balance the quartic: lambda = 2^t mu with |f4| 2^(4t) ~ |f0|. f_i, s_i gain 2^(t i): exact.
  const double step = balancing_step(f);
  if (step == 0) return uncertain();
  double w = 1;
  for (int i = 0; i < 5; ++i, w *= step) {
    f[static_cast<std::size_t>(i)] *= w;
    ef[i] *= w;
    if (i < 3) {
      s[static_cast<std::size_t>(i)] *= w;
      es[i] *= w;
    }
  }
  // Bring f and s into [-1, 1] (separately: every quantity is homogeneous in f and in s).
  if (!scale_into_unit(f.data(), ef, 5) || !scale_into_unit(s.data(), es, 3)) return uncertain();

  DecisionSigns out;
  for (int i = 0; i < 5; ++i) out.quartic.f[i] = certified(f[static_cast<std::size_t>(i)], ef[i]);
  double eps = 0;
  for (int i = 0; i < 5; ++i) eps = std::max(eps, ef[i]);
  for (int i = 0; i < 3; ++i) eps = std::max(eps, es[i]);
  if (!(eps <= kEps0)) return out;  // coefficients too inaccurate for the second stage
  SturmHabicht<double> sh(f);
  SmallnessQuantities<double> sq(f, s);
  const double q[8] = {sh.g2[0], sh.g2[1], sh.g2[2], sh.g1[0], sh.g1[1], sh.g0[0], sq.vertex, sq.graeffe};
  USign c[8];
  for (int i = 0; i < 8; ++i) c[i] = certified(q[i], b.a[i] + b.r[i] * eps);
  out.quartic.g2[0] = c[0];
  out.quartic.g2[1] = c[1];
  out.quartic.g2[2] = c[2];
  out.quartic.g1[0] = c[3];
  out.quartic.g1[1] = c[4];
  out.quartic.g0 = c[5];
  out.vertex = c[6];
  out.graeffe = c[7];
  return out;
}

namespace {

/// Bit `bit` of bits.positive / bits.negative for the sign of v certified against `bound`
/// (certified() above, as two bits; branch-free for the same reason).
inline void certify_bit(DiscriminantSignBits& bits, int bit, double v, double bound) {
  const double b = with_slack(bound);
  bits.positive |= static_cast<unsigned>(v > b) << bit;
  bits.negative |= static_cast<unsigned>(v < -b) << bit;
}

using detail::Lanes2;

/// certify_bit() for bits `bit` and `bit` + 1 from the two lanes of v and bound: the same
/// comparisons in a quarter of the instructions.
inline void certify_bit_pair(DiscriminantSignBits& bits, int bit, Lanes2 v, Lanes2 bound) {
  typedef long long Mask2 __attribute__((vector_size(16)));
  const Lanes2 b = with_slack(bound);
  const Mask2 pos = v > b, neg = v < -b;
  bits.positive |= static_cast<unsigned>((pos[0] & 1) | (pos[1] & 2)) << bit;
  bits.negative |= static_cast<unsigned>((neg[0] & 1) | (neg[1] & 2)) << bit;
}

/// The powers of the balancing step and the largest scaled error: what the smallness half reads.
struct Balance {
  Lanes2 w01;
  double w2, eps;
};

/// discriminant_bits' first half: f balanced (lambda = 2^t mu) and scaled into [-1, 1] in place,
/// its five sign bits and Disc(f)'s certified. False when that is all (the scaling failed or eps
/// is beyond kEps0). The numbers of static_filter_signs_normalized()'s balancing and scaling, each
/// the same double, with shorter dependency chains and in lanes (the filter waits on them, not on
/// throughput):
/// - the powers w_i = step^i: step and step^2 are normal (|t| <= 511) and exact from their bits;
///   step^3 = step^2 step and step^4 = step^2 step^2 are each the exact power rounded once, as the
///   loop's products are (when 2^(3t) is out of range, 2^(4t) is beyond it on the same side);
/// - the largest y_i = |f_i w_i| + err_i w_i in any order: every y_i >= 0, and a NaN (f_i = 0,
///   w_i = inf) implies w_4 = inf, so y_4 = inf, taken last, makes the result inf or NaN, which
///   unit_scale() rejects as scale_into_unit() rejects the loop's inf;
/// - eps, the largest scaled error, as the largest error scaled (rounding is monotone).
template <class F>
[[gnu::always_inline]] inline bool balanced_f_bits(const Bounds& b, F& f, DiscriminantSignBits& out, Balance& bal) {
  if (!normal_range(std::fabs(f[0])) || !normal_range(std::fabs(f[4]))) return false;  // balancing_step() 0
  const int t = (exponent_of(f[0]) - exponent_of(f[4])) / 4;
  const double w1 = power_of_two(t), w2 = power_of_two(2 * t), w4 = w2 * w2;
  const Lanes2 w01 = {1.0, w1}, w23 = Lanes2{w2, w2} * w01;
  Lanes2 f01 = Lanes2{f[0], f[1]} * w01, f23 = Lanes2{f[2], f[3]} * w23;
  double f4 = f[4] * w4;
  Lanes2 e01 = Lanes2{b.f[0], b.f[1]} * w01, e23 = Lanes2{b.f[2], b.f[3]} * w23;
  double e4 = b.f[4] * w4;
  const Lanes2 y = lanes_max(lanes_abs(f01) + e01, lanes_abs(f23) + e23);
  const Lanes2 scale2 = unit_scale(std::max(std::max(y[0], y[1]), std::fabs(f4) + e4));
  const double scale = scale2[0];
  if (scale == 0) return false;
  const Lanes2 e = lanes_max(e01, e23);
  const double eps = std::max(std::max(e[0], e[1]), e4) * scale;
  f01 *= scale2;
  f23 *= scale2;
  f4 *= scale;
  e01 *= scale2;
  e23 *= scale2;
  e4 *= scale;
  certify_bit_pair(out, 0, f01, e01);
  certify_bit_pair(out, 2, f23, e23);
  certify_bit(out, 4, f4, e4);
  if (!(eps <= kEps0)) return false;
  f = {f01[0], f01[1], f23[0], f23[1], f4};
  // The same template as the bound was derived from: the same operations in the same order.
  certify_bit(out, DiscriminantSignBits::kDisc, discriminant_times_27(f), b.a[kDisc27] + b.r[kDisc27] * eps);
  bal = {w01, w2, eps};
  return true;
}

/// discriminant_bits' second half: s balanced and scaled as f was, the smallness bits, and the gap
/// test when the signs leave only it open (four distinct negative roots and rho > 1).
template <class F>
[[gnu::always_inline]] inline void smallness_bits(const Bounds& b, const DoubleMatrix4& pn, const DoubleMatrix4& en,
                                                  const F& f, const Balance& bal, DiscriminantSignBits& out,
                                                  std::optional<bool>* gap) {
  auto s = special_polynomial_lanes(pn, en);  // bit for bit the generic template
  Lanes2 s01 = Lanes2{s[0], s[1]} * bal.w01;
  double s2 = s[2] * bal.w2;
  const Lanes2 es01 = Lanes2{b.s[0], b.s[1]} * bal.w01;
  const double es2 = b.s[2] * bal.w2;
  const Lanes2 ys = lanes_abs(s01) + es01;
  const Lanes2 s_scale2 = unit_scale(std::max(std::max(ys[0], ys[1]), std::fabs(s2) + es2));
  const double s_scale = s_scale2[0];
  if (s_scale == 0) return;
  s01 *= s_scale2;
  s2 *= s_scale;
  s = {s01[0], s01[1], s2};
  const double eps = std::max(bal.eps, std::max(std::max(es01[0], es01[1]), es2) * s_scale);
  if (!(eps <= kEps0)) return;
  SmallnessQuantities<double> sq(f, s);
  certify_bit(out, DiscriminantSignBits::kVertex, sq.vertex, b.a[6] + b.r[6] * eps);
  certify_bit(out, DiscriminantSignBits::kGraeffe, sq.graeffe, b.a[7] + b.r[7] * eps);
  // One branch, rarely taken: `&` rather than `&&`, whose first test (the case) is unpredictable.
  if (gap && (static_cast<int>(out.discriminant_case() == DiscriminantCase::AllNegative) &
              static_cast<int>(out.rho_vs_one() == 1))) {
    double q[detail::anysize::kGapSigns];
    detail::anysize::GapQuantities<double>(f, s).flatten(q);
    std::optional<int> signs[detail::anysize::kGapSigns];
    for (int i = 0; i < detail::anysize::kGapSigns; ++i)
      signs[i] = detail::certain(certified(q[i], b.a[kGap + i] + b.r[kGap + i] * eps));
    *gap = detail::anysize::roots_above_lambda_s(signs);
  }
}

/// The discriminant route (static_filter_discriminant_signs_normalized): the same pipeline as
/// static_filter_signs_normalized() (f, balancing, scaling into [-1, 1], the second-stage bound
/// a + r * eps), restricted to f and Disc(f), the latter from the invariants (27 Disc(f), about a
/// dozen products); s and the smallness quantities when need(bits) says so. Index kDisc27 of the
/// a/r arrays is 27 Disc(f), 6 and 7 are vertex and graeffe. Its balancing and scaling are written
/// out here rather than shared with the full pipeline: a shared helper measured 5-12 % slower on
/// decide_position (benchmarks/regime_bench); its two halves are always inlined into it.
template <class Need>
inline DiscriminantSignBits discriminant_bits(const DoubleMatrix4& pn, const DoubleMatrix4& en, Need need,
                                              std::optional<bool>* gap) {
  const Bounds& b = bounds();
  auto f = characteristic_polynomial_lanes(pn, en);  // bit for bit the generic template
  DiscriminantSignBits out;
  Balance bal;
  if (!balanced_f_bits(b, f, out, bal) || !need(out)) return out;
  smallness_bits(b, pn, en, f, bal, out, gap);
  return out;
}

USign sign_from_bits(const DiscriminantSignBits& bits, int i) {
  if ((bits.positive >> i) & 1) return USign(CGAL::POSITIVE);
  if ((bits.negative >> i) & 1) return USign(CGAL::NEGATIVE);
  return USign::indeterminate();
}

}  // namespace

DecisionSigns DiscriminantSignBits::signs() const {
  DecisionSigns d;
  for (int i = 0; i < 5; ++i) d.quartic.f[i] = sign_from_bits(*this, i);
  d.quartic.g0 = sign_from_bits(*this, kDisc);
  d.vertex = sign_from_bits(*this, kVertex);
  d.graeffe = sign_from_bits(*this, kGraeffe);
  return d;
}

const std::array<DiscriminantCase, 1 << 12>& detail::discriminant_case_table() {
  static const auto table = [] {
    std::array<DiscriminantCase, 1 << 12> t{};
    for (unsigned k = 0; k < t.size(); ++k)
      t[k] = relpos::discriminant_case(DiscriminantSignBits{k & 0x3f, k >> 6}.signs().quartic);
    return t;
  }();
  return table;
}

const std::array<signed char, 16>& detail::rho_vs_one_table() {
  static const auto table = [] {
    std::array<signed char, 16> t{};
    for (unsigned k = 0; k < t.size(); ++k) {
      const DecisionSigns d =
          DiscriminantSignBits{(k & 3) << DiscriminantSignBits::kVertex, (k >> 2) << DiscriminantSignBits::kVertex}
              .signs();
      t[k] = static_cast<signed char>(compare_rho_with_one(d.vertex, d.graeffe).value_or(2));
    }
    return t;
  }();
  return table;
}

// flatten: the balancing and scaling helpers inlined (out of line they cost 15 % of decide_position).
[[gnu::flatten]] DecisionSigns static_filter_discriminant_signs_normalized(const DoubleMatrix4& pn,
                                                                           const DoubleMatrix4& en,
                                                                           bool (*need_smallness)(const QuarticSigns&),
                                                                           std::optional<bool>* gap) {
  auto need = [need_smallness](const DiscriminantSignBits& bits) {
    return need_smallness && need_smallness(bits.signs().quartic);
  };
  return discriminant_bits(pn, en, need, gap).signs();
}

namespace {

/// The need of static_filter_discriminant_bits_normalized(): smallness always computed.
struct AlwaysNeeded {
  bool operator()(const DiscriminantSignBits&) const { return true; }
};

[[gnu::flatten]] DiscriminantSignBits bits_baseline(const DoubleMatrix4& pn, const DoubleMatrix4& en,
                                                    std::optional<bool>* gap) {
  return discriminant_bits(pn, en, AlwaysNeeded{}, gap);
}

}  // namespace

// On x86-64 (ELF, GCC) static_filter_discriminant_bits_normalized() is the same template compiled
// twice, for AVX2 and for the baseline, one of the two chosen once when the library is loaded
// (load_time_copies.hpp). Only the encoding changes -- three operands and unaligned memory operands,
// about a sixth fewer instructions on decide_position's path -- so every value, error bound and
// sign is the same double on either path; tests run both copies
// (detail::static_filter_discriminant_bits_copy).
#if RELPOS_AVX2_COPY

namespace {

[[gnu::flatten, gnu::target("avx2")]] DiscriminantSignBits bits_avx2(const DoubleMatrix4& pn, const DoubleMatrix4& en,
                                                                     std::optional<bool>* gap) {
  return discriminant_bits(pn, en, AlwaysNeeded{}, gap);
}

}  // namespace

using BitsFunction = DiscriminantSignBits(const DoubleMatrix4&, const DoubleMatrix4&, std::optional<bool>*);

// C linkage: the ifunc attribute names its resolver by the assembler name. Not instrumented, as
// cpu_has_avx2().
extern "C" {
[[gnu::no_sanitize_address, gnu::no_sanitize_undefined, gnu::no_instrument_function]] static BitsFunction*
relpos_resolve_static_filter_bits() {
  return detail::cpu_has_avx2() ? bits_avx2 : bits_baseline;
}
}

DiscriminantSignBits static_filter_discriminant_bits_normalized(const DoubleMatrix4& pn, const DoubleMatrix4& en,
                                                                std::optional<bool>* gap)
    __attribute__((ifunc("relpos_resolve_static_filter_bits")));
#else

[[gnu::flatten]] DiscriminantSignBits static_filter_discriminant_bits_normalized(const DoubleMatrix4& pn,
                                                                                 const DoubleMatrix4& en,
                                                                                 std::optional<bool>* gap) {
  return bits_baseline(pn, en, gap);
}
#endif

bool detail::static_filter_copy_runs(FilterCopy copy) {
#if RELPOS_AVX2_COPY
  if (copy == FilterCopy::avx2) return detail::cpu_has_avx2();
#endif
  return copy == FilterCopy::baseline;
}

DiscriminantSignBits detail::static_filter_discriminant_bits_copy(FilterCopy copy, const DoubleMatrix4& pn,
                                                                  const DoubleMatrix4& en, std::optional<bool>* gap) {
#if RELPOS_AVX2_COPY
  if (copy == FilterCopy::avx2) return bits_avx2(pn, en, gap);
#endif
  (void)copy;
  return bits_baseline(pn, en, gap);
}

}  // namespace relpos
