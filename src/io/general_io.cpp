// JSON in and out for the general quadrics (src/io/general_io.hpp; doc/cli.md, "General quadrics").
#include "io/general_io.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <sstream>
#include <string>

#include "algebra/pair_size.hpp"
#include "general/decision.hpp"
#include "io/json_values.hpp"
#include "io/report_text.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::detail::io {
namespace {

[[noreturn]] void general_fail(const std::string& path, const std::string& message) {
  throw InputError(path + ": " + message);
}

std::string member(const std::string& path, const std::string& key) { return path + "." + key; }

std::string described(const Json& v) {
  const std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

void general_check_keys(const Json& v, std::initializer_list<const char*> allowed, const std::string& path) {
  for (auto it = v.begin(); it != v.end(); ++it) {
    bool ok = false;
    for (const char* k : allowed) ok = ok || it.key() == k;
    if (!ok) general_fail(path, "unknown key \"" + it.key().substr(0, 40) + "\"");
  }
}

const Json& general_required(const Json& v, const char* key, const std::string& path) {
  if (!v.contains(key)) general_fail(path, std::string("missing \"") + key + "\"");
  return v[key];
}

Rational number(const Json& v, const std::string& path) { return rational_from_json(v, path); }

template <std::size_t N>
std::array<Rational, N> numbers(const Json& v, const std::string& path) {
  if (!v.is_array() || v.size() != N)
    general_fail(path, "expected an array of " + std::to_string(N) + " numbers, got " + described(v));
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = number(v[i], path + "[" + std::to_string(i) + "]");
  return out;
}

Matrix4 general_matrix4(const Json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 4) general_fail(path, "expected a 4x4 array, got " + described(v));
  Matrix4 m;
  for (int i = 0; i < 4; ++i) {
    const std::array<Rational, 4> row =
        numbers<4>(v[static_cast<std::size_t>(i)], path + "[" + std::to_string(i) + "]");
    for (int j = 0; j < 4; ++j) m(i, j) = row[static_cast<std::size_t>(j)];
  }
  return m;
}

template <class F>
Quadric with_role(const std::string& role, F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    throw InputError(role + ": " + e.what());
  }
}

Quaternion rotation_of(const Json& v, const std::string& path) {
  if (!v.contains("rotation")) return {Rational(1), Rational(0), Rational(0), Rational(0)};
  return numbers<4>(v["rotation"], member(path, "rotation"));
}

