// Exact arithmetic in Q(sqrt d) for the independent verifiers (src/certificate/verify.cpp, the
// general quadrics' src/general/verify.cpp): u + v sqrt d with rational u, v, every number of one
// certificate sharing d, and determinants of submatrices of a 4x4 matrix over it. Ring operations
// and one exact sign only: no code of the classifier (pencils, Sturm sequences, roots, filters), so a
// certificate checked with it is evidence independent of the code that produced it.
#pragma once

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "algebra/matrix4.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

struct Qd {
  Rational u, v;
};

/// Q(sqrt d), d >= 0 (d = 0: the rationals, so that one determinant code serves both).
class Field {
 public:
  explicit Field(Integer d) : d_(std::move(d)), dq_(d_) {}
  Qd add(const Qd& x, const Qd& y) const { return {x.u + y.u, x.v + y.v}; }
  Qd sub(const Qd& x, const Qd& y) const { return {x.u - y.u, x.v - y.v}; }
  Qd mul(const Qd& x, const Qd& y) const { return {x.u * y.u + x.v * y.v * dq_, x.u * y.v + x.v * y.u}; }
  Qd neg(const Qd& x) const { return {-x.u, -x.v}; }
  Qd zero() const { return {Rational(0), Rational(0)}; }
  int sign(const Qd& x) const {
    const int su = CGAL::sign(x.u), sv = d_ == 0 ? 0 : static_cast<int>(CGAL::sign(x.v));
    if (sv == 0) return su;
    if (su == 0) return sv;
    if (su == sv) return su;
    // Opposite signs: |u| against |v| sqrt d.
    return su * static_cast<int>(CGAL::sign(x.u * x.u - x.v * x.v * dq_));
  }
  std::string text(const Qd& x) const {
    if (x.v == 0 || d_ == 0) return to_string(x.u);
    return to_string(x.u) + (x.v < 0 ? " - " : " + ") + to_string(x.v < 0 ? Rational(-x.v) : x.v) + " sqrt " +
           to_string(d_);
  }

 private:
  Integer d_;
  Rational dq_;
};

/// A rational as an element of any Field.
inline Qd rat(const Rational& q) { return {q, Rational(0)}; }

using QMatrix = std::array<Qd, 16>;

/// Determinant of the submatrix of m on rows x cols, by Laplace expansion along the first row (at
/// most 4 x 4: 24 products; ring operations only).
inline Qd minor_det(const Field& f, const QMatrix& m, const std::vector<int>& rows, const std::vector<int>& cols) {
  const std::size_t n = rows.size();
  if (n == 0) return rat(Rational(1));
  if (n == 1) return m[static_cast<std::size_t>(4 * rows[0] + cols[0])];
  Qd total = f.zero();
  const std::vector<int> sub_rows(rows.begin() + 1, rows.end());
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<int> sub_cols;
    for (std::size_t j = 0; j < n; ++j)
      if (j != k) sub_cols.push_back(cols[j]);
    const Qd term = f.mul(m[static_cast<std::size_t>(4 * rows[0] + cols[k])], minor_det(f, m, sub_rows, sub_cols));
    total = k % 2 == 0 ? f.add(total, term) : f.sub(total, term);
  }
  return total;
}

/// The rank of the leading 3 x 3 block of k (lambda A + M, or B + t M), from its non-zero minors.
inline int block_rank(const Field& f, const QMatrix& k) {
  for (int size = 3; size >= 1; --size)
    for (int rmask = 1; rmask < 8; ++rmask)
      for (int cmask = 1; cmask < 8; ++cmask) {
        std::vector<int> r, c;
        for (int j = 0; j < 3; ++j) {
          if (rmask & (1 << j)) r.push_back(j);
          if (cmask & (1 << j)) c.push_back(j);
        }
        if (static_cast<int>(r.size()) == size && static_cast<int>(c.size()) == size &&
            f.sign(minor_det(f, k, r, c)) != 0)
          return size;
      }
  return 0;
}

/// A point as "(x, y, z)" in exact rationals, for a verifier's message.
inline std::string point_text(const Vector3& x) {
  return "(" + to_string(x[0]) + ", " + to_string(x[1]) + ", " + to_string(x[2]) + ")";
}

}  // namespace relpos::detail
