// Exact number types and exact parsing.
//
// relpos decides with exact rationals: every input entry becomes a CGAL::Gmpq (GMP) without
// rounding. A double is a dyadic rational and is taken as exactly that value; a decimal string
// such as "0.712045" is 712045/10^6, never the nearest double.
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace relpos {

using Integer = CGAL::Gmpz;
using Rational = CGAL::Gmpq;

/// Parse an exact rational from text: integers ("-3"), fractions ("p/q"), decimals ("0.712045",
/// "-.5", "1.5e-7", "2E+10"). The denominator of a fraction is written without sign, and no blank
/// surrounds the number. Throws relpos::InputError naming the text on anything else.
Rational parse_rational(std::string_view text);

/// The exact value of a finite double. Throws relpos::InputError on NaN or infinity.
Rational exact_rational(double value);

/// Shortest exact text of a rational: "3", "-7/2".
std::string to_string(const Rational& q);
std::string to_string(const Integer& z);

/// Decimal approximation of q with `digits` significant digits (rounded to nearest).
std::string to_decimal(const Rational& q, int digits);

/// Opt-in speed-up for programs that classify many pairs: GMP's blocks of up to 512 bytes are
/// recycled through per-thread caches keyed on their exact size (the exact stages and the full
/// evidence allocate and free millions of small limb arrays). Process-wide
/// (mp_set_memory_functions), so it also serves other GMP users of the process; safe to call at
/// any time, with GMP numbers alive: a cached block is a malloc block, reused only for its size.
/// Out of memory throws std::bad_alloc (GMP's default allocator aborts). The relpos CLI
/// and the Python module call it.
void install_gmp_block_cache();

}  // namespace relpos