Quadric geometric_form(const Json& v, const std::string& role) {
  const Json& t = v["type"];
  if (!t.is_string()) general_fail(member(role, "type"), "expected a string naming the type, got " + described(t));
  const std::string type = t.get<std::string>();
  auto vec = [&](const char* key) { return numbers<3>(general_required(v, key, role), member(role, key)); };
  auto num = [&](const char* key) { return number(general_required(v, key, role), member(role, key)); };
  if (type == "sphere") {
    general_check_keys(v, {"type", "center", "radius"}, role);
    return with_role(role, [&] { return Quadric::sphere(vec("center"), num("radius")); });
  }
  if (type == "ellipsoid" || type == "hyperboloid of one sheet" || type == "hyperboloid of two sheets") {
    general_check_keys(v, {"type", "center", "axes", "rotation"}, role);
    const Vector3 c = vec("center"), axes = vec("axes");
    const Quaternion q = rotation_of(v, role);
    if (type == "ellipsoid") return with_role(role, [&] { return Quadric::ellipsoid(c, axes, q); });
    if (type == "hyperboloid of one sheet")
      return with_role(role, [&] { return Quadric::hyperboloid_one_sheet(c, axes, q); });
    return with_role(role, [&] { return Quadric::hyperboloid_two_sheets(c, axes, q); });
  }
  if (type == "elliptic cone" || type == "cone") {
    general_check_keys(v, {"type", "apex", "a", "b", "rotation"}, role);
    return with_role(role, [&] { return Quadric::cone(vec("apex"), num("a"), num("b"), rotation_of(v, role)); });
  }
  if (type == "elliptic paraboloid" || type == "hyperbolic paraboloid") {
    general_check_keys(v, {"type", "vertex", "a", "b", "rotation"}, role);
    const Vector3 p = vec("vertex");
    const Rational a = num("a"), b = num("b");
    const Quaternion q = rotation_of(v, role);
    if (type == "elliptic paraboloid") return with_role(role, [&] { return Quadric::elliptic_paraboloid(p, a, b, q); });
    return with_role(role, [&] { return Quadric::hyperbolic_paraboloid(p, a, b, q); });
  }
  if (type == "elliptic cylinder" || type == "hyperbolic cylinder") {
    general_check_keys(v, {"type", "center", "a", "b", "rotation"}, role);
    const Vector3 c = vec("center");
    const Rational a = num("a"), b = num("b");
    const Quaternion q = rotation_of(v, role);
    if (type == "elliptic cylinder") return with_role(role, [&] { return Quadric::elliptic_cylinder(c, a, b, q); });
    return with_role(role, [&] { return Quadric::hyperbolic_cylinder(c, a, b, q); });
  }
  if (type == "parabolic cylinder") {
    general_check_keys(v, {"type", "vertex", "a", "rotation"}, role);
    return with_role(role, [&] { return Quadric::parabolic_cylinder(vec("vertex"), num("a"), rotation_of(v, role)); });
  }
  if (type == "half-space") {
    general_check_keys(v, {"type", "normal", "offset"}, role);
    return with_role(role, [&] { return Quadric::half_space(vec("normal"), num("offset")); });
  }
  if (type == "slab") {
    general_check_keys(v, {"type", "normal", "low", "high"}, role);
    return with_role(role, [&] { return Quadric::slab(vec("normal"), num("low"), num("high")); });
  }
  general_fail(member(role, "type"),
               "unknown type \"" + type.substr(0, 40) +
                   "\" (expected sphere, ellipsoid, hyperboloid of one sheet, hyperboloid of two sheets, "
                   "elliptic cone (or cone), elliptic paraboloid, hyperbolic paraboloid, elliptic cylinder, "
                   "hyperbolic cylinder, parabolic cylinder, slab or half-space)");
}

std::string meaning(QuadricPosition p) {
  switch (p) {
    case QuadricPosition::I:
      return "the ellipsoid lies in the interior of the quadric's solid";
    case QuadricPosition::TI:
      return "the ellipsoid lies in the quadric's solid and touches its surface";
    case QuadricPosition::C:
      return "the surfaces cross";
    case QuadricPosition::TE:
      return "the ellipsoid lies outside the quadric's solid and touches its surface";
    case QuadricPosition::E:
      return "the ellipsoid lies outside the quadric's solid";
    case QuadricPosition::O:
      return "the quadric's solid lies in the interior of the ellipsoid";
    case QuadricPosition::TO:
      return "the quadric's solid lies in the ellipsoid and touches its surface";
    case QuadricPosition::EQ:
      return "the two ellipsoids are the same";
  }
  return "";
}

Json vector_json(const Vector3& x) { return Json::array({to_string(x[0]), to_string(x[1]), to_string(x[2])}); }

Json quad_json(const QuadraticNumber& x) { return Json{{"a", to_string(x.a)}, {"b", to_string(x.b)}}; }

QuadraticNumber quad(const Json& j, const std::string& path) {
  if (!j.is_object()) general_fail(path, "expected {\"a\": ..., \"b\": ...}");
  general_check_keys(j, {"a", "b"}, path);
  return {number(general_required(j, "a", path), member(path, "a")),
          number(general_required(j, "b", path), member(path, "b"))};
}

QuadraticVector3 quad_vector(const Json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) general_fail(path, "expected 3 numbers {\"a\", \"b\"}");
  return {quad(j[0], path + "[0]"), quad(j[1], path + "[1]"), quad(j[2], path + "[2]")};
}

std::string quad_decimal(const QuadraticNumber& x, const Integer& d, int digits) {
  if (x.b == 0 || d == 0) return to_decimal(x.a, digits);
  // a + b sqrt(d) to the digits asked: sqrt(d) from an integer square root at a high scale.
  Integer scaled = d, root;
  const int extra = 4 * digits + 64;
  mpz_mul_2exp(scaled.mpz(), d.mpz(), static_cast<mp_bitcnt_t>(2 * extra));
  mpz_sqrt(root.mpz(), scaled.mpz());
  Rational r(root);
  mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(extra));
  return to_decimal(x.a + x.b * r, digits);
}

}  // namespace

