// The JSON form of certificates (doc/certificates.md), private side: written into an answer by the
// answer writer, read from a tree by `relpos verify`; the public text functions are in io.hpp.
#pragma once

#include "io/json_tree.hpp"
#include "io/json_write.hpp"
#include "relpos/position.hpp"

namespace relpos::detail::io {

/// The certificate's JSON value (certificate_json_text describes it).
void append_certificate(const Certificate& c, int digits, JsonWriter& w);

/// The certificate of a JSON value (certificate_from_json describes it). Throws relpos::InputError
/// naming the field on malformed input.
Certificate certificate_from_tree(const Json& j);

}  // namespace relpos::detail::io
