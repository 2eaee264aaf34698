// A quadric from 16 doubles in one frame (Ellipsoid::from_doubles, Paraboloid::from_doubles): the
// storage's normalization by a power of two (QuadricMatrix's constructor from doubles, with
// normalize_doubles) and the certified shape in doubles, inlined into each other (flatten); the
// intervals and the exact path out of line. The constructor lives here, not with the rest of the
// storage (quadric_matrix.cpp), so that the flattened constructors can inline it. Also the same
// normalization on its own (power_of_two_normalized, the static filter's input range).
#include "algebra/quadric_doubles.hpp"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "algebra/double_bits.hpp"
#include "algebra/kind_filter.hpp"
#include "algebra/quadric_kind.hpp"
#include "algebra/shape_filter.hpp"
#include "relpos/quadric.hpp"

namespace relpos {
namespace detail {

namespace {

/// Two 64-bit lanes of bits and eight 16-bit lanes (GCC/Clang vector extension; SSE2 on x86-64).
typedef long long Bits2 __attribute__((vector_size(16)));
typedef short Words8 __attribute__((vector_size(16)));

Words8 words_max(Words8 a, Words8 b) { return a > b ? a : b; }  // pmaxsw
Words8 words_min(Words8 a, Words8 b) { return a < b ? a : b; }  // pminsw

// normalize_doubles, inlined into the constructor from doubles (which has just read the same
// entries for its symmetry test). Run for every quadric made from doubles, on the top 16 bits of
// each entry's bits (sign, exponent, 4 bits of the significand), eight entries at a time: the
// largest top word of the |entries| gives the largest exponent (0x7ff: an infinity or a NaN), and
// the smallest top word of |entry| - 1 (as integers, compared unsigned; zero wraps to the largest)
// the exponent of the smallest non-zero |entry|, or one less when that entry is a power of two
// (then the exact scalar code below decides). Only rare cases (an entry that would turn subnormal,
// a largest entry in the top binade) take that code.
[[gnu::always_inline]] inline bool normalize(const DoubleMatrix4& in, DoubleMatrix4& out, int& exponent, bool& plain) {
  const Bits2 magnitude = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL}, one = {1, 1};
  const Bits2 flip = {static_cast<long long>(0x8000800080008000ULL), static_cast<long long>(0x8000800080008000ULL)};
  Words8 top[8], low[8];  // |x|, and (|x| - 1) with its words' signs flipped (signed order = unsigned order)
  for (std::size_t k = 0; k < 8; ++k) {
    Bits2 x;
    std::memcpy(&x, &in[2 * k], sizeof x);
    const Bits2 a = x & magnitude;
    top[k] = reinterpret_cast<Words8>(a);
    low[k] = reinterpret_cast<Words8>((a - one) ^ flip);
  }
  // The two halves folded onto each other: the top word of the first entry is lane 3 on a
  // little-endian machine, lane 0 on a big-endian one (no branch).
  constexpr int kTop = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? 3 : 0;
  auto fold = [](Words8 w) { return __builtin_shufflevector(w, w, 4, 5, 6, 7, 0, 1, 2, 3); };
  Words8 hi = words_max(words_max(words_max(top[0], top[1]), words_max(top[2], top[3])),
                        words_max(words_max(top[4], top[5]), words_max(top[6], top[7])));
  Words8 lo = words_min(words_min(words_min(low[0], low[1]), words_min(low[2], low[3])),
                        words_min(words_min(low[4], low[5]), words_min(low[6], low[7])));
  hi = words_max(hi, fold(hi));
  lo = words_min(lo, fold(lo));
  const int top_exponent = hi[kTop] >> 4;                        // biased exponent of the largest |entry|
  if (top_exponent == 0 || top_exponent == 0x7ff) return false;  // zero or subnormal; infinity or NaN
  // Biased exponent of the smallest non-zero |entry| (or one less, see above): 0 when it is subnormal.
  const unsigned lo_word = static_cast<std::uint16_t>(lo[kTop]) ^ 0x8000u;
  const int lo_exponent = static_cast<int>(lo_word >> 4);
  const int emax = top_exponent - 1023;
  const int k = -emax - 1;
  exponent = emax + 1;
  // Common case: every non-zero entry normal, and the smallest stays normal once scaled by 2^k.
  if (lo_exponent >= 1 && lo_exponent - 1023 + k >= -1022 && k >= -1022) {
    const double s = power_of_two(k);
    const Lanes2 scale = {s, s};
    for (std::size_t i = 0; i < 8; ++i) {
      Lanes2 x;
      std::memcpy(&x, &in[2 * i], sizeof x);
      x = x * scale;  // exact
      std::memcpy(&out[2 * i], &x, sizeof x);
    }
    plain = exponent <= 1023;
    return true;
  }
  // 2^-(e+1) is below the normal range when e = 1023: then scale in two exact steps. No entry may
  // turn subnormal, and each must be kept exactly: scaling back must give it again (a product below
  // DBL_MIN may have been rounded, in any rounding mode even up to DBL_MIN itself; scaling back by
  // powers of two is exact).
  const bool two_steps = k < -1022;
  const double pre = two_steps ? 0x1p-512 : 1.0, scale = power_of_two(two_steps ? k + 512 : k);
  const double back_pre = two_steps ? 0x1p512 : 1.0, back_scale = power_of_two(two_steps ? -k - 512 : -k);
  bool lost = false, subnormal = false;
  for (std::size_t i = 0; i < 16; ++i) {
    out[i] = in[i] * pre * scale;
    lost = lost || (in[i] != 0 && std::fabs(out[i]) < DBL_MIN) || out[i] * back_scale * back_pre != in[i];
    subnormal = subnormal || (in[i] != 0 && std::fabs(in[i]) < DBL_MIN);
  }
  plain = !subnormal && exponent <= 1023;  // no entry subnormal, 2^exponent normal
  return !lost;
}

}  // namespace

bool normalize_doubles(const DoubleMatrix4& in, DoubleMatrix4& out, int& exponent, bool& plain) {
  return normalize(in, out, exponent, plain);
}

QuadricMatrix::QuadricMatrix(const DoubleMatrix4& d) : flags_(kDoubles) {
  bool plain;
  // Not symmetric: no quadric (the shape tests, which read the normalized doubles, reject it).
  if (shape_filter::impl::symmetric(d) && normalize(d, v_, exponent_, plain)) {
    flags_ |= kNormalized | (plain ? kPlainScale : 0);
  } else {
    v_ = d;
    exponent_ = 0;
  }
}

void QuadricMatrix::negate_doubles() {
  for (double& x : v_) x = -x;
}

}  // namespace detail