Quadric quadric_from_json(const Json& v, const std::string& role) {
  if (v.is_array()) {
    const Matrix4 m = general_matrix4(v, role);
    return with_role(role, [&] { return Quadric::from_matrix(m); });
  }
  if (!v.is_object()) general_fail(role, "expected a 4x4 array or an object describing a quadric, got " + described(v));
  if (v.contains("matrix")) {
    general_check_keys(v, {"matrix"}, role);
    const Matrix4 m = general_matrix4(v["matrix"], member(role, "matrix"));
    return with_role(role, [&] { return Quadric::from_matrix(m); });
  }
  if (v.contains("coefficients")) {
    general_check_keys(v, {"coefficients"}, role);
    const Coefficients10 c = numbers<10>(v["coefficients"], member(role, "coefficients"));
    return with_role(role, [&] { return Quadric::from_coefficients(c); });
  }
  if (v.contains("type")) return geometric_form(v, role);
  general_fail(role,
               "no recognized quadric form (expected a 4x4 array or an object with \"matrix\", \"coefficients\" or "
               "\"type\")");
}

std::size_t check_general_pair_size(const Ellipsoid& e, const Quadric& q, const SizeLimit& limit) {
  return relpos::detail::check_normalized_size(storage_of(e), storage_of(q), limit);  // doc/cli.md, Limits
}

GeneralPairSize::GeneralPairSize(const Quadric& q, const SizeLimit& limit) : q_(q), limit_(limit) {
  try {
    q_bits_ = relpos::detail::check_normalized_size(storage_of(q), limit_);
  } catch (const InputError&) {
    within_ = false;  // each pair's error then names the larger of its two matrices
  }
}

std::size_t GeneralPairSize::check(const Ellipsoid& e) const {
  if (within_) return std::max(q_bits_, relpos::detail::check_normalized_size(storage_of(e), limit_));
  return check_general_pair_size(e, q_, limit_);
}

std::optional<QuadricPosition> quadric_position_from_text(const std::string& s) {
  for (QuadricPosition p : general::kAllQuadricPositions)
    if (to_string(p) == s) return p;
  return std::nullopt;
}

Json quadric_certificate_to_json(const QuadricCertificate& c, int digits) {
  using K = QuadricCertificate::Kind;
  switch (c.kind) {
    case K::None:
      return nullptr;
    case K::Definite:
      return Json{{"t", to_string(c.t)}};
    case K::Tangent:
      return Json{{"t", to_string(c.t)}, {"contact", vector_json(c.contact)}};
    case K::HardTangent: {
      Json centre = Json::array(), directions = Json::array(), decimal_centre = Json::array();
      for (const QuadraticNumber& x : c.centre) {
        centre.push_back(quad_json(x));
        decimal_centre.push_back(quad_decimal(x, c.d, digits));
      }
      for (const QuadraticVector3& w : c.directions)
        directions.push_back(Json::array({quad_json(w[0]), quad_json(w[1]), quad_json(w[2])}));
      Json t = quad_json(c.t_q);
      t["d"] = to_string(c.d);
      return Json{{"t", t},
                  {"contact_set", Json{{"center", centre},
                                       {"directions", directions},
                                       {"radius2", quad_json(c.radius2)},
                                       {"decimal", Json{{"t", quad_decimal(c.t_q, c.d, digits)},
                                                        {"center", decimal_centre},
                                                        {"radius2", quad_decimal(c.radius2, c.d, digits)}}}}}};
    }
    case K::Crossing: {
      Json j{{"inside", vector_json(c.inside)}, {"outside", vector_json(c.outside)}};
      if (c.beyond) j["beyond"] = vector_json(*c.beyond);
      return j;
    }
    case K::Equal:
      return Json{{"ratio", to_string(c.ratio)}};
  }
  return nullptr;
}

