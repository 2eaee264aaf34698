// Certified decimals of a classification's real roots, for its reports (text and JSON): an exact
// root rounded exactly, the others isolated on f's integer form to the digits asked.
#pragma once

#include <string>
#include <vector>

#include "relpos/classify.hpp"

namespace relpos::detail::io {

/// One certified decimal per entry of c.roots; with only_multiple, only for the roots of
/// multiplicity >= 2 (the others are left empty).
std::vector<std::string> root_decimals(const Classification& c, int digits, bool only_multiple);

}  // namespace relpos::detail::io
