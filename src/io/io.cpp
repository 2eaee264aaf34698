#include "relpos/io.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <utility>
#include <vector>

#include "algebra/cramer.hpp"
#include "algebra/forms.hpp"
#include "algebra/polynomial_text.hpp"
#include "algebra/roots.hpp"
#include "decide/stages.hpp"
#include "io/json_read.hpp"
#include "io/json_write.hpp"
#include "relpos/error.hpp"

namespace relpos::io {
namespace {

using Json = nlohmann::ordered_json;

/// "[json.exception.parse_error.101] parse error at ..." -> "parse error at ...".
std::string strip_exception_prefix(const std::string& what) {
  if (!what.empty() && what[0] == '[') {
    auto close = what.find("] ");
    if (close != std::string::npos) return what.substr(close + 2);
  }
  return what;
}

/// The nesting depth of a parse, limited to kMaxJsonDepth: copying and printing a JSON value recurse,
/// so a line of 100000 '[' would otherwise overflow the stack when its "id" is echoed.
class DepthLimit {
 protected:
  explicit DepthLimit(std::size_t start_depth) : depth_(start_depth) {}
  bool enter() {
    if (++depth_ > kMaxJsonDepth)
      throw InputError("invalid JSON: nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  }
  bool leave() {
    --depth_;
    return true;
  }

 private:
  std::size_t depth_;
};

/// The DOM builder of nlohmann::json, except that a floating-point number is stored as a string
/// holding its original text (the lexer hands the text to the SAX callback), so that no number is
/// ever rounded to a double; with `doubles`, every number becomes the exact value of the IEEE double
/// nearest its text instead. Duplicate keys are rejected; with max_elements, so are arrays and
/// objects of more entries (a quadric needs at most 16), which bounds the DOM of a batch line.
class ExactSax : public nlohmann::detail::json_sax_dom_parser<Json>, DepthLimit {
 public:
  using Base = nlohmann::detail::json_sax_dom_parser<Json>;
  ExactSax(Json& document, const detail::JsonReadOptions& options)
      : Base(document, /*allow_exceptions=*/true), DepthLimit(options.start_depth), options_(options) {}
  bool number_float(Json::number_float_t rounded, const Json::string_t& text) {
    if (!counted()) return false;
    Json::string_t copy = options_.doubles ? double_text(rounded) : text;
    return Base::string(copy);
  }
  bool number_integer(Json::number_integer_t v) {
    if (!counted()) return false;
    if (options_.doubles && (v > (std::int64_t(1) << 53) || v < -(std::int64_t(1) << 53))) {
      Json::string_t copy = double_text(static_cast<double>(v));
      return Base::string(copy);
    }
    return Base::number_integer(v);
  }
  bool number_unsigned(Json::number_unsigned_t v) {
    if (!counted()) return false;
    if (options_.doubles && v > (std::uint64_t(1) << 53)) {
      Json::string_t copy = double_text(static_cast<double>(v));
      return Base::string(copy);
    }
    return Base::number_unsigned(v);
  }
  bool null() { return counted() && Base::null(); }
  bool boolean(bool v) { return counted() && Base::boolean(v); }
  bool string(Json::string_t& v) { return counted() && Base::string(v); }
  bool key(Json::string_t& k) {
    auto& keys = keys_.back();
    if (std::find(keys.begin(), keys.end(), k) != keys.end())
      throw InputError("invalid JSON: duplicate key \"" + (k.size() > 40 ? k.substr(0, 40) + "..." : k) + "\"");
    keys.push_back(k);
    return Base::key(k);
  }
  // Nesting is limited (DepthLimit).
  bool start_object(std::size_t n) { return open() && Base::start_object(n); }
  bool end_object() { return close() && Base::end_object(); }
  bool start_array(std::size_t n) { return open() && Base::start_array(n); }
  bool end_array() { return close() && Base::end_array(); }

 private:
  static Json::string_t double_text(double d) {
    if (!std::isfinite(d)) return "inf";  // parse_rational rejects it with the field's path
    return to_string(exact_rational(d));
  }
  /// One more entry in the innermost array or object.
  bool counted() {
    if (!counts_.empty() && options_.max_elements != 0 && ++counts_.back() > options_.max_elements)
      throw InputError("an array or object of more than " + std::to_string(options_.max_elements) +
                       " entries (a quadric needs at most 16: a 4x4 matrix)");
    return true;
  }
  /// A new array or object: counted in its parent, one level deeper, with its own keys and count.
  bool open() {
    if (!counted() || !enter()) return false;
    keys_.emplace_back();
    counts_.push_back(0);
    return true;
  }
  bool close() {
    keys_.pop_back();
    counts_.pop_back();
    return leave();
  }
  detail::JsonReadOptions options_;
  std::vector<std::vector<std::string>> keys_;
  std::vector<std::size_t> counts_;
};

/// Validates JSON without storing anything (memory independent of the text's size): ignored content.
class ValidatingSax : public nlohmann::json_sax<Json>, DepthLimit {
 public:
  explicit ValidatingSax(std::size_t start_depth) : DepthLimit(start_depth) {}
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return enter(); }
  bool key(string_t&) override { return true; }
  bool end_object() override { return leave(); }
  bool start_array(std::size_t) override { return enter(); }
  bool end_array() override { return leave(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    if (e.id == 406) {  // a number beyond double range: nlohmann stops here
      overflow = true;
      return false;
    }
    throw detail::JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()));
  }
  bool overflow = false;  ///< a number beyond double range stopped the parse (valid JSON so far)
};

std::string shorten(const std::string& s, std::size_t limit = 40) {
  if (s.size() <= limit) return s;
  return s.substr(0, limit) + "...";
}

/// What a JSON value is, for messages: "true", "null", "an array of 3 elements", "a string "x"".
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

/// An array of exactly n entries (fails naming the path otherwise).
const Json& array_of(const Json& v, std::size_t n, const std::string& path, const char* what) {
  if (!v.is_array() || v.size() != n) fail(path, std::string("expected ") + what + ", got " + describe(v));
  return v;
}

template <std::size_t N>
std::array<Rational, N> vector_of(const Json& v, const std::string& path, const char* what) {
  array_of(v, N, path, what);
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = rational_from_json(v[i], index_path(path, i));
  return out;
}

Vector3 vector3(const Json& v, const std::string& path) { return vector_of<3>(v, path, "an array of 3 numbers"); }

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

/// Every key of the object must be one of `allowed`.
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

/// "center", or its spelling "centre"; the key actually used goes into the path.
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

/// Length of a JSON number token (RFC 8259 grammar) at the start of s, or 0 if there is none.
std::size_t json_number_length(std::string_view s) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - start;
  };
  if (i < s.size() && s[i] == '-') ++i;
  if (i < s.size() && s[i] == '0')
    ++i;
  else if (digits() == 0)
    return 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (digits() == 0) return 0;
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return 0;
  }
  if (i < s.size() && std::string_view("0123456789.eE+-").find(s[i]) != std::string_view::npos) return 0;
  return i;
}

