#include "io/margin_json.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>

#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::io {
namespace detail {
namespace {

using Json = nlohmann::ordered_json;

Rational exact_number(const Json& j, const std::string& path) {
  if (j.is_null() || j.is_boolean() || j.is_array() || j.is_object())
    throw InputError(path + ": expected a number, got " + j.dump().substr(0, 40));
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
    throw InputError(path + ": expected a number, got " + j.dump().substr(0, 40));
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(x))
    throw InputError(path + ": expected a finite number, got " + Json(text).dump().substr(0, 40));
  return x;
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

Margin margin_from_json(const Json& j) {
  const std::string path = "margin";
  if (!j.is_object()) throw InputError(path + ": expected an object");
  static const std::set<std::string> keys{"approx", "lo", "hi", "polynomial", "below", "above", "at"};
  for (const auto& item : j.items())
    if (!keys.count(item.key())) throw InputError(path + ": unknown key \"" + item.key().substr(0, 40) + "\"");
  for (const char* key : {"approx", "lo", "hi", "polynomial"})
    if (!j.contains(key)) throw InputError(path + ": missing \"" + key + "\"");
  Margin m;
  m.approx = double_number(j["approx"], path + ".approx");
  m.lo = exact_number(j["lo"], path + ".lo");
  m.hi = exact_number(j["hi"], path + ".hi");
  const Json& poly = j["polynomial"];
  if (!poly.is_array() || poly.empty()) throw InputError(path + ".polynomial: expected a non-empty array of integers");
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const std::string p = path + ".polynomial[" + std::to_string(i) + "]";
    const Rational c = exact_number(poly[i], p);
    if (c.denominator() != 1) throw InputError(p + ": expected an integer, got " + to_string(c));
    m.polynomial.push_back(c.numerator());
  }
  auto certificate = [&](const char* key, Certificate& out) {
    if (!j.contains(key)) return;
    try {
      out = certificate_from_json(j[key]);
    } catch (const InputError& err) {
      throw InputError(path + "." + key + ": " + err.what());
    }
  };
  certificate("below", m.below);
  certificate("above", m.above);
  certificate("at", m.at);
  return m;
}

}  // namespace detail

std::string margin_json_text(const Margin& m, int digits) {
  std::string text;
  detail::JsonWriter w(text);
  detail::append_margin(m, digits, w);
  return text;
}

Margin margin_from_json_text(std::string_view text) { return detail::margin_from_json(parse_json_exact(text)); }

std::string margin_to_text(const Margin& m, const RenderOptions& options) {
  const std::string pad(10, ' ');
  std::string t = "margin:   s* ";
  if (m.hi == 0) return t + "= 0: the ellipsoid's centre lies on the paraboloid (any scaling crosses it)\n";
  const bool rational = m.lo == m.hi;
  t += rational ? "= " + to_string(m.lo) + " exactly" : "~ " + m.value().decimals(options.digits);
  t += ": the factor by which the ellipsoid, scaled about its centre, first touches the paraboloid\n";
  t += pad + "minimal polynomial " + polynomial_text(m.polynomial) + "\n";
  if (rational) {
    t += pad + "proof: scaled by s* it is tangent (" +
         (m.at.lambda < 0 || m.at.kind == Certificate::Kind::HardTangent ? std::string("TI") : std::string("TE")) +
         " certificate)\n";
  } else {
    t += pad + "in [" + to_string(m.lo) + ", " + to_string(m.hi) + "]\n";
    t += pad + "proof: scaled by lo it is " + (m.below.lambda < 0 ? "I" : "E") +
         " (lambda = " + to_string(m.below.lambda) + "), scaled by hi it is C (two witness points)\n";
  }
  return t;
}

}  // namespace relpos::io
