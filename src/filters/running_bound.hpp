// A double that carries a certified bound on its rounding error: the filter number type of the
// scene early-outs (scene.hpp; math.md §13, for the derivation).
//
// For a straight-line program of +, -, * evaluated in IEEE double with rounding to nearest, each
// RunningBound holds the computed value v, a computed magnitude a (the same program on absolute
// values, subtraction replaced by addition, every product with non-zero operands floored at
// 2^-1022; a zero magnitude is an exact zero and stays zero) and an operation
// count d (x +- y: max(dx, dy) + 1; x * y: dx + dy + 2). By induction over the program,
//
//   |v - exact| <= ((1 + u)^d - 1) A  and  a >= A (1 - u)^d,   u = 2^-53,
//
// where A is the magnitude program evaluated exactly. The floor at 2^-1022 and the extra count per
// product absorb the absolute error 2^-1075 of an underflowing product; sums of doubles never
// underflow inexactly. Hence |v - exact| <= (d + 3) u a + 2^-1070 =: error_bound() for d <= 10^4,
// and sign() is certain when |v| exceeds it. Overflow gives an infinite or NaN value or bound, and
// then nothing is certified (every comparison with NaN is false). Unlike CGAL::Interval_nt this
// needs no rounding-mode switch and no branches; d is a compile-time constant once inlined.
//
// Requires the default rounding mode (to nearest) and no FMA contraction (-ffp-contract=off), like
// the static filter of the core.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace relpos {

class RunningBound {
 public:
  /// An exact input (every double is an exact rational).
  RunningBound(double exact = 0) : v_(exact), a_(std::fabs(exact)), d_(0) {}  // NOLINT: implicit on purpose

  /// A number known only to lie in [lo, hi] (e.g. CGAL::to_interval of a rational). Never certain
  /// when the interval is not finite or wider than about 2^-40 of its magnitude.
  static RunningBound enclosing(double lo, double hi) {
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) return nan();
    if (lo == hi) return RunningBound(lo);
    const double a = std::max(std::fabs(lo), std::fabs(hi));
    // |lo - x| <= hi - lo <= w (the subtraction rounded, then inflated); d u a >= w makes
    // ((1 + u)^d - 1) a >= w.
    const double w = (hi - lo) * (1 + 0x1p-50);
    const double d = std::ceil(w / (kU * a) * (1 + 0x1p-50)) + 1;
    if (!(d <= 4096)) return nan();
    return RunningBound(lo, a, static_cast<int>(d));
  }

  double value() const { return v_; }
  double magnitude() const { return a_; }
  int count() const { return d_; }
  /// Certified bound on |value() - exact|.
  double error_bound() const { return error_bound(a_, d_); }
  /// +1 or -1 when the exact value certainly has that sign, 0 when uncertain.
  int sign() const { return certain_sign(v_, a_, d_); }

  /// The bound and the sign test for a value v with magnitude a and count d (also used with counts
  /// computed once for a whole program: the count does not depend on the values).
  static double error_bound(double a, int d) { return static_cast<double>(d + 3) * kU * a + 0x1p-1070; }
  static int certain_sign(double v, double a, int d) {
    if (d > 10000) return 0;
    const double b = error_bound(a, d);
    if (v > b) return 1;
    if (v < -b) return -1;
    return 0;
  }

  /// x * 2^k, given two_k = 2^k. Exact unless the value underflows, whose absolute error 2^-1075 the
  /// extra count absorbs while the magnitude stays >= 2^-1000; below that nothing is certified.
  RunningBound times_power_of_two(double two_k) const {
    const double a = a_ * two_k;
    if (a != 0 && !(a >= 0x1p-1000 && a <= 0x1p1000)) return nan();
    return {v_ * two_k, a, d_ + 1};
  }

  friend RunningBound operator+(const RunningBound& x, const RunningBound& y) {
    return {x.v_ + y.v_, x.a_ + y.a_, std::max(x.d_, y.d_) + 1};
  }
  friend RunningBound operator-(const RunningBound& x, const RunningBound& y) {
    return {x.v_ - y.v_, x.a_ + y.a_, std::max(x.d_, y.d_) + 1};
  }
  friend RunningBound operator*(const RunningBound& x, const RunningBound& y) {
    // A zero magnitude means an exactly zero value (A <= a / (1 - u)^d = 0), so the product is
    // exactly zero and keeps magnitude 0. Flooring it to 2^-1022 instead would be sound but slow:
    // the floor times the next small magnitude underflows, and every underflowing product costs a
    // microcode assist (~150 cycles); matrices with zero entries did that hundreds of times per pair.
    const double m = x.a_ * y.a_;
    const double a = (x.a_ == 0 || y.a_ == 0) ? 0.0 : std::max(m, 0x1p-1022);
    return {x.v_ * y.v_, a, x.d_ + y.d_ + 2};
  }
  friend RunningBound operator-(const RunningBound& x) { return {-x.v_, x.a_, x.d_}; }

 private:
  static constexpr double kU = 0x1p-53;
  RunningBound(double v, double a, int d) : v_(v), a_(a), d_(d) {}
  static RunningBound nan() {
    const double q = std::numeric_limits<double>::quiet_NaN();
    return RunningBound(q, q, 0);
  }
  double v_, a_;
  int d_;
};

/// RunningBound without its count: value and magnitude as one SSE register, so a product is one
/// mulpd and a sum one addpd. For programs whose counts are known in advance (they never depend on
/// the values: run the same code once on RunningBound) -- the hot paths of the semi-static stage and
/// of the scene early-outs. There is no magnitude floor: a caller must keep every non-zero magnitude
/// product clear of underflow (each does it with a range guard on its inputs), and then a value's
/// underflow error (< 2^-1075) is absorbed by the count exactly as in RunningBound. A zero magnitude
/// is an exact zero and stays zero.
class RunningBoundLanes {
 public:
  RunningBoundLanes(double exact = 0) : x_{exact, std::fabs(exact)} {}  // NOLINT: like RunningBound
  static RunningBoundLanes of(const RunningBound& r) { return RunningBoundLanes(V2{r.value(), r.magnitude()}); }
  double value() const { return x_[0]; }
  double magnitude() const { return x_[1]; }
  RunningBoundLanes times_power_of_two(double two_k) const { return RunningBoundLanes(x_ * two_k); }

  friend RunningBoundLanes operator+(const RunningBoundLanes& a, const RunningBoundLanes& b) {
    return RunningBoundLanes(a.x_ + b.x_);
  }
  friend RunningBoundLanes operator-(const RunningBoundLanes& a, const RunningBoundLanes& b) {
    return RunningBoundLanes(a.x_ + b.x_ * kFlip);  // magnitudes add
  }
  friend RunningBoundLanes operator*(const RunningBoundLanes& a, const RunningBoundLanes& b) {
    return RunningBoundLanes(a.x_ * b.x_);
  }
  friend RunningBoundLanes operator-(const RunningBoundLanes& a) { return RunningBoundLanes(a.x_ * kFlip); }

 private:
  typedef double V2 __attribute__((vector_size(16)));  // {value, magnitude}
  static constexpr V2 kFlip = {-1.0, 1.0};             // negates the value lane only
  explicit RunningBoundLanes(V2 x) : x_(x) {}
  V2 x_;
};

}  // namespace relpos
