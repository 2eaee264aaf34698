// Input and output of relpos as text: exact reading of quadric descriptions given as JSON text, and
// the rendering of a Classification as a JSON object or as a human-readable report (doc/cli.md
// describes the formats). Text in, text out: no JSON library type appears here.
//
// Exactness: JSON numbers are never read through a double. Every non-integer JSON number is read
// from its decimal text (0.1 is 1/10, not the nearest double), and every leaf is converted with
// relpos::parse_rational. Strings are accepted wherever a number is ("p/q", "-3", "1.5e-7");
// booleans, null, NaN and infinities are rejected with the path of the field.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/margin.hpp"
#include "relpos/numbers.hpp"
#include "relpos/position.hpp"
#include "relpos/quadric.hpp"

namespace relpos::io {

/// Quadric descriptions given as JSON text (doc/cli.md, "Quadric formats"). `role` prefixes every
/// message and names the field paths ("ellipsoid", "paraboloid"). Text that is not JSON, or nested
/// deeper than 256 levels, throws InputError "<role>: invalid JSON: ..."; library errors (not an
/// ellipsoid, singular map, ...) are rethrown as InputError "<role>: <message>".
///   ellipsoid:  4x4 array | {"matrix"} | {"coefficients"} | {"sphere": {"center", "radius"}}
///               | {"center", "axes", "rotation" | "rotation_matrix"} | {"center", "map"}
///   paraboloid: 4x4 array | {"matrix"} | {"coefficients"} | {"vertex", "a", "b", "rotation"}
///               | {"map", "translation"}
Ellipsoid ellipsoid_from_json(std::string_view json_text, const std::string& role = "ellipsoid");
Paraboloid paraboloid_from_json(std::string_view json_text, const std::string& role = "paraboloid");

/// Options for rendering.
struct RenderOptions {
  int digits = 12;  ///< significant digits of root and rho approximations
};

/// The JSON report of one classification as one line of text (what `relpos classify --json`,
/// `relpos batch` and the Python module print, without "id"): position, small, contact, rho_vs_one,
/// rho, rho_approx, rule, stage, disc_sign, disc_ftilde_sign, roots, and with full evidence
/// degree_ftilde, f, s, multiple_roots and certificate. Key order is stable.
std::string classification_json_text(const Classification& c, const RenderOptions& options = {});

/// The contact-only answer (doc/contact.md) as one line of JSON text: contact, position, rule,
/// decided_by (decided_by(stage)).
std::string contact_json_text(const ContactAnswer& a);

/// A multi-line human-readable report (ends with a newline).
std::string classification_to_text(const Classification& c, const RenderOptions& options = {});

/// The JSON text of a margin (doc/certificates.md, "Margins"): {"approx": <double>, "lo": "p/q",
/// "hi": "p/q", "polynomial": ["c0", "c1", ...], and "below" and "above" (lo < hi) or "at" (lo == hi >
/// 0): certificates as certificate_json_text writes them}. `digits`: the hard case's "decimal".
std::string margin_json_text(const Margin& m, int digits = 12);
/// The inverse (numbers read exactly, approx as the double nearest its text). Throws InputError
/// naming the field on malformed text.
Margin margin_from_json_text(std::string_view text);

}  // namespace relpos::io

namespace relpos {

/// The JSON form of a certificate (doc/certificates.md) as text: numbers as exact strings ("3/4", "-2").
///   None         null
///   Definite     {"lambda": q}
///   Tangent      {"lambda": q, "contact": [x, y, z]}
///   HardTangent  {"lambda": {"a": q, "b": q, "d": n},
///                 "contact_set": {"center": [{"a", "b"} x3], "directions": [[{"a", "b"} x3], ...],
///                                 "radius2": {"a", "b"},
///                                 "decimal": {"lambda", "center": [3], "radius2"}}}
///   Crossing     {"inside": [x, y, z], "outside": [x, y, z]}
/// "decimal" holds `digits` significant digits for humans and is ignored by certificate_from_json.
std::string certificate_json_text(const Certificate& c, int digits = 12);
/// The inverse of certificate_json_text (numbers also accepted as JSON numbers, read exactly). Throws
/// relpos::InputError on text that is not JSON, and naming the field on malformed input (unknown or
/// missing keys, wrong types, non-numbers, d not a non-negative integer).
Certificate certificate_from_json(std::string_view json_text);

}  // namespace relpos
