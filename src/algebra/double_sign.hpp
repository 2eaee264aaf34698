// The exact sign of an integer polynomial of degree <= 4 at a double, filtered: what the
// certification of approximate roots asks for (roots.hpp's fast path, the certificates' curve
// search). The cheaper stages only save work; every answer is the exact sign.
#pragma once

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// h's coefficients h[0..n] as doubles, all divided by one power of two 2^top (the roots do not
/// move; each coefficient truncated to 53 bits), into c[0..n]; returns the Cauchy bound
/// 2 (1 + max |c_i / c_n|) on the roots, or 0 when it is not a finite double.
double scaled_doubles(const Integer* h, int n, double* c, long* top_out = nullptr);

/// The exact sign of an integer polynomial h (h[0..n], n <= 4, h[n] != 0) at doubles: the double
/// Horner value against a crude bound (2^-48 of the magnitude), then a compensated Horner evaluation
/// on h's leading 53 bits plus the leading 53 bits of the rest (each coefficient split in two
/// doubles) with a rigorous bound (round-to-nearest only), then exactly in integers. Each stage
/// answers only when certain, so the result is always the exact sign.
class DoubleSign {
 public:
  DoubleSign(const Integer* h, int n);
  int operator()(double x);
  /// The two floating-point stages only: the exact sign, or 0 when neither is certain.
  int filtered(double x);
  /// h / 2^top in doubles (each coefficient truncated to 53 bits), c[0..n].
  const double* coefficients() const { return c_; }
  /// The Cauchy bound on the roots of c, or 0 when it is not a finite double.
  double root_bound() const { return bound_; }

 private:
  bool split();
  int compensated(double x, double mag);
  const Integer* h_;
  int n_;
  long top_ = 0;
  double c_[5] = {}, lo_[5] = {}, bound_ = 0;
  bool relative_ = true;
  int split_ = 0;  // lo_ filled: 1, impossible: -1, not yet: 0
};

}  // namespace relpos::detail
