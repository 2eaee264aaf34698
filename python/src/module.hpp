// Shared parts of the extension relpos._relpos (doc/python.md): reading Python objects exactly, the
// type casters that refuse objects made by __new__ without __init__, and the binding functions of
// the module's other files.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <relpos/algebraic_real.hpp>
#include <relpos/error.hpp>
#include <relpos/general_quadric.hpp>
#include <relpos/motion.hpp>
#include <relpos/quadric.hpp>
#include <string>
#include <typeinfo>

#include "io/json_tree.hpp"

namespace relpos_python {

namespace py = pybind11;
using relpos::detail::io::Json;

/// A Python value as the JSON value the CLI would read for it, without rounding: int (any size) as
/// an integer or its exact digits, float as the double (read exactly by the library), a finite
/// Decimal as its own text ("1E-12000", the same number and limits as that string), Fraction and
/// numpy floats (float16 to longdouble) as the exact "p/q" of as_integer_ratio(), str
/// as itself, None/bool/numpy.bool_ as null/true/false (refused by the reader with the CLI's
/// message), a 0-d numpy array as its scalar, lists, tuples and numpy arrays as arrays, dicts as
/// objects. `path` names the value in the TypeError
/// raised for any other object ("ellipsoid.sphere.radius: expected int, float, ...").
Json to_json(py::handle x, const std::string& path);

/// The exact rational of a Python number (same rules as to_json; InputError/TypeError with `path`).
relpos::Rational to_rational(py::handle x, const std::string& path);

/// An exact number as a Python int / fractions.Fraction (of any size).
py::object to_python(const relpos::Integer& z);
py::object to_python(const relpos::Rational& q);

/// The quadric a Python description denotes: a 4x4 matrix, or a dict in any of the CLI's JSON forms
/// (doc/cli.md, "Quadric formats"), read by the CLI's reader: the same value and the same error
/// message as `relpos batch` for the same input. A 4x4 matrix whose 16 entries are doubles (a
/// float64 array, or floats and ints below 2^53) is first offered to from_doubles, which the
/// reader's exact path agrees with; anything it does not accept takes the reader, for the message.
/// Called with the GIL held; the exact validation runs without it.
relpos::Ellipsoid ellipsoid_from_python(py::handle description);
relpos::Paraboloid paraboloid_from_python(py::handle description);
/// Any real quadric (relpos.Quadric): a 4x4 matrix or a dict in any form of a batch line's
/// "quadric" (doc/cli.md, "General quadrics"), read by the CLI's reader (src/io/general_io.hpp).
relpos::Quadric quadric_from_python(py::handle description);

/// True when `x` is an instance of the bound class T whose C++ object was constructed (false for an
/// object made by T.__new__(T) alone).
template <class T>
bool is_built(py::handle x) {
  const py::detail::type_info* info = py::detail::get_type_info(typeid(T));
  if (!info || !PyObject_TypeCheck(x.ptr(), info->type)) return false;
  auto* inst = reinterpret_cast<py::detail::instance*>(x.ptr());
  const py::detail::value_and_holder vh = inst->get_value_and_holder(info, false);
  return vh && vh.holder_constructed();
}

/// The TypeError for an instance made by __new__ without __init__.
[[noreturn]] void throw_unbuilt(py::handle x);

/// The caster of a bound class T: an instance made by __new__ without __init__ is a TypeError
/// wherever it is passed (pybind11 would hand over uninitialised memory).
template <class T>
struct built_caster : py::detail::type_caster_base<T> {
  bool load(py::handle src, bool convert) {
    if (!py::detail::type_caster_base<T>::load(src, convert)) return false;
    const py::detail::type_info* info = py::detail::get_type_info(typeid(T));
    if (info && PyObject_TypeCheck(src.ptr(), info->type) && !is_built<T>(src)) throw_unbuilt(src);
    return true;
  }
};

// Binding functions of the module's files (called from PYBIND11_MODULE in relpos_module.cpp).
void bind_decide(py::module_& m);   // decide_positions, scene (decide.cpp)
void bind_motion(py::module_& m);   // first contact, timeline (motion.cpp)
void bind_batch(py::module_& m);    // _batch_block, the lines of `relpos batch` (batch_binding.cpp)
void bind_oracle(py::module_& m);   // _cases, _judge: relpos cases and relpos judge (oracle_binding.cpp)
void bind_general(py::module_& m);  // _classify_quadric_json, _verify_quadric (general_binding.cpp)

}  // namespace relpos_python

namespace pybind11::detail {
template <>
class type_caster<relpos::Ellipsoid> : public relpos_python::built_caster<relpos::Ellipsoid> {};
template <>
class type_caster<relpos::Paraboloid> : public relpos_python::built_caster<relpos::Paraboloid> {};
template <>
class type_caster<relpos::Quadric> : public relpos_python::built_caster<relpos::Quadric> {};
template <>
class type_caster<relpos::AlgebraicReal> : public relpos_python::built_caster<relpos::AlgebraicReal> {};
template <>
class type_caster<relpos::FirstContact> : public relpos_python::built_caster<relpos::FirstContact> {};
template <>
class type_caster<relpos::Timeline> : public relpos_python::built_caster<relpos::Timeline> {};
}  // namespace pybind11::detail
