// Input and output of relpos in JSON: exact parsing of quadric descriptions and rendering of a
// Classification as a JSON object or as a human-readable report (doc/cli.md describes the formats).
//
// Exactness: JSON numbers are never read through a double. parse_json_exact() keeps the decimal
// text of every non-integer JSON number (0.1 is 1/10, not the nearest double), and every leaf is
// converted with relpos::parse_rational. Strings are accepted wherever a number is ("p/q", "-3",
// "1.5e-7"); booleans, null, NaN and infinities are rejected with the path of the field.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::io {

/// Deepest nesting of arrays and objects that parse_json_exact accepts.
inline constexpr std::size_t kMaxJsonDepth = 256;

/// Parse JSON text, keeping every floating-point JSON number as a string holding its original text
/// (integers stay integers: they are exact; numbers beyond the range of a double are kept as text
/// too). Throws relpos::InputError ("invalid JSON: ...") on malformed text or nesting deeper than
/// kMaxJsonDepth. Object keys keep their order.
nlohmann::ordered_json parse_json_exact(std::string_view text);

/// An exact number from a JSON value (integer, string as above, or a float kept as text by
/// parse_json_exact). `path` names the field in error messages, e.g. "ellipsoid.matrix[2][3]".
/// Throws InputError "<path>: expected a number, got true" and the like.
Rational rational_from_json(const nlohmann::ordered_json& value, const std::string& path);

/// Limits on the polynomials of a rigid motion (doc/cli.md, Limits): the event polynomials' degree
/// and coefficient sizes grow with these, and the cost with them.
inline constexpr std::size_t kMaxMotionDegree = 12;
inline constexpr std::size_t kMaxMotionCoefficientBits = 512;

/// The `count` polynomials in t of a rigid motion's translation (3) or quaternion (4), as
/// `relpos motion` and the Python package read them: a JSON array of `count` entries, each an array
/// of exact coefficients (lowest degree first) or one number (a constant); trailing zeros dropped.
/// Throws InputError naming the field (`role`[i][k]) on a non-number or beyond the limits above.
std::vector<std::vector<Rational>> motion_polynomials(const nlohmann::ordered_json& value, std::size_t count,
                                                      const std::string& role);

/// Quadric descriptions (doc/cli.md, "Quadric formats"). `role` prefixes every message and names
/// the field paths ("ellipsoid", "paraboloid"). Library errors (not an ellipsoid, singular map,
/// ...) are rethrown as InputError "<role>: <message>".
///   ellipsoid:  4x4 array | {"matrix"} | {"coefficients"} | {"sphere": {"center", "radius"}}
///               | {"center", "axes", "rotation" | "rotation_matrix"} | {"center", "map"}
///   paraboloid: 4x4 array | {"matrix"} | {"coefficients"} | {"vertex", "a", "b", "rotation"}
///               | {"map", "translation"}
/// Parse from a value obtained with parse_json_exact (a value from the ordinary parser would have
/// its floats rounded to doubles; those are then taken as the exact dyadic value of the double).
Ellipsoid ellipsoid_from_json(const nlohmann::ordered_json& value, const std::string& role = "ellipsoid");
Paraboloid paraboloid_from_json(const nlohmann::ordered_json& value, const std::string& role = "paraboloid");

/// One sentence saying what a position means ("the ellipsoid lies inside the paraboloid ...").
std::string position_meaning(Position p);

/// "<1", "=1", ">1".
std::string rho_vs_one_text(int sign);

/// Options for rendering.
struct RenderOptions {
  int digits = 12;  ///< significant digits of root and rho approximations
};

/// The JSON report of one classification (without "id"): position, small, contact, rho_vs_one, rho,
/// rho_approx, rule, stage, disc_sign, disc_ftilde_sign, roots, and with full
/// evidence degree_ftilde, f, s and multiple_roots. Key order is stable.
nlohmann::ordered_json classification_to_json(const Classification& c, const RenderOptions& options = {});

/// The same report as one line of JSON text: dump_json(classification_to_json(c, options)),
/// written directly (what `relpos classify --json`, `relpos batch` and the Python module print).
std::string classification_json_text(const Classification& c, const RenderOptions& options = {});

/// The minimal report of `relpos batch --evidence minimal` (without "id") as one line of JSON
/// text: position, small, contact, rule, stage (the Python package's classify(evidence="minimal")).
std::string minimal_json_text(const Verdict& v);

/// The contact-only answer (doc/contact.md): contact, position, rule, decided_by (decided_by(stage)).
nlohmann::ordered_json contact_to_json(const ContactAnswer& a);

/// A multi-line human-readable report (ends with a newline).
std::string classification_to_text(const Classification& c, const RenderOptions& options = {});

/// A polynomial with exact coefficients (index = power) as text: "3*l^4 - 1/2*l^2 + 7".
std::string polynomial_to_text(const Rational* coefficients, int size, const std::string& variable = "l");

// ------------------------------------------------------------------------------------------------
// Batch lines: the answer to one JSON Lines input line, as `relpos batch` writes it (doc/cli.md,
// "relpos batch"); its reader is internal (src/io/batch.hpp).

/// Default longest input line (--max-line-bytes): 64 MiB.
inline constexpr std::size_t kDefaultMaxLineBytes = std::size_t(64) << 20;

struct BatchOptions {
  Evidence evidence = Evidence::Full;  ///< Minimal: id, position, small, contact, rule, stage only
  bool contact_only = false;           ///< the contact answer of doc/contact.md
  bool numbers_as_doubles = false;     ///< each JSON number is the IEEE double nearest its text
  std::size_t max_line_bytes = kDefaultMaxLineBytes;
  SizeLimit size_limit;  ///< the pair size limit (--max-bits)
  RenderOptions render;
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

/// A JSON value as one line of text, invalid UTF-8 replaced by U+FFFD (the one JSON writer).
std::string dump_json(const nlohmann::ordered_json& value);

}  // namespace relpos::io

namespace relpos {

/// The JSON form of a certificate (doc/certificates.md): numbers as exact strings ("3/4", "-2").
///   None         null
///   Definite     {"lambda": q}
///   Tangent      {"lambda": q, "contact": [x, y, z]}
///   HardTangent  {"lambda": {"a": q, "b": q, "d": n},
///                 "contact_set": {"center": [{"a", "b"} x3], "directions": [[{"a", "b"} x3], ...],
///                                 "radius2": {"a", "b"},
///                                 "decimal": {"lambda", "center": [3], "radius2"}}}
///   Crossing     {"inside": [x, y, z], "outside": [x, y, z]}
/// "decimal" holds `digits` significant digits for humans and is ignored by certificate_from_json.
nlohmann::ordered_json certificate_to_json(const Certificate& c, int digits = 12);
/// The inverse of certificate_to_json (numbers also accepted as JSON numbers, read exactly). Throws
/// relpos::InputError naming the field on malformed input (unknown or missing keys, wrong types,
/// non-numbers, d not a non-negative integer).
Certificate certificate_from_json(const nlohmann::ordered_json& j);

}  // namespace relpos