std::optional<DoubleMatrix4> detail::power_of_two_normalized(const std::optional<DoubleMatrix4>& m) {
  if (!m) return std::nullopt;
  DoubleMatrix4 out;
  int exponent;
  bool plain;
  if (!detail::normalize_doubles(*m, out, exponent, plain)) return std::nullopt;
  return out;
}

namespace {

/// The exact rationals of 16 doubles; InputError (exact_rational's message) on NaN or infinity.
Matrix4 exact_matrix(const DoubleMatrix4& d) {
  Matrix4 m;
  for (std::size_t i = 0; i < 16; ++i) m.a[i] = exact_rational(d[i]);
  return m;
}

bool all_finite(const DoubleMatrix4& d) {
  for (double x : d)
    if (!std::isfinite(x)) return false;
  return true;
}

/// A matrix the shape tests did not certify: refused at once when the filtered type test finds it of
/// another kind (kind_filter.hpp; the exact path's message, a few microseconds instead of an exact
/// classification). Its orientation when it finds an ellipsoid and one is wanted (the sign of the
/// first entry: Q3 is definite), else 0: the exact path decides.
int kind_orientation(const DoubleMatrix4& d, QuadricKind want, void (*refuse)(QuadricKind)) {
  const std::optional<QuadricKind> k = detail::shape_filter::certified_kind(d);
  if (k && *k != want) refuse(*k);
  return k && *k == QuadricKind::Ellipsoid ? (d[0] > 0 ? 1 : -1) : 0;
}

}  // namespace

// flatten: the constructor and the signs in doubles in one frame, the values just normalized read
// without a call between; the rest (intervals, the exact path) out of line.
[[gnu::flatten]] Ellipsoid Ellipsoid::from_doubles(const DoubleMatrix4& e) {
  // Built in the returned object (one return: no copy of the 16 doubles) and normalized in place;
  // normalized doubles are finite, so all_finite runs only when the normalization did not.
  Ellipsoid out(e);
  const DoubleMatrix4* normalized = out.m_.filter_doubles();
  int orientation = detail::shape_filter::certified_ellipsoid_in_doubles(normalized);
  if (orientation == 0) {
    [&]() __attribute__((noinline)) {
      orientation = normalized || all_finite(e) ? detail::shape_filter::certified_ellipsoid_by_intervals(e) : 0;
      // Not certified (or not an ellipsoid): the exact path decides and names what the matrix is.
      if (orientation == 0) orientation = kind_orientation(e, QuadricKind::Ellipsoid, detail::refuse_as_ellipsoid);
      if (orientation == 0) out = Ellipsoid(*from_matrix(exact_matrix(e)).doubles());
    }
    ();
  }
  if (orientation < 0) out.m_.negate_doubles();
  return out;
}

// The same steps as Ellipsoid::from_doubles with the paraboloid's certifier, written out: a template
// over both would have to be a friend of both classes for these few lines.
[[gnu::flatten]] Paraboloid Paraboloid::from_doubles(const DoubleMatrix4& p) {
  Paraboloid out(p);
  const DoubleMatrix4* normalized = out.m_.filter_doubles();
  int orientation = detail::shape_filter::certified_paraboloid_in_doubles(p, normalized);
  if (orientation == 0) {
    [&]() __attribute__((noinline)) {
      orientation = normalized || all_finite(p) ? detail::shape_filter::certified_paraboloid_by_intervals(p) : 0;
      if (orientation == 0) kind_orientation(p, QuadricKind::EllipticParaboloid, detail::refuse_as_paraboloid);
      if (orientation == 0) out = Paraboloid(*from_matrix(exact_matrix(p)).doubles());
    }
    ();
  }
  if (orientation < 0) out.m_.negate_doubles();
  return out;
}

}  // namespace relpos
