// The double and long double baselines in their own translation unit, compiled without
// -frounding-math (benchmarks/CMakeLists.txt): the code a user would write, with every
// optimisation the compiler may apply to plain float code.
#include "float_baseline.hpp"

namespace bench {

std::optional<Position> naive_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  return float_classify<double>(pd, ed, [](double d) { return d; });
}

std::optional<Position> naive_long_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  return float_classify<long double>(pd, ed, [](double d) { return static_cast<long double>(d); });
}

Position minimal_double(const std::array<double, 16>& pd, const std::array<double, 16>& ed) {
  return minimal_float<double>(pd, ed);
}

}  // namespace bench
