// The common quadric forms read straight from JSON text into double enclosures: no DOM,
// no rationals, no heap traffic per number. Used by the batch line's reader (batch.cpp) before the
// general reader (quadric_json.hpp).
//
// A value is read here only when it is one of the forms below, its JSON is plainly valid (keys
// without escapes, no duplicate keys, no other keys) and each number is short (at most 19
// significant digits and a decimal exponent within +-30 after trailing zeros are removed; with
// --numbers double, a double within 2^+-100), or, in a matrix, when its numbers are those of a
// matrix of short numbers times one power of ten (exponents spanning at most 60, each
// enclosure within 2^+-1020: a matrix scaled by 10^300 is read as fast as the unscaled one).
// Anything else returns nullopt and the caller takes the
// general reader, which decides every case and words every error: this reader never answers
// differently and never refuses. The numbers read and the form are kept as the quadric's recipe
// (algebra/decimal_recipe.hpp), from which the exact matrix is built only when an exact stage or the
// evidence asks for it, by the constructor the general reader calls for the form (or, for a matrix,
// with the sign normalization from_matrix applies): the rationals and the evidence are those of the
// general path (tests/test_fast_reader.cpp compares them). For decimal numbers the evidence's
// integer form, its scale's split and the closed forms of a sphere and a standard paraboloid with
// its vertex on the axis are written from the same recipe, without the rationals.
//
// Forms: a 4x4 array or {"matrix": 4x4} (ellipsoid or paraboloid; an exactly symmetric matrix whose
// shape the interval filter certifies, and for a paraboloid det Q3 = 0 by exactly-zero entries),
// {"sphere": {"center"|"centre": [x, y, z], "radius": r}} and {"vertex": [x, y, z], "a": a, "b": b}
// (no rotation).
//
// Size limit (doc/cli.md, Limits): short numbers keep every matrix read here far below
// kMaxNormalizedBits. A number is m 10^e with m < 10^19 and |e| <= 30, so its numerator and
// denominator have at most 64 + 100 bits; the entries of these forms are polynomials of degree at
// most 4 in at most 5 such numbers over powers of ten and the squares of a and b, whose primitive
// integer forms stay below 1500 bits (tests/test_fast_reader.cpp builds the extreme case and checks it).
// A matrix of wide numbers has the primitive integer form of its numbers times 10^-s (s the
// smallest exponent), a matrix of short numbers: the same bound.
#pragma once

#include <optional>
#include <string_view>

#include "relpos/general_quadric.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::io {

/// The ellipsoid described by the JSON text, or nullopt when this reader does not take it.
/// `doubles`: each number is the double nearest its text (--numbers double).
std::optional<Ellipsoid> fast_ellipsoid(std::string_view text, bool doubles);

/// The elliptic paraboloid described by the JSON text, or nullopt (as fast_ellipsoid).
std::optional<Paraboloid> fast_paraboloid(std::string_view text, bool doubles);

/// The same for a text that starts with the value and may go on after it (the rest of a batch
/// line), made in `out` (true), or false with `out` empty. `end` is set to the value's length when
/// the value is one this reader scans (valid JSON, whatever the form), else to npos, so that a
/// caller scanning a line needs no second pass over it.
bool fast_ellipsoid_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Ellipsoid>& out);
bool fast_paraboloid_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Paraboloid>& out);

/// The "quadric" of a batch line (doc/cli.md, "General quadrics") when it is a matrix (a 4x4 array or
/// {"matrix": 4x4}) that this reader certifies as an ellipsoid or an elliptic paraboloid: made in
/// `out` by Quadric::of, the quadric the general reader makes of it (the same exact matrix and type);
/// any other form or type: false, `out` empty, for the general reader. `end` as fast_ellipsoid_at.
bool fast_quadric_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Quadric>& out);

}  // namespace relpos::detail::io