/// The text with every well-formed JSON number outside strings turned into a string holding it.
/// Malformed tokens are left alone for the parser to report.
std::string quote_numbers(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 16);
  bool in_string = false;
  for (std::size_t i = 0; i < text.size();) {
    const char ch = text[i];
    if (in_string) {
      out += ch;
      if (ch == '\\' && i + 1 < text.size()) {
        out += text[i + 1];
        i += 2;
        continue;
      }
      if (ch == '"') in_string = false;
      ++i;
      continue;
    }
    if (ch == '"') {
      in_string = true;
      out += ch;
      ++i;
      continue;
    }
    if (ch == '-' || (ch >= '0' && ch <= '9')) {
      const std::string_view token = text.substr(i, json_number_length(text.substr(i)));
      if (!token.empty()) {
        // Floats and integers too long for 64 bits become strings; other integers stay as they are.
        const bool quote = token.find_first_of(".eE") != std::string_view::npos || token.size() > 18;
        if (quote) out += '"';
        out += token;
        if (quote) out += '"';
        i += token.size();
        continue;
      }
    }
    out += ch;
    ++i;
  }
  return out;
}

/// Run a library factory, prefixing its InputError with the role.
template <class F>
auto with_role(const std::string& role, F&& make) -> decltype(make()) {
  try {
    return make();
  } catch (const InputError& e) {
    throw InputError(role + ": " + e.what());
  }
}

