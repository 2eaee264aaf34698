#include "io/motion_json.hpp"

#include <gmp.h>

#include <algorithm>

#include "io/json_values.hpp"
#include "relpos/error.hpp"

namespace relpos::detail::io {

std::vector<std::vector<Rational>> motion_polynomials(const Json& v, std::size_t count, const std::string& role) {
  if (!v.is_array() || v.size() != count)
    throw InputError(role + ": expected an array of " + std::to_string(count) +
                     " polynomials (arrays of coefficients, lowest degree first)");
  std::vector<std::vector<Rational>> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::string path = index_path(role, i);
    if (v[i].is_array()) {
      for (std::size_t k = 0; k < v[i].size(); ++k) out[i].push_back(rational_from_json(v[i][k], index_path(path, k)));
    } else {
      out[i].push_back(rational_from_json(v[i], path));  // a constant
    }
    while (!out[i].empty() && out[i].back() == 0) out[i].pop_back();
    if (out[i].size() > kMaxMotionDegree + 1)
      throw InputError(path + ": degree " + std::to_string(out[i].size() - 1) + " is beyond the limit of " +
                       std::to_string(kMaxMotionDegree) + " (doc/cli.md, Limits)");
    for (std::size_t k = 0; k < out[i].size(); ++k) {
      const Rational& c = out[i][k];
      const std::size_t bits =
          std::max(mpz_sizeinbase(c.numerator().mpz(), 2), mpz_sizeinbase(c.denominator().mpz(), 2));
      if (bits > kMaxMotionCoefficientBits)
        throw InputError(index_path(path, k) + ": a " + std::to_string(bits) +
                         "-bit numerator or denominator, beyond the limit of " +
                         std::to_string(kMaxMotionCoefficientBits) + " bits (doc/cli.md, Limits)");
    }
  }
  return out;
}

}  // namespace relpos::detail::io
