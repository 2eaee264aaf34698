// Values read from exact JSON trees (json_tree.hpp), every failure an InputError naming the field's
// path ("ellipsoid.matrix[2][3]: expected a number, got true"): numbers, vectors, matrices,
// quaternions, and the checks of an object's keys. The readers of quadrics, motions and
// certificates are written with these.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>

#include "io/json_tree.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::io {

/// An exact number from a JSON value (integer, string such as "p/q", "-3", "1.5e-7", or a float kept
/// as text by parse_json). Throws InputError "<path>: expected a number, got true" and the like.
Rational rational_from_json(const Json& value, const std::string& path);

/// The first `limit` characters of s, and "..." when there were more.
std::string shorten(const std::string& s, std::size_t limit = 40);
/// What a JSON value is, for messages: "true", "null", "an array of 3 elements", "a string "x"".
std::string describe(const Json& v);
[[noreturn]] void fail(const std::string& path, const std::string& message);
std::string index_path(const std::string& path, std::size_t i);
std::string key_path(const std::string& path, const std::string& key);

/// An array of exactly n entries (fails naming the path otherwise).
const Json& array_of(const Json& v, std::size_t n, const std::string& path, const char* what);
Vector3 vector3(const Json& v, const std::string& path);
Matrix4 matrix4(const Json& v, const std::string& path);
Matrix3 matrix3(const Json& v, const std::string& path);
Coefficients10 coefficients10(const Json& v, const std::string& path);
Quaternion quaternion(const Json& v, const std::string& path);

/// Every key of the object must be one of `allowed`.
void check_keys(const Json& obj, std::initializer_list<const char*> allowed, const std::string& path);
/// The member `key`, or fails "<path>.<key>: missing".
const Json& required(const Json& obj, const char* key, const std::string& path);
/// "center", or its spelling "centre"; the key actually used goes into the path.
std::pair<const Json*, std::string> center_field(const Json& obj, const std::string& path);
/// "keys "a", "b"" or "an empty object", for messages.
std::string key_list(const Json& obj);

}  // namespace relpos::detail::io
