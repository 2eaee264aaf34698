// Quadrics from exact JSON trees (doc/cli.md, "Quadric formats"), the general reader of every form:
// the public text functions (io.hpp: ellipsoid_from_json, paraboloid_from_json), a batch line's
// quadrics the fast reader leaves, and the Python module's values read through these. `role`
// prefixes every message and names the field paths ("ellipsoid", "paraboloid"); library errors (not
// an ellipsoid, singular map, ...) are rethrown as InputError "<role>: <message>".
//   ellipsoid:  4x4 array | {"matrix"} | {"coefficients"} | {"sphere": {"center", "radius"}}
//               | {"center", "axes", "rotation" | "rotation_matrix"} | {"center", "map"}
//   paraboloid: 4x4 array | {"matrix"} | {"coefficients"} | {"vertex", "a", "b", "rotation"}
//               | {"map", "translation"}
// The tree comes from parse_json (a tree from the ordinary parser would have its floats rounded to
// doubles; those are then taken as the exact dyadic value of the double).
#pragma once

#include <string>

#include "io/json_tree.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::io {

Ellipsoid ellipsoid_from_tree(const Json& value, const std::string& role = "ellipsoid");
Paraboloid paraboloid_from_tree(const Json& value, const std::string& role = "paraboloid");

}  // namespace relpos::detail::io
