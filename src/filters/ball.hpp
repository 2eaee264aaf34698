// A double with a certified radius: midpoint-radius ("ball") arithmetic, the filter number type for
// quantities computed from already-filtered values (math.md §17). Where RunningBound bounds an
// error by the magnitude of the whole expansion that produced a value, a Ball propagates the radius
// through the actual values (|x y - m1 m2| <= |m1| r2 + |m2| r1 + r1 r2), so a discriminant of a
// polynomial whose coefficients are known to 15 digits is known to about as many digits as its
// conditioning allows, however long the expansions behind those coefficients were.
//
// Rounding to nearest, no FMA contraction (-ffp-contract=off), no rounding-mode switch. A rounded
// sum or product m has |m - exact| <= 2^-52 |m| + 2^-1075 (the absolute term only for an
// underflowing product; sums of doubles never round inexactly below the normal range). The radius is
// a sum of non-negative terms, each rounded with relative error <= 2^-53 and possibly underflowing:
// the computed sum is inflated by (1 + 2^-49) and 2^-1069 is added, which covers both (the
// inflation exceeds (1 - 2^-53)^-8). Overflow gives an infinite or NaN radius, and nothing is
// certified then (every comparison with NaN is false).
#pragma once

#include <cmath>

namespace relpos {

class Ball {
 public:
  Ball(double exact = 0) : m_(exact), r_(0) {}  // NOLINT: implicit, like RunningBound
  Ball(double mid, double radius) : m_(mid), r_(radius) {}
  double mid() const { return m_; }
  double radius() const { return r_; }
  /// +1 or -1 when every number of the ball has that sign, 0 when uncertain.
  int sign() const { return m_ > r_ ? 1 : (m_ < -r_ ? -1 : 0); }

  friend Ball operator+(const Ball& x, const Ball& y) {
    const double m = x.m_ + y.m_;
    return {m, widen(x.r_ + y.r_ + kRel * std::fabs(m))};
  }
  friend Ball operator-(const Ball& x, const Ball& y) {
    const double m = x.m_ - y.m_;
    return {m, widen(x.r_ + y.r_ + kRel * std::fabs(m))};
  }
  friend Ball operator*(const Ball& x, const Ball& y) {
    const double m = x.m_ * y.m_;
    return {m, widen(std::fabs(x.m_) * y.r_ + std::fabs(y.m_) * x.r_ + x.r_ * y.r_ + kRel * std::fabs(m))};
  }
  friend Ball operator-(const Ball& x) { return {-x.m_, x.r_}; }
  /// x times an exact double c (a Horner step at a point): the same bound with r_c = 0.
  Ball times(double c) const {
    const double m = m_ * c;
    return {m, widen(std::fabs(c) * r_ + kRel * std::fabs(m))};
  }

 private:
  static constexpr double kRel = 0x1p-52;
  static double widen(double r) { return r * (1 + 0x1p-49) + 0x1p-1069; }
  double m_, r_;
};

}  // namespace relpos
