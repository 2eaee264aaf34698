#include "io/json_values.hpp"

#include <array>

#include "relpos/error.hpp"

namespace relpos::detail::io {
namespace {

template <std::size_t N>
std::array<Rational, N> vector_of(const Json& v, const std::string& path, const char* what) {
  array_of(v, N, path, what);
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = rational_from_json(v[i], index_path(path, i));
  return out;
}

/// An N x N matrix of exact numbers (Matrix4 or Matrix3), row by row, each entry's path in messages.
template <class M, std::size_t N>
M square_matrix(const Json& v, const std::string& path, const char* what, const char* row_what) {
  array_of(v, N, path, what);
  M m;
  for (std::size_t i = 0; i < N; ++i) {
    const std::string row = index_path(path, i);
    array_of(v[i], N, row, row_what);
    for (std::size_t j = 0; j < N; ++j)
      m(static_cast<int>(i), static_cast<int>(j)) = rational_from_json(v[i][j], index_path(row, j));
  }
  return m;
}

}  // namespace

std::string shorten(const std::string& s, std::size_t limit) {
  if (s.size() <= limit) return s;
  return s.substr(0, limit) + "...";
}

std::string describe(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case Json::value_t::string:
      return "a string \"" + shorten(v.get_ref<const std::string&>()) + "\"";
    case Json::value_t::array: {
      const auto n = v.size();
      return "an array of " + std::to_string(n) + (n == 1 ? " element" : " elements");
    }
    case Json::value_t::object:
      return "an object";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    case Json::value_t::binary:
    case Json::value_t::discarded:
      break;
  }
  return "an unsupported value";
}

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw InputError(path + ": " + message); }

std::string index_path(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::string key_path(const std::string& path, const std::string& key) { return path + "." + key; }

const Json& array_of(const Json& v, std::size_t n, const std::string& path, const char* what) {
  if (!v.is_array() || v.size() != n) fail(path, std::string("expected ") + what + ", got " + describe(v));
  return v;
}

Vector3 vector3(const Json& v, const std::string& path) { return vector_of<3>(v, path, "an array of 3 numbers"); }

Matrix4 matrix4(const Json& v, const std::string& path) {
  return square_matrix<Matrix4, 4>(v, path, "a 4x4 array (4 rows of 4 numbers)", "a row of 4 numbers");
}

Matrix3 matrix3(const Json& v, const std::string& path) {
  return square_matrix<Matrix3, 3>(v, path, "a 3x3 array (3 rows of 3 numbers)", "a row of 3 numbers");
}

Coefficients10 coefficients10(const Json& v, const std::string& path) {
  return vector_of<10>(v, path, "an array of 10 coefficients [A,B,C,D,E,F,G,H,I,J]");
}

Quaternion quaternion(const Json& v, const std::string& path) {
  return vector_of<4>(v, path, "a quaternion [w,x,y,z]");
}

void check_keys(const Json& obj, std::initializer_list<const char*> allowed, const std::string& path) {
  for (const auto& item : obj.items()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || item.key() == a;
    if (ok) continue;
    std::string list;
    for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + "\"" + a + "\"";
    fail(path, "unknown key \"" + shorten(item.key()) + "\" (this form takes " + list + ")");
  }
}

const Json& required(const Json& obj, const char* key, const std::string& path) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(key_path(path, key), "missing");
  return *it;
}

std::pair<const Json*, std::string> center_field(const Json& obj, const std::string& path) {
  const bool us = obj.contains("center"), uk = obj.contains("centre");
  if (us && uk) fail(path, "both \"center\" and \"centre\" given");
  if (uk) return {&obj["centre"], key_path(path, "centre")};
  if (us) return {&obj["center"], key_path(path, "center")};
  fail(key_path(path, "center"), "missing");
}

std::string key_list(const Json& obj) {
  if (obj.empty()) return "an empty object";
  std::string list;
  for (const auto& item : obj.items())
    list += std::string(list.empty() ? "" : ", ") + "\"" + shorten(item.key()) + "\"";
  return "keys " + list;
}

Rational rational_from_json(const Json& v, const std::string& path) {
  switch (v.type()) {
    case Json::value_t::number_integer:
      return parse_rational(std::to_string(v.get<Json::number_integer_t>()));
    case Json::value_t::number_unsigned:
      return parse_rational(std::to_string(v.get<Json::number_unsigned_t>()));
    case Json::value_t::number_float:
      // Only from a document not built by parse_json_exact: the double is all that is left.
      try {
        return exact_rational(v.get<double>());
      } catch (const InputError& e) {
        fail(path, e.what());
      }
    case Json::value_t::string:
      try {
        return parse_rational(v.get_ref<const std::string&>());
      } catch (const InputError& e) {
        fail(path, e.what());
      }
    default:
      fail(path, "expected a number, got " + describe(v));
  }
}

}  // namespace relpos::detail::io
