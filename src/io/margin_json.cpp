// Margins as JSON (include/relpos/margin.hpp): exact strings out, exact numbers in.
#include "io/margin_json.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "io/certificate_json.hpp"
#include "io/json_values.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::detail::io {
namespace {

/// An exact number: what rational_from_json reads (a JSON number's text or a string "p/q").
Rational exact_number(const Json& j, const std::string& path) {
  if (!j.is_number() && !j.is_string()) fail(path, "expected a number, got " + describe(j));
  return rational_from_json(j, path);
}

/// The double a JSON number's text denotes (the nearest one; strtod rounds correctly); null stands
/// for +infinity, the nearest double of an s* beyond the double range.
double double_number(const Json& j, const std::string& path) {
  if (j.is_null()) return std::numeric_limits<double>::infinity();
  std::string text;
  if (j.is_string())
    text = j.get<std::string>();
  else if (j.is_number())
    text = j.dump();
  else
    fail(path, "expected a number, got " + describe(j));
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(x))
    fail(path, "expected a finite number, got " + describe(Json(text)));
  return x;
}

/// The certificate under `key`, when there is one; its messages prefixed by the margin's path.
void read_certificate(const Json& j, const char* key, const std::string& path, Certificate& out) {
  const auto it = j.find(key);
  if (it == j.end()) return;
  try {
    out = certificate_from_tree(*it);
  } catch (const InputError& err) {
    fail(key_path(path, key), err.what());
  }
}

}  // namespace

void append_margin(const Margin& m, int digits, JsonWriter& w) {
  w.raw("{\"approx\":");
  w.number(m.approx);  // null for +infinity, an s* beyond the double range (JSON has no infinity)
  w.member("lo");
  w.rational(m.lo);
  w.member("hi");
  w.rational(m.hi);
  w.member("polynomial");
  w.raw("[");
  for (std::size_t i = 0; i < m.polynomial.size(); ++i) {
    if (i) w.raw(",");
    w.rational(Rational(m.polynomial[i]));
  }
  w.raw("]");
  if (m.lo != m.hi) {
    w.member("below");
    append_certificate(m.below, digits, w);
    w.member("above");
    append_certificate(m.above, digits, w);
  } else if (m.at.kind != Certificate::Kind::None) {
    w.member("at");
    append_certificate(m.at, digits, w);
  }
  w.raw("}");
}

Margin margin_from_tree(const Json& j) {
  const std::string path = "margin";
  if (!j.is_object()) fail(path, "expected an object, got " + describe(j));
  check_keys(j, {"approx", "lo", "hi", "polynomial", "below", "above", "at"}, path);
  Margin m;
  m.approx = double_number(required(j, "approx", path), key_path(path, "approx"));
  m.lo = exact_number(required(j, "lo", path), key_path(path, "lo"));
  m.hi = exact_number(required(j, "hi", path), key_path(path, "hi"));
  const std::string poly_path = key_path(path, "polynomial");
  const Json& poly = required(j, "polynomial", path);
  if (!poly.is_array() || poly.empty()) fail(poly_path, "expected a non-empty array of integers");
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const std::string p = index_path(poly_path, i);
    const Rational c = exact_number(poly[i], p);
    if (c.denominator() != 1) fail(p, "expected an integer, got " + to_string(c));
    m.polynomial.push_back(c.numerator());
  }
  read_certificate(j, "below", path, m.below);
  read_certificate(j, "above", path, m.above);
  read_certificate(j, "at", path, m.at);
  return m;
}

}  // namespace relpos::detail::io

namespace relpos::io {

std::string margin_json_text(const Margin& m, int digits) {
  std::string text;
  detail::io::JsonWriter w(text);
  detail::io::append_margin(m, digits, w);
  return text;
}

Margin margin_from_json_text(std::string_view text) {
  return detail::io::margin_from_tree(detail::io::parse_json_exact(text));
}

}  // namespace relpos::io