QuadricCertificate quadric_certificate_from_json(const Json& j) {
  using K = QuadricCertificate::Kind;
  const std::string path = "certificate";
  QuadricCertificate c;
  if (j.is_null()) return c;
  if (!j.is_object()) general_fail(path, "expected an object, got " + described(j));
  if (j.contains("ratio")) {
    general_check_keys(j, {"ratio"}, path);
    c.kind = K::Equal;
    c.ratio = number(j["ratio"], member(path, "ratio"));
    return c;
  }
  if (j.contains("inside") || j.contains("outside")) {
    general_check_keys(j, {"inside", "outside", "beyond"}, path);
    c.kind = K::Crossing;
    c.inside = numbers<3>(general_required(j, "inside", path), member(path, "inside"));
    c.outside = numbers<3>(general_required(j, "outside", path), member(path, "outside"));
    if (j.contains("beyond")) c.beyond = numbers<3>(j["beyond"], member(path, "beyond"));
    return c;
  }
  if (j.contains("contact_set")) {
    general_check_keys(j, {"t", "contact_set"}, path);
    c.kind = K::HardTangent;
    const Json& t = general_required(j, "t", path);
    if (!t.is_object()) general_fail(member(path, "t"), "expected {\"a\", \"b\", \"d\"}");
    general_check_keys(t, {"a", "b", "d"}, member(path, "t"));
    c.t_q = {number(general_required(t, "a", member(path, "t")), member(path, "t.a")),
             number(general_required(t, "b", member(path, "t")), member(path, "t.b"))};
    const Rational d = number(general_required(t, "d", member(path, "t")), member(path, "t.d"));
    if (d.denominator() != 1 || d < 0) general_fail(member(path, "t.d"), "expected a non-negative integer");
    c.d = d.numerator();
    const std::string sp = member(path, "contact_set");
    const Json& s = j["contact_set"];
    if (!s.is_object()) general_fail(sp, "expected an object");
    general_check_keys(s, {"center", "directions", "radius2", "decimal"}, sp);
    c.centre = quad_vector(general_required(s, "center", sp), member(sp, "center"));
    const Json& dirs = general_required(s, "directions", sp);
    if (!dirs.is_array() || dirs.size() > 3)
      general_fail(member(sp, "directions"), "expected an array of at most 3 vectors");
    for (std::size_t i = 0; i < dirs.size(); ++i)
      c.directions.push_back(quad_vector(dirs[i], member(sp, "directions") + "[" + std::to_string(i) + "]"));
    c.radius2 = quad(general_required(s, "radius2", sp), member(sp, "radius2"));
    return c;
  }
  if (j.contains("contact")) {
    general_check_keys(j, {"t", "contact"}, path);
    c.kind = K::Tangent;
    c.t = number(general_required(j, "t", path), member(path, "t"));
    c.contact = numbers<3>(j["contact"], member(path, "contact"));
    return c;
  }
  general_check_keys(j, {"t"}, path);
  c.kind = K::Definite;
  c.t = number(general_required(j, "t", path), member(path, "t"));
  return c;
}

std::string general_answer_text(const QuadricClassification& c, int digits) {
  std::ostringstream os;
  const QuadricVerdict& v = c.verdict;
  os << "position: " << to_string(v.position) << " (" << meaning(v.position) << ")\n";
  os << "quadric: " << to_string(v.type) << "\n";
  os << "contact: " << to_string(contact_of(v.position)) << "\n";
  os << "rule: " << describe(v.rule) << "\n";
  os << "stage: " << to_string(v.stage) << "\n";
  os << "f(t) = det(Q + t E) = " << polynomial_to_text(c.f.data(), 5, "t") << "\n";
  os << "D(t) = det(B + t M) = " << polynomial_to_text(c.d.data(), 4, "t") << "\n";
  os << "real roots of f and D:\n";
  for (const PencilRoot& r : c.roots)
    os << "  " << (r.exact ? to_string(*r.exact) : to_decimal((r.lower + r.upper) / 2, digits))
       << "  (multiplicity in f " << r.multiplicity_f << ", in D " << r.multiplicity_d << ")\n";
  os << "certificate: " << dump_json(quadric_certificate_to_json(c.certificate, digits)) << "\n";
  return os.str();
}

}  // namespace relpos::detail::io
