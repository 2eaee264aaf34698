// The pieces of a batch line (internal): the reader shared by `relpos batch`, the JSON Lines input of
// `relpos scene`, `relpos verify` and the fuzzer (batch.cpp); the answer to a line is io.hpp's
// answer_batch_line (batch_answer.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "relpos/general_quadric.hpp"
#include "relpos/io.hpp"
#include "relpos/quadric.hpp"

namespace relpos::io {

class GeneralPairSize;  // general_io.hpp

/// One input line, read: the id as the JSON text to echo, and the quadrics.
struct BatchLine {
  std::string id;    ///< the id's JSON text exactly as in the input, or the line number
  std::string meta;  ///< the "meta" member's JSON text exactly as in the input, or empty (doc/cli.md)
  std::optional<Ellipsoid> ellipsoid;
  std::optional<Paraboloid> paraboloid;
  std::optional<Quadric> quadric;  ///< a general quadric in place of the paraboloid (doc/quadrics.md)
};

/// "line too long: more than N bytes (--max-line-bytes)", the refusal of a line beyond the limit.
std::string too_long_message(std::size_t max_line_bytes);

/// The line without what every input format ignores: a UTF-8 byte order mark on line 1 and one
/// trailing '\r'. Throws InputError for a line longer than max_line_bytes, a byte order mark on a
/// later line, or a NUL byte (the message names the column).
std::string_view normalize_line(std::string_view line, long line_number, std::size_t max_line_bytes);

/// Read one JSON Lines line {"id", "ellipsoid", "paraboloid", "comment", "meta"} (with `fixed`, a scene
/// line: {"id", "ellipsoid", "comment", "meta"}, and the size limit is checked against *fixed). The top-level
/// object is scanned once: the id's text is kept, "comment" is validated without being stored,
/// duplicate keys are refused. out.id is set (to the line number at first, to the id once it is
/// read) before any InputError is thrown, so that errors echo the id; out's quadrics are the line's
/// only when nothing is thrown. With `id`, the id is not copied into out.id: *id is set to its text
/// instead (a view into `line`, or of out.id), before anything is thrown; the same for `meta` and
/// out.meta (set once the members are scanned: empty before, and when the line has none).
void read_batch_line(std::string_view line, long line_number, const BatchOptions& options, const Paraboloid* fixed,
                     BatchLine& out, std::string_view* id = nullptr, std::string_view* meta = nullptr);
/// The same for a scene line against a general quadric (doc/cli.md, "relpos scene"): out.ellipsoid
/// only, the size limit checked against the quadric by `fixed` (general_io.hpp).
void read_batch_line(std::string_view line, long line_number, const BatchOptions& options, const GeneralPairSize& fixed,
                     BatchLine& out, std::string_view* id = nullptr, std::string_view* meta = nullptr);

}  // namespace relpos::io
