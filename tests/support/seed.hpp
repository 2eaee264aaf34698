// The seed of a test's random part: RELPOS_SEED=<n> reruns or varies it (decimal or 0x hex).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

namespace relpos::testing {

/// RELPOS_SEED when set and non-empty, else `fallback`.
inline std::uint64_t seed_from_env(std::uint64_t fallback) {
  const char* env = std::getenv("RELPOS_SEED");
  return env && *env ? std::strtoull(env, nullptr, 0) : fallback;
}

/// seed_from_env, printed once with the test's name so a failing run can be reproduced.
inline std::uint64_t announced_seed(const std::string& test, std::uint64_t fallback) {
  const std::uint64_t s = seed_from_env(fallback);
  std::cout << test << ": seed " << s << " (set RELPOS_SEED to rerun or vary it)" << std::endl;
  return s;
}

}  // namespace relpos::testing
