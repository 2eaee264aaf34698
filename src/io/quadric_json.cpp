#include "io/quadric_json.hpp"

#include "algebra/cramer.hpp"
#include "io/json_values.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::detail::io {
namespace {

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

Ellipsoid ellipsoid_from_tree(const Json& v, const std::string& role) {
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

Paraboloid paraboloid_from_tree(const Json& v, const std::string& role) {
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

}  // namespace relpos::detail::io

namespace relpos::io {

Ellipsoid ellipsoid_from_json(std::string_view text, const std::string& role) {
  detail::io::Json tree;
  try {
    tree = detail::io::parse_json_exact(text);
  } catch (const InputError& e) {
    throw InputError(role + ": " + e.what());
  }
  return detail::io::ellipsoid_from_tree(tree, role);
}

Paraboloid paraboloid_from_json(std::string_view text, const std::string& role) {
  detail::io::Json tree;
  try {
    tree = detail::io::parse_json_exact(text);
  } catch (const InputError& e) {
    throw InputError(role + ": " + e.what());
  }
  return detail::io::paraboloid_from_tree(tree, role);
}

}  // namespace relpos::io
