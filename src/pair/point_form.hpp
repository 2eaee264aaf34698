// Exact signs of a quadric's form X^T Q X at rational points X = (x, 1), on integers (the
// certificates' candidate points, math.md §8): Q times the positive lcm of its denominators, x over
// the lcm D of its coordinates' denominators, so D^2 X^T Q X = N^T Qz N with N = (D x, D). No rational
// canonicalisation (gcd) per operation, and every integer, temporaries included, is a pooled one.
#pragma once

#include <gmp.h>

#include <array>

#include "algebra/forms.hpp"
#include "filters/pooled_integer.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

class PointForm {
 public:
  /// From the integer form itself (forms::integer_form).
  template <class Z>
  explicit PointForm(const forms::MatrixOf<Z>& z) {
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) mpz_set(z_[i][j].mpz(), z(i, j).mpz());
    double_off_diagonal();
  }
  /// From a matrix of exact doubles, written straight into the form (no Integer handles).
  explicit PointForm(const DoubleMatrix4& d) {
    PooledInteger lower[6];  // the entries below the diagonal, equal to those above
    std::array<mpz_ptr, 16> out;
    for (int i = 0, k = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) out[static_cast<std::size_t>(4 * i + j)] = (j >= i ? z_[i][j] : lower[k++]).mpz();
    Integer l;
    forms::integer_form(d, out, l);
    double_off_diagonal();
  }
  PointForm(const PointForm&) = delete;
  PointForm& operator=(const PointForm&) = delete;

  /// Numerators N = (D x, D) of a point, shared by every form evaluated at it.
  struct Point {
    PooledInteger n[4];
    explicit Point(const std::array<Rational, 3>& x) {
      mpz_set_ui(n[3].mpz(), 1);
      for (int i = 0; i < 3; ++i) forms::fold_lcm(n[3].mpz(), mpq_denref(x[i].mpq()));
      for (int i = 0; i < 3; ++i) {
        mpz_divexact(n[i].mpz(), n[3].mpz(), mpq_denref(x[i].mpq()));
        mpz_mul(n[i].mpz(), n[i].mpz(), mpq_numref(x[i].mpq()));
      }
    }
    Point(const Point&) = delete;
    Point& operator=(const Point&) = delete;
  };

  /// sign(X^T Q X): Horner per row, N_i (sum_{j >= i} Qz_ij N_j).
  int sign(const Point& x) const {
    PooledInteger acc, row;
    for (int i = 0; i < 4; ++i) {
      mpz_set_ui(row.mpz(), 0);
      for (int j = i; j < 4; ++j) mpz_addmul(row.mpz(), z_[i][j].mpz(), x.n[j].mpz());
      mpz_addmul(acc.mpz(), row.mpz(), x.n[i].mpz());
    }
    return acc.sign();
  }

 private:
  void double_off_diagonal() {  // off-diagonal entries appear twice in X^T Q X
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) mpz_mul_2exp(z_[i][j].mpz(), z_[i][j].mpz(), 1);
  }
  PooledInteger z_[4][4];  // the upper triangle (j >= i) only
};

}  // namespace relpos::detail
