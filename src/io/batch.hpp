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

namespace relpos::detail::io {

// The answer to one JSON Lines input line, as `relpos batch` writes it (doc/cli.md, "relpos batch"):
// the one batch-line function of the CLI, the Python package and the fuzzers (batch_answer.cpp).

/// Default longest input line (--max-line-bytes): 64 MiB.
inline constexpr std::size_t kDefaultMaxLineBytes = std::size_t(64) << 20;

struct BatchOptions {
  Evidence evidence = Evidence::Full;  ///< Minimal: id, position, small, contact, rule, stage only
  bool contact_only = false;           ///< the contact answer of doc/contact.md
  bool numbers_as_doubles = false;     ///< each JSON number is the IEEE double nearest its text
  std::size_t max_line_bytes = kDefaultMaxLineBytes;
  SizeLimit size_limit;  ///< the pair size limit (--max-bits)
  relpos::io::RenderOptions render;
  /// > 0: every answer ends with "margin" (margin.hpp, margin_json_text), its enclosure of relative
  /// width 2^-margin_bits; 0: no margin.
  int margin_bits = 0;
};

/// The error of a line that ran out of memory, and the error of one whose id could not even be
/// echoed: its id is then the line number (doc/cli.md, "Out of memory").
inline constexpr const char* kOutOfMemoryMessage = "out of memory while answering this line";
inline constexpr const char* kOutOfMemoryNoIdMessage =
    "out of memory while answering this line (its id is replaced by the line number)";

/// The one JSON output line (no newline) answering an input line of `relpos batch`: the
/// classification or {"id": ..., "error": "..."}. Out of memory on the line is that line's error.
/// Memory: the answer and small bounded parts; the id is not copied (doc/cli.md, "Memory").
std::string answer_batch_line(std::string_view line, long line_number, const BatchOptions& options);

/// The same line written into `out` (replacing its text, keeping its capacity: a caller answering
/// many lines reuses its buffers). Never throws: out of memory gives the line's error with the id,
/// else with the line number (kOutOfMemoryNoIdMessage), and `out` is left empty only when not even
/// that fits (a caller keeping some capacity in `out` never sees it).
void answer_batch_line(std::string_view line, long line_number, const BatchOptions& options, std::string& out);
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

}  // namespace relpos::detail::io
