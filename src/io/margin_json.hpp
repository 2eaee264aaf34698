// The JSON form of a margin (include/relpos/margin.hpp; doc/certificates.md, "Margins"), private
// side: written into an answer by the answer writer (answer_json.hpp, append_margin_member), read
// from an exact tree by `relpos verify`; the public text functions are in io.hpp.
#pragma once

#include "io/json_tree.hpp"
#include "io/json_write.hpp"
#include "relpos/margin.hpp"

namespace relpos::detail::io {

/// {"approx": <double>, "lo": "p/q", "hi": "p/q", "polynomial": ["c0", ...], then "below" and
/// "above" (lo < hi) or "at" (lo == hi > 0), certificates as append_certificate writes them}.
void append_margin(const Margin& m, int digits, JsonWriter& w);

/// The inverse of append_margin on an exact tree (parse_json_exact; approx: the double nearest its
/// decimal text, null for +infinity). Throws InputError naming the field ("margin.lo: ...").
Margin margin_from_tree(const Json& j);

}  // namespace relpos::detail::io
