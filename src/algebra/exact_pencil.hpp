// The pencil's two polynomials (pencil.hpp, math.md §2) for an exact ring such as the integers,
// with each product added straight into the coefficient it belongs to.
//
// Why a second form: the generic formulas fix one order of operations for every number type, since
// the floating-point filters' error bounds are derived on it; they form each minor product as a
// polynomial and then add it. Exact arithmetic does not depend on the order, so here every product
// of two minors' coefficients goes into f or s by one fused call (add_product / sub_product, found
// by argument-dependent lookup: GMP's addmul and submul for PooledInteger) instead of a product, a
// temporary and an addition: a third fewer calls on the evidence's long integers. Exact types only.
// The minors are formed in NT and f, s summed in Acc (NT unless a wider accumulator takes the fused
// products, as fixed_pencil.hpp's 128-bit minors summed in 320 bits).
#pragma once

#include "algebra/pencil.hpp"

namespace relpos {

/// det(lambda P + E) as characteristic_polynomial, for an exact NT (same value, other order).
template <class NT, class M, class Acc = NT>
Quartic<Acc> exact_characteristic_polynomial(const M& p, const M& e) {
  static constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  using detail::add_product;  // unqualified calls: a fused overload wins
  using detail::sub_product;
  Quartic<Acc> f{Acc(0), Acc(0), Acc(0), Acc(0), Acc(0)};
  for (int k = 0; k < 6; ++k) {
    const int* top = kPairs[k];
    const int* bot = kPairs[5 - k];  // complementary columns; Laplace signs + - + + - +
    const Quadratic<NT> u = detail::linear_minor2<NT>(e, p, 0, 1, top[0], top[1]);
    const Quadratic<NT> v = detail::linear_minor2<NT>(e, p, 2, 3, bot[0], bot[1]);
    const bool minus = k == 1 || k == 4;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        if (minus)
          sub_product(f[a + b], u[a], v[b]);
        else
          add_product(f[a + b], u[a], v[b]);
      }
  }
  return f;
}

/// det(lambda A + M) as special_polynomial, for an exact NT (same value, other order).
template <class NT, class M, class Acc = NT>
Quadratic<Acc> exact_special_polynomial(const M& p, const M& e) {
  using detail::add_product;
  using detail::sub_product;
  Quadratic<Acc> s{Acc(0), Acc(0), Acc(0)};
  for (int j = 0; j < 3; ++j) {  // along row 0: entry (0, j) = x0 + lambda x1, signs + - +
    const int c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
    const Quadratic<NT> m = detail::linear_minor2<NT>(e, p, 1, 2, c0, c1);
    const NT &x0 = e(0, j), &x1 = p(0, j);
    auto add = [j](Acc& acc, const NT& x, const NT& y) {
      if (j == 1)
        sub_product(acc, x, y);
      else
        add_product(acc, x, y);
    };
    add(s[0], x0, m[0]);
    add(s[1], x0, m[1]);
    add(s[1], x1, m[0]);
    add(s[2], x0, m[2]);
    add(s[2], x1, m[1]);  // the lambda^3 term x1 m[2] is det A = 0
  }
  return s;
}

}  // namespace relpos