/// Determinant of a symmetric 3x3 block given by its entries.
Rational det3(const Rational (&b)[3][3]) {
  return relpos::detail::det3<Rational>([&b](int i, int j) -> const Rational& { return b[i][j]; });
}

/// A paraboloid from a matrix or coefficients, whose 3x3 block is `block`: when the library refuses
/// it and the block has full rank, the likely cause is rounding (a paraboloid's block has rank 2, and
/// rounded decimals of a rotated one almost never keep it), so the message says so.
template <class F>
Paraboloid paraboloid_checked(const std::string& role, const Rational (&block)[3][3], F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    if (det3(block) == 0) throw InputError(role + ": " + e.what());
    throw InputError(role + ": " + e.what() +
                     "; its 3x3 block has full rank, so this is not a paraboloid as given: if the numbers are "
                     "rounded decimals of a paraboloid, rounding can break the shape - give it exactly by its "
                     "geometric form {\"vertex\", \"a\", \"b\", \"rotation\"} or {\"map\", \"translation\"}");
  }
}

Paraboloid paraboloid_from_matrix(const Matrix4& m, const std::string& role) {
  Rational block[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) block[i][j] = m(i, j);
  return paraboloid_checked(role, block, [&] { return Paraboloid::from_matrix(m); });
}

Paraboloid paraboloid_from_coefficients(const Coefficients10& c, const std::string& role) {
  const Rational half(1, 2);
  const Rational block[3][3] = {
      {c[0], c[3] * half, c[4] * half}, {c[3] * half, c[1], c[5] * half}, {c[4] * half, c[5] * half, c[2]}};
  return paraboloid_checked(role, block, [&] { return Paraboloid::from_coefficients(c); });
}

}  // namespace

namespace detail {

Json parse_json(std::string_view text, const JsonReadOptions& options) {
  Json root;
  try {
    ExactSax sax(root, options);
    Json::sax_parse(text.begin(), text.end(), &sax);
    return root;
  } catch (const nlohmann::json::out_of_range& e) {
    // "number overflow" (406): a number beyond the range of a double, which nlohmann checks before
    // handing us the text. Quote the number tokens and parse again; they are exact all the same.
    if (e.id != 406) throw detail::JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()));
    if (options.doubles) throw InputError("invalid JSON: a number beyond the range of a double (--numbers double)");
  } catch (const nlohmann::json::exception& e) {
    throw detail::JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()));
  }
  const std::string quoted = quote_numbers(text);
  root = Json();
  try {
    ExactSax sax(root, options);
    Json::sax_parse(quoted.begin(), quoted.end(), &sax);
  } catch (const nlohmann::json::exception& e) {
    throw detail::JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()) +
                                  " (columns counted after quoting the numbers beyond double range)");
  }
  return root;
}

void validate_json(std::string_view text, std::size_t start_depth) {
  ValidatingSax sax(start_depth);
  Json::sax_parse(text.begin(), text.end(), &sax);
  if (!sax.overflow) return;
  const std::string quoted = quote_numbers(text);  // rare: numbers beyond double range
  ValidatingSax again(start_depth);
  Json::sax_parse(quoted.begin(), quoted.end(), &again);
}

}  // namespace detail

