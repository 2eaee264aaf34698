// What a quadric read from text was made of (the "recipe"): its form and the decimal numbers read,
// a plain value. The exact matrix is built from it only when an exact stage or the evidence asks
// (QuadricMatrix keeps it behind an opaque pointer), and the evidence reads its integer form and
// truncated doubles from the numbers without building the matrix. The reader of text (src/io) only
// fills it; every exact value of it is written here.
#pragma once

#include <array>
#include <cstdint>

#include "algebra/integer_form.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// A number as read: (-1)^neg m 10^e with m free of trailing zeros (0 for zero, with e = 0 and neg
/// false), or in a recipe of doubles the double (-1)^neg m 2^(e-53) (m < 2^53). One value has one
/// identity: the reader's exact symmetry and zero tests compare identities.
struct Decimal {
  std::uint64_t m = 0;
  int e = 0;
  bool neg = false;
  bool is_zero() const { return m == 0; }
  bool same(const Decimal& o) const { return neg == o.neg && m == o.m && e == o.e; }
};

/// A quadric's form and numbers: a matrix (16 numbers, row-major, exactly symmetric, taken with the
/// orientation the shape test certified), a sphere (centre x, y, z and radius r in n[0..3]) or a
/// standard paraboloid without rotation (vertex x, y, z, then a and b in n[0..4]).
struct DecimalRecipe {
  enum class Form : unsigned char { Matrix, Sphere, Standard };
  Form form = Form::Matrix;
  bool doubles = false;  ///< the numbers are doubles (--numbers double), not decimals
  int orientation = 1;   ///< -1: the matrix is the negated numbers (Q3 made definite)
  std::array<Decimal, 16> n{};
};

/// The exact matrix: that of the constructor the general reader calls for the form
/// (Ellipsoid::sphere, Paraboloid::standard), or the numbers with the orientation (what from_matrix
/// returns); for decimal numbers the entries of a sphere and of a standard paraboloid with its
/// vertex on the axis are written directly in canonical form (their denominators are powers of 2
/// and 5, and the squared mantissas of a and b in forms::inverse_square).
Matrix4 exact_matrix(const DecimalRecipe& r);

/// Whether the evidence of a pair has closed forms on these numbers (closed_evidence.hpp): decimal
/// numbers of a sphere, or of a standard paraboloid with its vertex on the axis.
bool has_closed_form(const DecimalRecipe& r);

/// For decimal numbers (a matrix, a sphere, a standard paraboloid with its vertex anywhere):
/// exact_matrix(r)'s entries truncated towards zero (forms::truncated_double of each), written from
/// the numbers in a few scratch rationals, without a matrix of rationals; false (out unspecified)
/// for a recipe of doubles.
bool truncated_doubles(const DecimalRecipe& r, DoubleMatrix4& out);

/// For decimal numbers: integer_form(exact_matrix(r), l) and split_scale(l, exact_matrix(r)) written
/// from the exponents and mantissas (forms::integer_form_of; recipe_integer_form.cpp), a standard
/// paraboloid off the axis included (its vertex's sum over lcm(R_a^2, R_b^2); the split's factors
/// then a coprime base of the same rest, perhaps coarser than split_scale's); false (nothing
/// written) for a recipe of doubles.
bool write_integer_form(const DecimalRecipe& r, const forms::IntegerFormOut& out);

/// c0^2 + c1^2 + c2^2 - r^2 of a sphere's decimal numbers as an integer sum over the smallest power
/// of ten: the sum into `sum`, and the exponent `low` returned, with the entry = sum 10^(2 low).
int sphere_sum(const DecimalRecipe& r, mpz_ptr sum);

}  // namespace relpos::detail
