// A polynomial with exact coefficients as text, e.g. "3*l^4 - 1/2*l^2 + 7": written once for the
// rational polynomials of the reports (io.hpp) and the integer polynomials of instants
// (algebraic_real.hpp).
#pragma once

#include <cstddef>
#include <string>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// c[0], ..., c[size - 1] are the coefficients of 1, x, ..., x^(size - 1); zero terms are left out,
/// a unit coefficient is written only on the constant term, and the zero polynomial is "0".
template <class T>
std::string polynomial_text(const T* c, std::size_t size, const std::string& variable) {
  std::string out;
  for (std::size_t k = size; k-- > 0;) {
    if (c[k] == 0) continue;
    const bool neg = c[k] < 0;
    const T mag = neg ? T(-c[k]) : c[k];
    out += out.empty() ? (neg ? "-" : "") : (neg ? " - " : " + ");
    const bool one = mag == 1;
    if (!one || k == 0) out += to_string(mag);
    if (k > 0) {
      if (!one) out += "*";
      out += variable;
      if (k > 1) out += "^" + std::to_string(k);
    }
  }
  return out.empty() ? "0" : out;
}

}  // namespace relpos::detail
