// float_rules.hpp's baselines, compiled without -frounding-math (CMakeLists.txt): the code a user
// would write, with every optimisation the compiler may apply to plain float code.
#include "oracle/float_rules.hpp"

namespace relpos::detail::oracle {

std::optional<Position> paper_rule_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  return float_classify<double>(pd, ed, [](double d) { return d; });
}

std::optional<Position> paper_rule_long_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  return float_classify<long double>(pd, ed, [](double d) { return static_cast<long double>(d); });
}

Position minimal_rule_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  return minimal_float<double>(pd, ed);
}

}  // namespace relpos::detail::oracle
