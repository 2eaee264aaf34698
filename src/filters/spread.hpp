// A double program on inputs known to within a radius, with a certified bound on its result: the
// value, the program's magnitude at the inputs' midpoints and at their ends, and an operation count,
// in the lanes of two vectors, so that a product is two vector multiplications (the general filter's
// Sturm–Habicht sequence and values at points, math.md §17).
//
// Each input x_true is known as a double x with |x_true - x| <= r. Run the program three times: on
// the midpoints (the value v), and as its magnitude program -- subtraction turned into addition -- on
// |x| (a) and on |x| + r rounded upwards (a'), with the count d of RunningBound (x +- y: max + 1;
// x y: dx + dy + 2). For every node w of the program, with W its magnitude program,
//   |w(x_true) - w(x)| <= W(|x| + r) - W(|x|)
// (sums: the triangle inequality; products: |u'v' - uv| <= |u' - u| |v'| + |u| |v' - v| <= (U' - U) V' +
// U (V' - V) = U'V' - UV, since |v'| <= V' and |u| <= U), and the rounding error of the value is at most
// ((1 + u)^d - 1) W(|x|) (RunningBound's induction, u = 2^-53). The computed magnitudes satisfy
// a <= W(|x|)(1 + u)^d, a' >= W(|x| + r)(1 - u)^d (non-negative operands, no underflow: see below), so
//   |w(x_true) - v| <= W' - W + ((1 + u)^d - 1) W <= (a' - a) + 3.1 (d + 1) u a'
// for d <= 10^4, and (a' - a) is rounded with relative error u. bound() adds 2^-1000 for the value's
// underflows (each below 2^-1075). The caller keeps every non-zero input magnitude within
// [2^-120, 2^120] (Spread::in_range), so that a product of at most eight magnitudes never underflows
// or overflows; a zero input with zero radius is an exact zero and stays zero.
//
// Rounding to nearest, no FMA contraction (-ffp-contract=off).
#pragma once

#include <algorithm>
#include <cmath>

namespace relpos {

class Spread {
 public:
  /// An exact double (radius 0), e.g. a constant of the program or a point it is evaluated at.
  Spread(double exact = 0) : va_{exact, std::fabs(exact)}, ud_{std::fabs(exact), 0} {}  // NOLINT: implicit
  /// An input known to within `radius` of `mid`.
  static Spread input(double mid, double radius) {
    const double a = std::fabs(mid);
    return Spread(V2{mid, a}, V2{(a + radius) * (1 + 0x1p-51), 0});
  }
  /// Whether an input's magnitudes are in the range the bound assumes (or exactly zero).
  static bool in_range(double mid, double radius) {
    const double a = std::fabs(mid) + radius;
    return a == 0 || (a >= 0x1p-120 && a <= 0x1p120);
  }
  double value() const { return va_[0]; }
  /// The certified bound on |exact - value()|.
  double bound() const {
    const double a = va_[1], up = ud_[0];
    return (up - a) * (1 + 0x1p-51) + 3.1 * (ud_[1] + 1) * 0x1p-53 * up + 0x1p-1000;
  }
  /// +1 or -1 when certain, 0 otherwise (also for NaN and infinities, and for d > 10^4).
  int sign() const {
    if (!(ud_[1] <= 10000)) return 0;
    const double b = bound();
    return va_[0] > b ? 1 : (va_[0] < -b ? -1 : 0);
  }
  /// This value as a fresh input (the next stage's coefficient).
  Spread restarted() const { return input(va_[0], bound()); }

  friend Spread operator+(const Spread& p, const Spread& q) { return Spread(p.va_ + q.va_, summed(p.ud_, q.ud_)); }
  friend Spread operator-(const Spread& p, const Spread& q) {
    return Spread(p.va_ + q.va_ * kFlip, summed(p.ud_, q.ud_));
  }
  friend Spread operator*(const Spread& p, const Spread& q) {
    const V2 m = p.ud_ * q.ud_, s = p.ud_ + q.ud_ + V2{0, 2};
    return Spread(p.va_ * q.va_, __builtin_shufflevector(m, s, 0, 3));  // (a'_p a'_q, d_p + d_q + 2)
  }
  friend Spread operator-(const Spread& p) { return Spread(p.va_ * kFlip, p.ud_); }
  /// p times an exact double c (a Horner step at a point).
  Spread times(double c) const {
    const double m = std::fabs(c);
    return Spread(va_ * V2{c, m}, ud_ * V2{m, 1} + V2{0, 2});
  }

 private:
  // (value, magnitude) and (magnitude at the ends, operation count): the count is a small integer,
  // exact in a double, carried in the second lane so that each number is two vector registers.
  typedef double V2 __attribute__((vector_size(16)));
  static constexpr V2 kFlip = {-1.0, 1.0};
  /// (a'_p + a'_q, max(d_p, d_q) + 1).
  static V2 summed(V2 p, V2 q) {
    const V2 s = p + q, m = (p > q ? p : q) + V2{0, 1};
    return __builtin_shufflevector(s, m, 0, 3);
  }
  Spread(V2 va, V2 ud) : va_(va), ud_(ud) {}
  V2 va_, ud_;
};

}  // namespace relpos
