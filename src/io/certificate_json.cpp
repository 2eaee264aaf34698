// Certificates as JSON (include/relpos/position.hpp): exact strings out, exact numbers in.
#include "io/certificate_json.hpp"

#include <gmp.h>

#include <cstddef>
#include <set>
#include <string>
#include <utility>

#include "certificate/verify.hpp"
#include "io/json_values.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::detail::io {
namespace {

/// floor(sqrt(d) * 10^k) / 10^k: below sqrt d by less than 10^-k.
Rational sqrt_below(const Integer& d, unsigned long k) {
  Integer scale, scaled, root;
  mpz_ui_pow_ui(scale.mpz(), 10, k);
  scaled = d * scale * scale;
  mpz_sqrt(root.mpz(), scaled.mpz());
  return Rational(root, scale);
}

/// `digits` significant digits of a + b sqrt d (for humans; the last digit may be off by one).
std::string quad_decimal(const QuadraticNumber& x, const Integer& d, int digits) {
  if (x.b == 0 || d == 0) return to_decimal(x.a, digits);
  if (quadratic_sign(x, d) == 0) return "0";
  // Increase the precision until the error bound |b| 10^-k is far below the value.
  for (unsigned long k = static_cast<unsigned long>(digits) + 10;; k *= 2) {
    const Rational approx = x.a + x.b * sqrt_below(d, k);
    Integer ten_k;
    mpz_ui_pow_ui(ten_k.mpz(), 10, k);
    const Rational bound = (x.b < 0 ? Rational(-x.b) : x.b) / Rational(ten_k);
    const Rational magnitude = approx < 0 ? Rational(-approx) : approx;
    Integer margin;
    mpz_ui_pow_ui(margin.mpz(), 10, static_cast<unsigned long>(digits) + 3);
    if (magnitude > bound * Rational(margin) || k > 100000) return to_decimal(approx, digits);
  }
}

void only_keys(const Json& j, const std::string& path, const std::set<std::string>& allowed) {
  if (!j.is_object()) throw InputError(path + ": expected an object");
  for (const auto& item : j.items())
    if (!allowed.count(item.key())) throw InputError(path + ": unknown key \"" + item.key().substr(0, 40) + "\"");
}

const Json& field(const Json& j, const std::string& key, const std::string& path) {
  if (!j.contains(key)) throw InputError(path + ": missing \"" + key + "\"");
  return j[key];
}

Rational number(const Json& j, const std::string& path) {
  if (j.is_null() || j.is_boolean() || j.is_array() || j.is_object())
    throw InputError(path + ": expected a number, got " + j.dump().substr(0, 40));
  return rational_from_json(j, path);
}

Vector3 vec(const Json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) throw InputError(path + ": expected an array of 3 numbers");
  return {number(j[0], path + "[0]"), number(j[1], path + "[1]"), number(j[2], path + "[2]")};
}

QuadraticNumber quad(const Json& j, const std::string& path) {
  only_keys(j, path, {"a", "b"});
  return {number(field(j, "a", path), path + ".a"), number(field(j, "b", path), path + ".b")};
}

QuadraticVector3 quad_vec(const Json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) throw InputError(path + ": expected an array of 3 {\"a\", \"b\"} objects");
  return {quad(j[0], path + "[0]"), quad(j[1], path + "[1]"), quad(j[2], path + "[2]")};
}

void vec_json(const Vector3& v, JsonWriter& w) { w.rationals(v.data(), v.size()); }

void quad_json(const QuadraticNumber& x, JsonWriter& w) {
  w.raw("{\"a\":");
  w.rational(x.a);
  w.raw(",\"b\":");
  w.rational(x.b);
  w.raw("}");
}

void quad_vec_json(const QuadraticVector3& v, JsonWriter& w) {
  for (std::size_t i = 0; i < 3; ++i) {
    w.raw(i ? "," : "[");
    quad_json(v[i], w);
  }
  w.raw("]");
}