Json parse_json_exact(std::string_view text) { return detail::parse_json(text, detail::JsonReadOptions{}); }

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

std::vector<std::vector<Rational>> motion_polynomials(const Json& v, std::size_t count, const std::string& role) {
  if (!v.is_array() || v.size() != count)
    throw InputError(role + ": expected an array of " + std::to_string(count) +
                     " polynomials (arrays of coefficients, lowest degree first)");
  std::vector<std::vector<Rational>> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::string path = index_path(role, i);
    if (v[i].is_array()) {
      for (std::size_t k = 0; k < v[i].size(); ++k) out[i].push_back(rational_from_json(v[i][k], index_path(path, k)));
    } else {
      out[i].push_back(rational_from_json(v[i], path));  // a constant
    }
    while (!out[i].empty() && out[i].back() == 0) out[i].pop_back();
    if (out[i].size() > kMaxMotionDegree + 1)
      throw InputError(path + ": degree " + std::to_string(out[i].size() - 1) + " is beyond the limit of " +
                       std::to_string(kMaxMotionDegree) + " (doc/cli.md, Limits)");
    for (std::size_t k = 0; k < out[i].size(); ++k) {
      const Rational& c = out[i][k];
      const std::size_t bits =
          std::max(mpz_sizeinbase(c.numerator().mpz(), 2), mpz_sizeinbase(c.denominator().mpz(), 2));
      if (bits > kMaxMotionCoefficientBits)
        throw InputError(index_path(path, k) + ": a " + std::to_string(bits) +
                         "-bit numerator or denominator, beyond the limit of " +
                         std::to_string(kMaxMotionCoefficientBits) + " bits (doc/cli.md, Limits)");
    }
  }
  return out;
}

Ellipsoid ellipsoid_from_json(const Json& v, const std::string& role) {
  if (v.is_array()) {
    Matrix4 m = matrix4(v, role);
    return with_role(role, [&] { return Ellipsoid::from_matrix(m); });
  }
  if (!v.is_object()) fail(role, "expected a 4x4 array or an object describing an ellipsoid, got " + describe(v));
  if (v.contains("matrix")) {
    check_keys(v, {"matrix"}, role);
    Matrix4 m = matrix4(v["matrix"], key_path(role, "matrix"));
    return with_role(role, [&] { return Ellipsoid::from_matrix(m); });
  }
  if (v.contains("coefficients")) {
    check_keys(v, {"coefficients"}, role);
    Coefficients10 c = coefficients10(v["coefficients"], key_path(role, "coefficients"));
    return with_role(role, [&] { return Ellipsoid::from_coefficients(c); });
  }
  if (v.contains("sphere")) {
    check_keys(v, {"sphere"}, role);
    const std::string path = key_path(role, "sphere");
    const Json& s = v["sphere"];
    if (!s.is_object()) fail(path, "expected an object {\"center\": [x,y,z], \"radius\": r}, got " + describe(s));
    check_keys(s, {"center", "centre", "radius"}, path);
    auto [cj, cpath] = center_field(s, path);
    Vector3 c = vector3(*cj, cpath);
    Rational r = rational_from_json(required(s, "radius", path), key_path(path, "radius"));
    return with_role(role, [&] { return Ellipsoid::sphere(c, r); });
  }
  if (v.contains("axes")) {
    check_keys(v, {"center", "centre", "axes", "rotation", "rotation_matrix"}, role);
    auto [cj, cpath] = center_field(v, role);
    Vector3 c = vector3(*cj, cpath);
    Vector3 axes = vector3(v["axes"], key_path(role, "axes"));
    if (v.contains("rotation") && v.contains("rotation_matrix"))
      fail(role, "give either \"rotation\" (a quaternion) or \"rotation_matrix\", not both");
    if (v.contains("rotation_matrix")) {
      Matrix3 r = matrix3(v["rotation_matrix"], key_path(role, "rotation_matrix"));
      return with_role(role, [&] { return Ellipsoid::from_axes(c, axes, r); });
    }
    Quaternion q{Rational(1), Rational(0), Rational(0), Rational(0)};
    if (v.contains("rotation")) q = quaternion(v["rotation"], key_path(role, "rotation"));
    return with_role(role, [&] { return Ellipsoid::from_axes(c, axes, q); });
  }
  if (v.contains("map")) {
    check_keys(v, {"center", "centre", "map"}, role);
    auto [cj, cpath] = center_field(v, role);
    Vector3 c = vector3(*cj, cpath);
    Matrix3 l = matrix3(v["map"], key_path(role, "map"));
    return with_role(role, [&] { return Ellipsoid::from_map(c, l); });
  }
  fail(role,
       "no recognized ellipsoid form in " + key_list(v) +
           " (expected a 4x4 array or an object with \"matrix\", \"coefficients\", \"sphere\", \"axes\" or \"map\")");
}

