// The JSON form of a margin (include/relpos/margin.hpp; doc/certificates.md, "Margins"), written by the
// one JSON writer of the reports (json_write.hpp) and read back with exact numbers.
#pragma once

#include <nlohmann/json.hpp>

#include "io/json_write.hpp"
#include "relpos/margin.hpp"

namespace relpos::io::detail {

/// {"approx": <double>, "lo": "p/q", "hi": "p/q", "polynomial": ["c0", ...], then "below" and
/// "above" (lo < hi) or "at" (lo == hi > 0), certificates as append_certificate writes them}.
void append_margin(const Margin& m, int digits, JsonWriter& w);

/// The inverse of append_margin on a value parsed by parse_json_exact (approx: the double nearest its
/// decimal text). Throws InputError naming the field ("margin.lo: ...").
Margin margin_from_json(const nlohmann::ordered_json& j);

}  // namespace relpos::io::detail
