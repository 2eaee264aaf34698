// A positive integer scale split as 2^twos 5^fives rest: 2 and 5 are what doubles and decimal text
// put in denominators, so dividing by a power of the scale (divided_by_powers.hpp) takes them by a
// bit scan and single-limb remainders, and the rest by gcds with its short coprime factors.
#pragma once

#include <vector>

#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::forms {

/// A positive integer scale split as 2^twos 5^fives rest, and rest^k for the powers a caller
/// divides by. The rest is also kept as a product of pairwise coprime factors base^power (one
/// factor, rest itself, unless the scale was split along its denominators), so that a gcd with it
/// is a gcd with a short base.
struct SplitScale {
  struct Factor {
    Integer base;
    unsigned long power = 1;
  };
  unsigned long twos = 0, fives = 0;
  Integer rest{1};
  std::vector<Integer> rest_power;  ///< rest^k for k = 0..4; empty for rest 1 (doubles, decimal text)
  std::vector<Factor> factors;      ///< rest = prod base^power, bases pairwise coprime; empty for rest 1
};

/// Splits a positive integer.
SplitScale split_scale(const Integer& scale);

/// Splits scale = the lcm of the denominators of m's entries (integer_form), its rest kept as a
/// coprime base of those denominators' rests (square ones by their roots), with the lcm's powers:
/// for a standard paraboloid with decimal a and b, the rest of lcm(den(1/a^2), den(1/b^2)) becomes
/// ma^2 mb^2 (or ma'^2 c^2 mb'^2 when ma and mb share c) with one-limb bases instead of one
/// four-limb number.
SplitScale split_scale(const Integer& scale, const Matrix4& m);

/// split_scale(scale, m) from parts of the scale its caller knows: scale = 2^twos 5^fives rest, rest
/// prime to 10 and the lcm of `rests`, the distinct rests of m's denominators (2s and 5s removed), each
/// base^power with power 2 for a square.
SplitScale split_scale(unsigned long twos, unsigned long fives, const Integer& rest,
                       const std::vector<SplitScale::Factor>& rests);

}  // namespace relpos::detail::forms