Paraboloid paraboloid_from_json(const Json& v, const std::string& role) {
  if (v.is_array()) {
    return paraboloid_from_matrix(matrix4(v, role), role);
  }
  if (!v.is_object())
    fail(role, "expected a 4x4 array or an object describing an elliptic paraboloid, got " + describe(v));
  if (v.contains("matrix")) {
    check_keys(v, {"matrix"}, role);
    return paraboloid_from_matrix(matrix4(v["matrix"], key_path(role, "matrix")), role);
  }
  if (v.contains("coefficients")) {
    check_keys(v, {"coefficients"}, role);
    return paraboloid_from_coefficients(coefficients10(v["coefficients"], key_path(role, "coefficients")), role);
  }
  if (v.contains("vertex") || v.contains("a") || v.contains("b")) {
    check_keys(v, {"vertex", "a", "b", "rotation"}, role);
    Vector3 vertex = vector3(required(v, "vertex", role), key_path(role, "vertex"));
    Rational a = rational_from_json(required(v, "a", role), key_path(role, "a"));
    Rational b = rational_from_json(required(v, "b", role), key_path(role, "b"));
    Quaternion q{Rational(1), Rational(0), Rational(0), Rational(0)};
    if (v.contains("rotation")) q = quaternion(v["rotation"], key_path(role, "rotation"));
    return with_role(role, [&] { return Paraboloid::standard(vertex, a, b, q); });
  }
  if (v.contains("map") || v.contains("translation")) {
    check_keys(v, {"map", "translation"}, role);
    Matrix3 t = matrix3(required(v, "map", role), key_path(role, "map"));
    Vector3 tr = vector3(required(v, "translation", role), key_path(role, "translation"));
    return with_role(role, [&] { return Paraboloid::from_map(t, tr); });
  }
  fail(role, "no recognized paraboloid form in " + key_list(v) +
                 " (expected a 4x4 array or an object with \"matrix\", \"coefficients\", \"vertex\"/\"a\"/\"b\" or "
                 "\"map\"/\"translation\")");
}

// ------------------------------------------------------------------------------------------------
// Rendering

std::string position_meaning(Position p) {
  switch (p) {
    case Position::I:
      return "the ellipsoid lies inside the paraboloid, with no common point";
    case Position::TI:
      return "the ellipsoid lies inside the paraboloid and touches it (tangent from inside)";
    case Position::C:
      return "the surfaces cross: they meet, and not only tangentially";
    case Position::TE:
      return "the ellipsoid lies outside the paraboloid and touches it (tangent from outside)";
    case Position::E:
      return "the ellipsoid lies outside the paraboloid, with no common point";
  }
  return "?";
}

std::string rho_vs_one_text(int sign) { return sign < 0 ? "<1" : sign == 0 ? "=1" : ">1"; }

