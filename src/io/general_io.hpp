// JSON in and out for the general quadrics (doc/cli.md, "General quadrics"; math.md §14–§18): the
// "quadric" of a batch line or of `relpos classify --quadric`, the answers, and the certificates'
// JSON form, read back by `relpos verify`.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "relpos/general_classify.hpp"
#include "relpos/io.hpp"

namespace relpos::io {

/// A general quadric from a value of parse_json_exact: a 4x4 array, {"matrix"}, {"coefficients"},
/// or a geometric form {"type": NAME, ...} with NAME one of to_string(QuadricType) or "sphere":
///   sphere {"center", "radius"}; ellipsoid and the hyperboloids {"center", "axes", "rotation"?};
///   "elliptic cone" {"apex", "a", "b", "rotation"?}; the paraboloids {"vertex", "a", "b", "rotation"?};
///   the elliptic and hyperbolic cylinders {"center", "a", "b", "rotation"?}; "parabolic cylinder"
///   {"vertex", "a", "rotation"?}; "half-space" {"normal", "offset"}; "slab" {"normal", "low", "high"}.
/// InputError "<role>: ..." naming the field, or what the matrix is when it is refused.
Quadric quadric_from_json(const nlohmann::ordered_json& value, const std::string& role = "quadric");

/// The answer to a general pair (without "id"): position, contact, quadric_type, rule, stage, and with
/// `full` the exact f and d, the real roots (decimals with `digits` digits, multiplicities) and the
/// certificate.
nlohmann::ordered_json general_answer_json(const QuadricVerdict& v, const QuadricClassification* full, int digits);

/// The same pair as a multi-line report (relpos classify --quadric).
std::string general_answer_text(const QuadricClassification& c, int digits);

/// The JSON form of a general certificate (exact numbers as strings):
///   Definite {"t"}; Tangent {"t", "contact"}; HardTangent {"t": {"a", "b", "d"}, "contact_set":
///   {"center", "directions", "radius2", "decimal"}}; Crossing {"inside", "outside", "beyond"?};
///   Equal {"ratio"}.
nlohmann::ordered_json quadric_certificate_to_json(const QuadricCertificate& c, int digits);
/// The inverse (numbers also as JSON numbers, read exactly); InputError naming the field.
QuadricCertificate quadric_certificate_from_json(const nlohmann::ordered_json& j);

/// "I", "TI", ..., "EQ" back to the position, or nullopt.
std::optional<QuadricPosition> quadric_position_from_text(const std::string& s);

}  // namespace relpos::io
