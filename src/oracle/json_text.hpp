// The oracle's JSON: members in the order written, and text with any invalid UTF-8 of a user's line
// (an id, a meta member) replaced rather than refused, so that a report can always be written.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace relpos::detail::oracle {

using Json = nlohmann::ordered_json;

/// One line of JSON text.
inline std::string dump(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace relpos::detail::oracle