namespace {

std::string stage_meaning(Stage s) { return relpos::detail::stage_row(s).meaning; }

/// f scaled by the positive lcm of its denominators: same roots, integer coefficients.
Quartic<Integer> integer_quartic(const Quartic<Rational>& f) {
  Integer l(1);
  forms::lcm_of_denominators(f.begin(), f.end(), l);
  Quartic<Integer> out;
  for (std::size_t i = 0; i < 5; ++i) out[i] = f[i].numerator() * (l / f[i].denominator());
  return out;
}

/// One certified decimal per entry of c.roots (exact roots are rounded exactly); with only_multiple,
/// only for the roots of multiplicity >= 2 (the others are left empty).
std::vector<std::string> root_decimals(const Classification& c, int digits, bool only_multiple) {
  std::vector<std::string> out(c.roots.size());
  bool need_isolation = false;
  for (const auto& r : c.roots)
    if (!r.exact && (!only_multiple || r.multiplicity_f >= 2)) need_isolation = true;
  std::vector<std::string> iso;
  if (need_isolation) iso = real_root_decimals(integer_quartic(c.f), digits);
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const auto& r = c.roots[i];
    if (only_multiple && r.multiplicity_f < 2) continue;  // not shown: left empty
    if (r.exact)
      out[i] = to_decimal(*r.exact, digits);
    else if (iso.size() == c.roots.size())
      out[i] = iso[i];
    else  // should not happen: fall back on the midpoint of the isolating interval
      out[i] = to_decimal((r.lower + r.upper) / 2, digits);
  }
  return out;
}

std::string double_text(double x, int digits) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits < 1 ? 1 : (digits > 15 ? 15 : digits), x);
  return buf;
}

std::string count_text(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string polynomial_to_text(const Rational* c, int size, const std::string& var) {
  return relpos::detail::polynomial_text(c, size < 0 ? 0 : static_cast<std::size_t>(size), var);
}

namespace detail {

namespace {

/// The members of a report that depend on the verdict alone, written once: a batch line copies them.
struct VerdictTexts {
  std::array<std::array<std::string, 2>, kAllPositions.size()> head;  // by position and smallness
  std::array<std::string, kRuleCount> rule;
  std::array<std::string, kAllStages.size()> stage;
};

const VerdictTexts& verdict_texts() {
  static const VerdictTexts texts = [] {
    VerdictTexts t;
    for (const Position p : kAllPositions)
      for (const bool small : {false, true}) {
        JsonWriter w(t.head[static_cast<std::size_t>(p)][small]);
        w.member("position");
        w.string(to_string(p));
        w.member("small");
        w.boolean(small);
        w.member("contact");
        w.boolean(contact_of(p) != Contact::None);
      }
    for (std::size_t k = 0; k < kRuleCount; ++k) {
      JsonWriter w(t.rule[k]);
      w.member("rule");
      w.string(describe(static_cast<Rule>(k)));
    }
    for (const Stage st : kAllStages) {
      JsonWriter w(t.stage[static_cast<std::size_t>(st)]);
      w.member("stage");
      w.string(to_string(st));
    }
    return t;
  }();
  return texts;
}

}  // namespace

void append_verdict_head(const Verdict& v, JsonWriter& w) {
  w.raw(verdict_texts().head.at(static_cast<std::size_t>(v.position))[v.small]);
}

const std::string& rule_member(Rule r) { return verdict_texts().rule.at(static_cast<std::size_t>(r)); }

const std::string& stage_member(Stage st) { return verdict_texts().stage.at(static_cast<std::size_t>(st)); }

void append_classification(const Classification& c, const RenderOptions& options, JsonWriter& w) {
  const Verdict& v = c.verdict;
  append_verdict_head(v, w);
  w.member("rho_vs_one");
  w.string(rho_vs_one_text(v.rho_vs_one));
  w.member("rho");
  w.or_null(c.rho, [&](const Rational& rho) { w.rational(rho); });
  w.member("rho_approx");  // the double nearest the exact rho when there is one
  const bool approx = c.has_full_evidence && std::isfinite(c.rho_approx);
  w.or_null(approx ? std::optional<double>(c.rho_approx) : std::nullopt, [&](double x) { w.number(x); });
  w.raw(rule_member(v.rule));
  w.raw(stage_member(v.stage));
  w.member("disc_sign");
  w.integer(v.sign_disc_f);
  w.member("disc_ftilde_sign");
  w.integer(v.sign_disc_ftilde);
  if (c.has_full_evidence) {
    w.member("degree_ftilde");
    w.integer(c.degree_ftilde);
  }
  const std::pair<const char*, int> counts[] = {{"real", v.real_roots},
                                                {"negative", v.negative_roots},
                                                {"positive", v.positive_roots},
                                                {"nonreal", v.nonreal_roots}};
  w.member("roots");
  for (std::size_t k = 0; k < 4; ++k) {
    w.raw(k == 0 ? "{" : ",");
    w.key(counts[k].first);
    w.integer(counts[k].second);
  }
  w.raw("}");
  if (!c.has_full_evidence) {
    w.raw("}");
    return;
  }
  w.member("f");
  w.rationals(c.f.data(), c.f.size());
  w.member("s");
  w.rationals(c.s.data(), c.s.size());
  w.member("multiple_roots");
  w.raw("[");
  const auto approx_roots = root_decimals(c, options.digits, /*only_multiple=*/true);
  bool first = true;
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const auto& r = c.roots[i];
    if (r.multiplicity_f < 2) continue;
    w.raw(first ? "{" : ",{");
    first = false;
    w.key("value");
    w.or_null(r.exact, [&](const Rational& x) { w.rational(x); });
    w.member("interval");
    const Rational ends[2] = {r.lower, r.upper};
    w.rationals(ends, 2);
    w.member("approx");
    w.string(approx_roots[i]);
    w.member("multiplicity_f");
    w.integer(r.multiplicity_f);
    w.member("multiplicity_s");
    w.integer(r.multiplicity_s);
    w.member("tangency");
    w.boolean(r.tangency());
    w.raw("}");
  }
  w.raw("]");
  w.member("certificate");
  append_certificate(c.certificate, options.digits, w);
  w.raw("}");
}

}  // namespace detail

