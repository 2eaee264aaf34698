// JSON trees with exact numbers (private: the CLI, the Python module and the tests reach them; the
// public API takes and gives JSON text, include/relpos/io.hpp). Every number keeps its decimal text
// (never a double), duplicate keys are refused, the nesting is bounded (kMaxJsonDepth), and content
// that is only validated is read by a pass that stores nothing.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "relpos/error.hpp"

namespace relpos::detail::io {

using Json = nlohmann::ordered_json;

/// Text that is not JSON (the other InputErrors of these functions are limits).
struct JsonSyntaxError : InputError {
  using InputError::InputError;
};

struct JsonReadOptions {
  bool doubles = false;          ///< every number is the IEEE double nearest its text (--numbers double)
  std::size_t max_elements = 0;  ///< entries per array or object (0: no limit)
  std::size_t start_depth = 0;   ///< nesting already entered (a value inside a line's object)
};

/// JSON text as a tree, keeping every floating-point JSON number as a string holding its original
/// text (integers stay integers: they are exact; numbers beyond the range of a double are kept as
/// text too). Object keys keep their order. Throws JsonSyntaxError ("invalid JSON: ...") on
/// malformed text, InputError on nesting deeper than kMaxJsonDepth or beyond the options' limits.
Json parse_json(std::string_view text, const JsonReadOptions& options);

/// parse_json with the default options: the exact tree of any JSON text.
inline Json parse_json_exact(std::string_view text) { return parse_json(text, JsonReadOptions{}); }

/// Throws InputError "invalid JSON: ..." unless text is one JSON value; stores nothing.
void validate_json(std::string_view text, std::size_t start_depth = 0);

/// A JSON value as one line of text, invalid UTF-8 replaced by U+FFFD.
std::string dump_json(const Json& value);

/// Deepest nesting of arrays and objects that the JSON reader accepts.
inline constexpr std::size_t kMaxJsonDepth = 256;

}  // namespace relpos::detail::io