/// The hard case's certificate: lambda_s in Q(sqrt d), the contact set, and its decimals.
void append_hard_tangent(const Certificate& c, int digits, JsonWriter& w) {
  w.raw("{\"lambda\":{\"a\":");
  w.rational(c.lambda_q.a);
  w.raw(",\"b\":");
  w.rational(c.lambda_q.b);
  w.raw(",\"d\":");
  w.rational(Rational(c.d));
  w.raw("},\"contact_set\":{\"center\":");
  quad_vec_json(c.centre, w);
  w.raw(",\"directions\":[");
  for (std::size_t i = 0; i < c.directions.size(); ++i) {
    if (i) w.raw(",");
    quad_vec_json(c.directions[i], w);
  }
  w.raw("],\"radius2\":");
  quad_json(c.radius2, w);
  w.raw(",\"decimal\":{\"lambda\":");
  w.string(quad_decimal(c.lambda_q, c.d, digits));
  w.raw(",\"center\":[");
  for (std::size_t i = 0; i < 3; ++i) {
    if (i) w.raw(",");
    w.string(quad_decimal(c.centre[i], c.d, digits));
  }
  w.raw("],\"radius2\":");
  w.string(quad_decimal(c.radius2, c.d, digits));
  w.raw("}}}");
}

}  // namespace

void append_certificate(const Certificate& c, int digits, JsonWriter& w) {
  using K = Certificate::Kind;
  switch (c.kind) {
    case K::None:
      w.null();
      return;
    case K::Definite:
      w.raw("{\"lambda\":");
      w.rational(c.lambda);
      w.raw("}");
      return;
    case K::Tangent:
      w.raw("{\"lambda\":");
      w.rational(c.lambda);
      w.raw(",\"contact\":");
      vec_json(c.contact, w);
      w.raw("}");
      return;
    case K::Crossing:
      w.raw("{\"inside\":");
      vec_json(c.inside, w);
      w.raw(",\"outside\":");
      vec_json(c.outside, w);
      w.raw("}");
      return;
    case K::HardTangent:
      append_hard_tangent(c, digits, w);
      return;
  }
  w.null();
}

Certificate certificate_from_tree(const Json& j) {
  const std::string path = "certificate";
  Certificate c;
  if (j.is_null()) return c;
  if (!j.is_object()) throw InputError(path + ": expected an object or null, got " + j.dump().substr(0, 40));
  if (j.contains("inside") || j.contains("outside")) {
    only_keys(j, path, {"inside", "outside"});
    c.kind = Certificate::Kind::Crossing;
    c.inside = vec(field(j, "inside", path), path + ".inside");
    c.outside = vec(field(j, "outside", path), path + ".outside");
    return c;
  }
  if (j.contains("contact_set")) {
    only_keys(j, path, {"lambda", "contact_set"});
    c.kind = Certificate::Kind::HardTangent;
    const Json& l = field(j, "lambda", path);
    const std::string lp = path + ".lambda";
    only_keys(l, lp, {"a", "b", "d"});
    c.lambda_q = {number(field(l, "a", lp), lp + ".a"), number(field(l, "b", lp), lp + ".b")};
    const Rational d = number(field(l, "d", lp), lp + ".d");
    if (d.denominator() != 1 || d < 0)
      throw InputError(lp + ".d: expected a non-negative integer, got " + to_string(d));
    c.d = d.numerator();
    const Json& s = j["contact_set"];
    const std::string sp = path + ".contact_set";
    only_keys(s, sp, {"center", "directions", "radius2", "decimal"});
    c.centre = quad_vec(field(s, "center", sp), sp + ".center");
    const Json& dirs = field(s, "directions", sp);
    if (!dirs.is_array()) throw InputError(sp + ".directions: expected an array");
    for (std::size_t i = 0; i < dirs.size(); ++i)
      c.directions.push_back(quad_vec(dirs[i], sp + ".directions[" + std::to_string(i) + "]"));
    c.radius2 = quad(field(s, "radius2", sp), sp + ".radius2");
    return c;
  }
  if (j.contains("contact")) {
    only_keys(j, path, {"lambda", "contact"});
    c.kind = Certificate::Kind::Tangent;
    c.lambda = number(field(j, "lambda", path), path + ".lambda");
    c.contact = vec(j["contact"], path + ".contact");
    return c;
  }
  only_keys(j, path, {"lambda"});
  c.kind = Certificate::Kind::Definite;
  c.lambda = number(field(j, "lambda", path), path + ".lambda");
  return c;
}

}  // namespace relpos::detail::io

namespace relpos {

std::string certificate_json_text(const Certificate& c, int digits) {
  std::string text;
  detail::io::JsonWriter w(text);
  detail::io::append_certificate(c, digits, w);
  return text;
}

Certificate certificate_from_json(std::string_view text) {
  return detail::io::certificate_from_tree(detail::io::parse_json_exact(text));
}

}  // namespace relpos
