// Exact arithmetic in Q(sqrt n) and the linear algebra of a tangency at the end of an interval
// (math.md §18): the multiplier t* = a + b sqrt n is a root of D of degree <= 2, and the contact set
// is computed over Q(sqrt n) by Gaussian elimination. The verifiers have their own Q(sqrt d)
// (src/certificate/quadratic_field.hpp) on purpose: a certificate is evidence only if the code that
// checks it shares nothing with the code that wrote it (doc/math.md §18).
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "relpos/general_position.hpp"

namespace relpos::detail::general {

/// u + v sqrt(n) for the field's n (n = 0: the rationals).
struct Qn {
  Rational u, v;
};

class QuadraticField {
 public:
  explicit QuadraticField(Integer n) : n_(std::move(n)), nq_(n_) {}
  const Integer& n() const { return n_; }
  Qn of(const Rational& q) const { return {q, Rational(0)}; }
  Qn add(const Qn& x, const Qn& y) const { return {x.u + y.u, x.v + y.v}; }
  Qn sub(const Qn& x, const Qn& y) const { return {x.u - y.u, x.v - y.v}; }
  Qn mul(const Qn& x, const Qn& y) const { return {x.u * y.u + x.v * y.v * nq_, x.u * y.v + x.v * y.u}; }
  /// 1/x for x != 0: (u - v sqrt n) / (u^2 - v^2 n), the denominator non-zero because sqrt n is
  /// irrational whenever v != 0 is used (n not a square, or v = 0).
  Qn inv(const Qn& x) const {
    const Rational norm = x.u * x.u - x.v * x.v * nq_;
    return {x.u / norm, -x.v / norm};
  }
  int sign(const Qn& x) const {
    const int su = CGAL::sign(x.u), sv = n_ == 0 ? 0 : static_cast<int>(CGAL::sign(x.v));
    if (sv == 0) return su;
    if (su == 0 || su == sv) return su == 0 ? sv : su;
    return su * static_cast<int>(CGAL::sign(x.u * x.u - x.v * x.v * nq_));
  }
  bool is_zero(const Qn& x) const { return sign(x) == 0; }

 private:
  Integer n_;
  Rational nq_;
};

using Qn3 = std::array<Qn, 3>;

/// The solutions of A x = r (A 3x3, row-major) over the field: a particular solution and a basis of
/// the kernel of A, or nullopt when the system is inconsistent.
struct AffineSolution {
  Qn3 particular;
  std::vector<Qn3> kernel;
};

inline std::optional<AffineSolution> solve_affine(const QuadraticField& k, std::array<Qn, 9> a, Qn3 r) {
  int pivot_col[3] = {-1, -1, -1};
  int row = 0;
  for (int col = 0; col < 3 && row < 3; ++col) {
    int p = -1;
    for (int i = row; i < 3; ++i)
      if (!k.is_zero(a[static_cast<std::size_t>(3 * i + col)])) {
        p = i;
        break;
      }
    if (p < 0) continue;
    for (int j = 0; j < 3; ++j)
      std::swap(a[static_cast<std::size_t>(3 * p + j)], a[static_cast<std::size_t>(3 * row + j)]);
    std::swap(r[static_cast<std::size_t>(p)], r[static_cast<std::size_t>(row)]);
    const Qn inv = k.inv(a[static_cast<std::size_t>(3 * row + col)]);
    for (int j = 0; j < 3; ++j)
      a[static_cast<std::size_t>(3 * row + j)] = k.mul(a[static_cast<std::size_t>(3 * row + j)], inv);
    r[static_cast<std::size_t>(row)] = k.mul(r[static_cast<std::size_t>(row)], inv);
    for (int i = 0; i < 3; ++i) {
      if (i == row) continue;
      const Qn factor = a[static_cast<std::size_t>(3 * i + col)];
      if (k.is_zero(factor)) continue;
      for (int j = 0; j < 3; ++j)
        a[static_cast<std::size_t>(3 * i + j)] =
            k.sub(a[static_cast<std::size_t>(3 * i + j)], k.mul(factor, a[static_cast<std::size_t>(3 * row + j)]));
      r[static_cast<std::size_t>(i)] =
          k.sub(r[static_cast<std::size_t>(i)], k.mul(factor, r[static_cast<std::size_t>(row)]));
    }
    pivot_col[row] = col;
    ++row;
  }
  for (int i = row; i < 3; ++i)
    if (!k.is_zero(r[static_cast<std::size_t>(i)])) return std::nullopt;
  AffineSolution s;
  for (Qn& x : s.particular) x = k.of(Rational(0));
  bool is_pivot[3] = {false, false, false};
  for (int i = 0; i < row; ++i) {
    s.particular[static_cast<std::size_t>(pivot_col[i])] = r[static_cast<std::size_t>(i)];
    is_pivot[pivot_col[i]] = true;
  }
  for (int free = 0; free < 3; ++free) {
    if (is_pivot[free]) continue;
    Qn3 w;
    for (Qn& x : w) x = k.of(Rational(0));
    w[static_cast<std::size_t>(free)] = k.of(Rational(1));
    for (int i = 0; i < row; ++i)
      w[static_cast<std::size_t>(pivot_col[i])] = k.sub(k.of(Rational(0)), a[static_cast<std::size_t>(3 * i + free)]);
    s.kernel.push_back(w);
  }
  return s;
}

}  // namespace relpos::detail::general
