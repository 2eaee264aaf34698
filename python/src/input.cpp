// Python objects read exactly (module.hpp): every description goes through the CLI's JSON reader
// (src/io/quadric_json.hpp), so a value reads and fails exactly as the same text does in
// `relpos batch`.
#include <optional>
#include <relpos/numbers.hpp>
#include <string>

#include "io/general_io.hpp"
#include "io/json_values.hpp"
#include "io/quadric_json.hpp"
#include "module.hpp"

namespace relpos_python {

namespace {

std::string type_name(py::handle x) { return py::str(py::type::handle_of(x).attr("__name__")).cast<std::string>(); }

/// The value of a Python int when it fits in a long long.
std::optional<long long> small_int(py::handle x) {
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(x.ptr(), &overflow);
  if (overflow) return std::nullopt;
  if (value == -1 && PyErr_Occurred()) throw py::error_already_set();
  return value;
}

/// The decimal digits of a Python int of any size. str(int) is refused beyond
/// sys.get_int_max_str_digits() digits; the bytes of the int are not, and GMP writes the digits.
std::string int_text(py::handle x) {
  if (const auto small = small_int(x)) return std::to_string(*small);
  const py::object magnitude = py::reinterpret_steal<py::object>(PyNumber_Absolute(x.ptr()));
  if (!magnitude) throw py::error_already_set();
  const std::size_t bytes = (magnitude.attr("bit_length")().cast<std::size_t>() + 7) / 8;
  const std::string data = magnitude.attr("to_bytes")(bytes, "little").cast<py::bytes>();
  relpos::Integer z;
  mpz_import(z.mpz(), data.size(), -1, 1, 0, 0, data.data());
  if (!magnitude.equal(x)) mpz_neg(z.mpz(), z.mpz());
  return relpos::to_string(z);
}

/// An integer JSON value: the int itself when it fits in 64 bits, else its exact digits (which the
/// reader parses as the CLI parses a long integer, with the same size limit).
Json int_json(py::handle x) {
  if (const auto small = small_int(x)) return Json(static_cast<std::int64_t>(*small));
  return Json(int_text(x));
}

bool is_sequence(py::handle x) {
  return PySequence_Check(x.ptr()) && !PyUnicode_Check(x.ptr()) && !PyBytes_Check(x.ptr()) &&
         !PyByteArray_Check(x.ptr());
}

}  // namespace

Json to_json(py::handle x, const std::string& path) {
  if (x.is_none()) return Json(nullptr);
  if (PyBool_Check(x.ptr())) return Json(x.ptr() == Py_True);
  if (PyLong_Check(x.ptr())) return int_json(x);
  if (PyFloat_Check(x.ptr())) return Json(PyFloat_AsDouble(x.ptr()));  // numpy.float64 too; exact
  if (PyUnicode_Check(x.ptr())) return Json(x.cast<std::string>());
  if (PyDict_Check(x.ptr())) {
    Json out = Json::object();
    for (const auto& item : py::reinterpret_borrow<py::dict>(x)) {
      if (!PyUnicode_Check(item.first.ptr()))
        throw py::type_error(path + ": expected str keys, got " + type_name(item.first));
      const std::string key = item.first.cast<std::string>();
      out[key] = to_json(item.second, path + "." + key);
    }
    return out;
  }
  static const py::handle numpy_bool = py::object(py::module_::import("numpy").attr("bool_")).release();
  static const py::handle numpy_array = py::object(py::module_::import("numpy").attr("ndarray")).release();
  if (py::isinstance(x, numpy_bool)) return Json(PyObject_IsTrue(x.ptr()) == 1);  // refused as a bool
  if (py::isinstance(x, numpy_array) && x.attr("ndim").cast<int>() == 0)
    return to_json(x[py::tuple()], path);  // a 0-d array: its scalar
  if (is_sequence(x)) {
    Json out = Json::array();
    const py::ssize_t n = PySequence_Size(x.ptr());
    if (n < 0) throw py::error_already_set();
    for (py::ssize_t i = 0; i < n; ++i) out.push_back(to_json(x[py::int_(i)], path + "[" + std::to_string(i) + "]"));
    return out;
  }
  if (py::hasattr(x, "__index__")) {  // numpy integers
    const py::object value = py::reinterpret_steal<py::object>(PyNumber_Index(x.ptr()));
    if (!value) throw py::error_already_set();
    return int_json(value);
  }
  static const py::handle decimal = py::object(py::module_::import("decimal").attr("Decimal")).release();
  if (py::isinstance(x, decimal) && x.attr("is_finite")().cast<bool>()) {
    // Its own decimal text ("1E-12000"), read exactly by the parser: the same number and the same
    // limits as that string (as_integer_ratio would spell 10^12000 out against the length limit).
    return Json(py::str(x).cast<std::string>());
  }
  if (py::hasattr(x, "as_integer_ratio")) {
    // fractions.Fraction, numpy.float16/32/longdouble: p/q exactly; a Decimal NaN or infinity gets
    // the library's message for it below.
    py::tuple ratio;
    try {
      ratio = x.attr("as_integer_ratio")();
    } catch (const py::error_already_set&) {  // NaN, infinity: the library's message for them
      PyErr_Clear();
      const double value = PyFloat_AsDouble(x.ptr());
      if (value == -1.0 && PyErr_Occurred()) {  // a signalling NaN
        PyErr_Clear();
        throw relpos::InputError(path + ": not a finite number: " + py::str(x).cast<std::string>());
      }
      return Json(value);
    }
    const std::string q = int_text(ratio[1]);
    return Json(int_text(ratio[0]) + (q == "1" ? "" : "/" + q));
  }
  throw py::type_error(path + ": expected int, float, fractions.Fraction, str or a sequence, got " + type_name(x));
}

py::object to_python(const relpos::Integer& z) {
  if (mpz_fits_slong_p(z.mpz())) return py::reinterpret_steal<py::object>(PyLong_FromLong(mpz_get_si(z.mpz())));
  // int(str) is refused beyond sys.get_int_max_str_digits() digits; int.from_bytes is not.
  std::string bytes((mpz_sizeinbase(z.mpz(), 2) + 7) / 8, '\0');
  std::size_t written = 0;
  mpz_export(bytes.data(), &written, -1, 1, 0, 0, z.mpz());
  bytes.resize(written);
  static const py::handle from_bytes =
      py::object(py::module_::import("builtins").attr("int").attr("from_bytes")).release();
  py::object magnitude = from_bytes(py::bytes(bytes), "little");
  return mpz_sgn(z.mpz()) < 0 ? py::reinterpret_steal<py::object>(PyNumber_Negative(magnitude.ptr())) : magnitude;
}

py::object to_python(const relpos::Rational& q) {
  static const py::handle fraction = py::object(py::module_::import("fractions").attr("Fraction")).release();
  return fraction(to_python(q.numerator()), to_python(q.denominator()));
}

relpos::Rational to_rational(py::handle x, const std::string& path) {
  return relpos::detail::io::rational_from_json(to_json(x, path), path);
}

namespace {

/// The 16 entries of a 4x4 matrix when each is a double as it stands (a native float64 array, or
/// a sequence of 4 sequences of Python floats and ints of at most 53 bits): no value is rounded.
std::optional<relpos::DoubleMatrix4> exact_doubles(py::handle x) {
  relpos::DoubleMatrix4 d;
  if (py::isinstance<py::array>(x)) {
    const auto a = py::reinterpret_borrow<py::array>(x);
    if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4 || !a.dtype().equal(py::dtype::of<double>()))
      return std::nullopt;
    const auto r = a.unchecked<double, 2>();
    for (py::ssize_t i = 0; i < 4; ++i)
      for (py::ssize_t j = 0; j < 4; ++j) d[static_cast<std::size_t>(4 * i + j)] = r(i, j);
    return d;
  }
  if (!PyList_Check(x.ptr()) && !PyTuple_Check(x.ptr())) return std::nullopt;
  const auto rows = py::reinterpret_borrow<py::sequence>(x);
  if (rows.size() != 4) return std::nullopt;
  for (std::size_t i = 0; i < 4; ++i) {
    const py::handle row = rows[i];
    if (!PyList_Check(row.ptr()) && !PyTuple_Check(row.ptr())) return std::nullopt;
    const auto entries = py::reinterpret_borrow<py::sequence>(row);
    if (entries.size() != 4) return std::nullopt;
    for (std::size_t j = 0; j < 4; ++j) {
      PyObject* v = entries[j].ptr();
      double& out = d[4 * i + j];
      if (PyFloat_Check(v)) {
        out = PyFloat_AS_DOUBLE(v);
      } else if (PyLong_CheckExact(v)) {
        int overflow = 0;
        const long long n = PyLong_AsLongLongAndOverflow(v, &overflow);
        if (overflow || n > (1LL << 53) || n < -(1LL << 53)) return std::nullopt;
        out = static_cast<double>(n);
      } else {
        return std::nullopt;
      }
    }
  }
  return d;
}

template <class Q>
Q described_quadric(py::handle description, const char* role, Q (*from_json)(const Json&, const std::string&)) {
  if (const auto d = exact_doubles(description)) {
    try {
      return Q::from_doubles(*d);
    } catch (const relpos::InputError&) {  // the reader below words the error as the CLI does
    }
  }
  const Json json = to_json(description, role);
  py::gil_scoped_release release;  // the exact validation (numbers may have thousands of digits)
  return from_json(json, role);
}

}  // namespace

relpos::Ellipsoid ellipsoid_from_python(py::handle description) {
  return described_quadric<relpos::Ellipsoid>(description, "ellipsoid", relpos::detail::io::ellipsoid_from_tree);
}

relpos::Paraboloid paraboloid_from_python(py::handle description) {
  return described_quadric<relpos::Paraboloid>(description, "paraboloid", relpos::detail::io::paraboloid_from_tree);
}

relpos::Quadric quadric_from_python(py::handle description) {
  return described_quadric<relpos::Quadric>(description, "quadric", relpos::detail::io::quadric_from_json);
}

void throw_unbuilt(py::handle x) {
  throw py::type_error("relpos." + type_name(x) + ": the object was made by __new__ without __init__ (not built)");
}

}  // namespace relpos_python