std::string classification_json_text(const Classification& c, const RenderOptions& options) {
  std::string out;
  out.reserve(c.has_full_evidence ? 2048 : 512);  // the reports of ordinary pairs fit: no reallocation
  detail::JsonWriter w(out);
  detail::append_classification(c, options, w);
  out[0] = '{';  // the members start with a comma (batch writes the id before them)
  return out;
}

Json classification_to_json(const Classification& c, const RenderOptions& options) {
  return Json::parse(classification_json_text(c, options));
}

namespace {

/// One line saying what the certificate is and why it proves the position (position.hpp).
std::string certificate_text(const Certificate& c) {
  switch (c.kind) {
    case Certificate::Kind::Definite:
      return "lambda = " + to_string(c.lambda) +
             ": lambda P + E is positive definite, so p has one sign on the "
             "solid ellipsoid";
    case Certificate::Kind::Tangent:
      return "lambda = " + to_string(c.lambda) + ": lambda P + E is positive semidefinite; contact point (" +
             to_string(c.contact[0]) + ", " + to_string(c.contact[1]) + ", " + to_string(c.contact[2]) + ")";
    case Certificate::Kind::HardTangent:
      return "lambda = lambda_s (hard case): contact along " +
             std::string(c.directions.empty()       ? "one point"
                         : c.directions.size() == 1 ? "two points"
                                                    : "a conic") +
             " (exact centre, directions and squared radius in the JSON output)";
    case Certificate::Kind::Crossing:
      return "inside point (" + to_string(c.inside[0]) + ", " + to_string(c.inside[1]) + ", " + to_string(c.inside[2]) +
             "), outside point (" + to_string(c.outside[0]) + ", " + to_string(c.outside[1]) + ", " +
             to_string(c.outside[2]) + ") of the solid ellipsoid";
    case Certificate::Kind::None:
      break;
  }
  return "none";
}

}  // namespace

