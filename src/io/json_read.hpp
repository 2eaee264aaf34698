// Private JSON reading of src/io (io.cpp, batch.cpp): exact numbers, duplicate keys rejected,
// bounded DOMs, and validation without a DOM for ignored content.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string_view>

#include "relpos/error.hpp"

namespace relpos::io::detail {

/// Text that is not JSON (the other InputErrors of these functions are limits).
struct JsonSyntaxError : InputError {
  using InputError::InputError;
};

struct JsonReadOptions {
  bool doubles = false;          ///< every number is the IEEE double nearest its text (--numbers double)
  std::size_t max_elements = 0;  ///< entries per array or object (0: no limit)
  std::size_t start_depth = 0;   ///< nesting already entered (a value inside a line's object)
};

/// parse_json_exact with options; throws JsonSyntaxError "invalid JSON: ...".
nlohmann::ordered_json parse_json(std::string_view text, const JsonReadOptions& options);

/// Throws InputError "invalid JSON: ..." unless text is one JSON value; stores nothing.
void validate_json(std::string_view text, std::size_t start_depth = 0);

}  // namespace relpos::io::detail
