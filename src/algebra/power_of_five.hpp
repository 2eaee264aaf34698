// Powers of five on GMP integers: the factor that decimal text puts into denominators beside the
// twos of doubles. Multiplied from a per-thread table, and divided out by single-limb remainders.
#pragma once

#include <gmp.h>

namespace relpos::detail::forms {

/// out = 5^k: copied from a per-thread table of the powers met so far (k up to 512; beyond, computed):
/// the reductions by decimal scales need the same few powers line after line, and mpz_ui_pow_ui
/// recomputes one with a temporary allocation each time.
void set_power_of_five(mpz_ptr out, unsigned long k);
/// out = x 5^k (out may be x), from the same table.
void times_power_of_five(mpz_ptr out, mpz_srcptr x, unsigned long k);

/// Divides x (non-zero) by its factors 5, at most `most` of them, and returns how many: 27 at a
/// time, by x mod 5^27 (< 2^63) in one single-limb pass; when that is not zero, its own valuation
/// is x's (r = x + k 5^27). No mpz temporaries, unlike mpz_remove.
unsigned long remove_fives(mpz_ptr x, unsigned long most);

}  // namespace relpos::detail::forms
