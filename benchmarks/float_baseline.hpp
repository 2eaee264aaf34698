// Float baselines for relpos_bench: the library's generic formulas instantiated with a float type
// NT, and the decision table a user would write on top of the float signs (no certification). One
// home for them: src/oracle/float_rules.hpp, which `relpos judge` runs too.
#pragma once

#include <array>
#include <optional>

#include "oracle/float_rules.hpp"

namespace bench {

using namespace relpos;
using relpos::detail::oracle::float_classify;
using relpos::detail::oracle::Mat;
using relpos::detail::oracle::minimal_float;
using relpos::detail::oracle::naive_table;
using relpos::detail::oracle::usign;

/// The double and long double baselines, compiled in their own translation unit without
/// -frounding-math (naive_double.cpp): what a user's float code would be.
std::optional<Position> naive_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed);
std::optional<Position> naive_long_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed);
Position minimal_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed);

}  // namespace bench