std::string classification_to_text(const Classification& c, const RenderOptions& options) {
  std::string t;
  auto line = [&](const std::string& label, const std::string& text) {
    t += label;
    if (label.size() < 10) t += std::string(10 - label.size(), ' ');
    t += text + "\n";
  };
  line("position:", to_string(c.verdict.position) + " - " + position_meaning(c.verdict.position));
  line("rule:", c.rule_text());

  std::string small =
      c.verdict.small ? "yes (the paper's smallness hypothesis holds): " : "no (the smallness hypothesis fails): ";
  const std::string compare = std::string("rho ") + (c.verdict.rho_vs_one < 0    ? "< 1"
                                                     : c.verdict.rho_vs_one == 0 ? "= 1"
                                                                                 : "> 1");
  if (c.rho) {
    const std::string exact = to_string(*c.rho), approx = to_decimal(*c.rho, options.digits);
    small += "rho = " + exact + (approx == exact ? "" : " ~ " + approx);
  } else if (c.has_full_evidence) {
    small += compare + ", rho ~ " + double_text(c.rho_approx, options.digits) + " (irrational; double precision)";
  } else {
    small += compare;
  }
  line("small:", small);
  line("contact:", contact_of(c.verdict.position) != Contact::None ? "yes" : "no");
  line("stage:", to_string(c.verdict.stage) + " (" + stage_meaning(c.verdict.stage) + ")");
  if (c.has_full_evidence) line("proof:", certificate_text(c.certificate));

  t += "\n";
  if (c.has_full_evidence) {
    t += "f(l) = det(l P + E) = " + polynomial_to_text(c.f.data(), 5) + "\n";
    t += "s(l) = det(l A + M) = " + polynomial_to_text(c.s.data(), 3) + "\n";
  }
  auto sign_text = [](int s) { return s < 0 ? std::string("< 0") : s == 0 ? "= 0" : "> 0"; };
  t += "Disc(f) " + sign_text(c.verdict.sign_disc_f) + ", Disc(f~) " + sign_text(c.verdict.sign_disc_ftilde);
  if (c.has_full_evidence) t += ", deg f~ = " + std::to_string(c.degree_ftilde);
  t += "   (f~ = f / gcd(f, s))\n";

  t += "real roots of f: " + count_text(c.verdict.real_roots, "distinct root", "distinct roots") + " (" +
       std::to_string(c.verdict.negative_roots) + " negative, " + std::to_string(c.verdict.positive_roots) +
       " positive)";
  if (c.has_full_evidence && !c.roots.empty()) {
    t += ", certified to " + std::to_string(options.digits) + " significant digits:\n";
    const auto approx = root_decimals(c, options.digits, /*only_multiple=*/false);
    std::size_t width = 0;
    for (const auto& a : approx) width = std::max(width, a.size());
    for (std::size_t i = 0; i < c.roots.size(); ++i) {
      const auto& r = c.roots[i];
      std::string row = "  l = " + approx[i] + std::string(width - approx[i].size(), ' ');
      if (r.exact && to_string(*r.exact) != approx[i]) row += "  (exactly " + to_string(*r.exact) + ")";
      row += "  ";
      if (r.multiplicity_f == 1) {
        row += "simple";
        if (r.multiplicity_s > 0) row += "; also a root of s";
      } else {
        row += "multiplicity " + std::to_string(r.multiplicity_f) + " in f, " + std::to_string(r.multiplicity_s) +
               " in s: ";
        row += r.tangency() ? "tangency (a multiple root of f~)"
                            : "special root of s (not a tangency; simple or absent in f~)";
      }
      t += row + "\n";
    }
  } else {
    t += "\n";
  }
  t += "non-real roots of f: " + std::to_string(c.verdict.nonreal_roots) + " (with multiplicity)\n";
  return t;
}

}  // namespace relpos::io
