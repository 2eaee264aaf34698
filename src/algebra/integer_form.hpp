// Each matrix's own integer form, what the reported evidence is computed on: the matrix times the
// lcm of its own denominators, from rationals, from the bits of doubles (in GMP or in machine
// words), or from the decimal numbers a quadric was read from (decimal_recipe.hpp).
#pragma once

#include <gmp.h>

#include <array>
#include <cstdint>

#include "algebra/matrix_view.hpp"
#include "algebra/split_scale.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::forms {

/// The matrix times the lcm of its own denominators (returned in `l`): the integer form of one
/// quadric. The reported evidence is computed on the two forms, each with its own scale:
/// det(lambda P + E) = sum_i g_i lambda^i / (lp^i le^(4-i)) with g = det(mu Pz + Ez), which keeps
/// every product shorter than one common lcm of both matrices would.
MatrixOf<Integer> integer_form(const Matrix4& m, Integer& l);
/// The same for a matrix of exact doubles, read from their bits (no rationals): equal to
/// integer_form of the matrix of Rational(d[i]).
MatrixOf<Integer> integer_form(const DoubleMatrix4& d, Integer& l);
/// The same written into the caller's integers (16 distinct mpz, row-major), e.g. pooled ones.
void integer_form(const DoubleMatrix4& d, const std::array<mpz_ptr, 16>& out, Integer& l);
/// The same in machine words when every entry is below 2^62 in absolute value (the integer forms of
/// doubles nearly always are: 53-bit significands shifted to a common power of two), with the lcm
/// as its exponent: l = 2^twos. False (out and twos unspecified) otherwise.
bool small_integer_form(const DoubleMatrix4& d, MatrixOf<std::int64_t>& out, unsigned long& twos);

/// Where integer_form_of writes: integer_form(m, l) into 16 distinct integers (row-major, e.g.
/// entries() of pooled ones) and split_scale(l, m) of a quadric's matrix m.
struct IntegerFormOut {
  std::array<mpz_ptr, 16> form;
  Integer& l;
  SplitScale& split;
  /// False when the caller reads only the split's twos, fives and rest: a writer may then leave
  /// rest_power and factors empty.
  bool factors = true;
  /// False when the caller reads only l and the split: a writer may then leave `form` unwritten.
  bool entries = true;
  /// False when the caller reads only the split's twos and fives (and neither the form nor the
  /// factors): a writer may then leave l and the split's rest unwritten too.
  bool scale = true;
};

/// integer_form(q.matrix(), l) and split_scale(l, q.matrix()): for a quadric read from decimal
/// text, written from its recipe (decimal_recipe.hpp: the lcm and the split from the exponents and
/// the mantissas, no rationals and no gcd of long numbers) when it can, else from the matrix.
void integer_form_of(const detail::QuadricMatrix& q, const IntegerFormOut& out);

}  // namespace relpos::detail::forms
