// relpos._relpos: the compiled part of the Python package relpos (doc/python.md).
//
// Every description handed in from Python is turned into the JSON value the CLI would read and read
// by the CLI's reader (input.cpp, through src/io's private tree readers), so numbers are exact and
// messages are the CLI's; answers are the library's JSON text. relpos::InputError becomes ValueError.
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/contact.hpp>
#include <relpos/io.hpp>
#include <relpos/numbers.hpp>
#include <string>

#include "module.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

py::list matrix_to_python(const relpos::Matrix4& m) {
  py::list rows;
  for (int i = 0; i < 4; ++i) {
    py::list row;
    for (int j = 0; j < 4; ++j) row.append(relpos_python::to_python(m(i, j)));
    rows.append(row);
  }
  return rows;
}

/// The matrix __reduce__ stored (16 exact texts, row-major), read by GMP without the parser's limit
/// on one input number: a validated matrix (a sphere's e0 = |c|^2 - r^2, say) may hold longer ones.
relpos::Matrix4 matrix_from_texts(const py::tuple& texts) {
  if (texts.size() != 16) throw py::type_error("relpos: a pickled quadric holds 16 numbers");
  relpos::Matrix4 m;
  for (std::size_t k = 0; k < 16; ++k) {
    relpos::Rational q;
    if (mpq_set_str(q.mpq(), texts[k].cast<std::string>().c_str(), 10) != 0)
      throw py::type_error("relpos: invalid pickled number");
    mpq_canonicalize(q.mpq());
    m.a[k] = q;
  }
  return m;
}

py::tuple matrix_to_texts(const relpos::Matrix4& m) {
  py::tuple out(16);
  for (std::size_t k = 0; k < 16; ++k) out[k] = py::str(relpos::to_string(m.a[k]));
  return out;
}

/// The exact entries as text ("p/q"), rows of four: what __repr__ shows and the constructor reads
/// back exactly.
py::list matrix_to_strings(const relpos::Matrix4& m) {
  py::list rows;
  for (int i = 0; i < 4; ++i) {
    py::list row;
    for (int j = 0; j < 4; ++j) row.append(py::str(relpos::to_string(m(i, j))));
    rows.append(row);
  }
  return rows;
}

std::string matrix_repr(const char* name, const relpos::Matrix4& m) {
  return std::string(name) + "(" + py::repr(matrix_to_strings(m)).cast<std::string>() + ")";
}

/// The methods Ellipsoid and Paraboloid share: the matrix, repr, pickling (relpos._rebuild on the
/// exact texts of the matrix, at every protocol), == on the exact matrices, and a hash consistent
/// with it.
template <class Q>
void bind_quadric_common(py::class_<Q>& c, const char* repr_name) {
  c.def(
       "_matrix", [](const Q& q) { return matrix_to_python(q.matrix()); },
       "The validated, sign-normalized matrix (inside is negative) as a list of 4 lists of fractions.Fraction.")
      .def("__repr__", [repr_name](const Q& q) { return matrix_repr(repr_name, q.matrix()); })
      .def(
          "__reduce__",
          [](const Q& q) {
            static const py::handle rebuild = py::object(py::module_::import("relpos").attr("_rebuild")).release();
            return py::make_tuple(rebuild, py::make_tuple(py::type::of<Q>(), matrix_to_texts(q.matrix())));
          },
          "Pickling support (every protocol): the exact matrix as text.")
      .def(
          "__eq__",
          [](const Q& a, py::handle b) -> py::object {
            if (!relpos_python::is_built<Q>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            return py::bool_(a.matrix() == b.cast<const Q&>().matrix());
          },
          py::is_operator())
      .def("__hash__", [](const Q& q) { return py::hash(matrix_to_texts(q.matrix())); });
}

}  // namespace

PYBIND11_MODULE(_relpos, m) {
  m.doc() = "relpos: exact relative position of an ellipsoid and an elliptic paraboloid (compiled part)";
  relpos::install_gmp_block_cache();  // many small GMP blocks per pair (relpos/numbers.hpp)
  // relpos::InputError derives from std::invalid_argument; translated explicitly all the same.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const relpos::InputError& err) {
      PyErr_SetString(PyExc_ValueError, err.what());
    }
  });

  py::class_<relpos::Ellipsoid> ellipsoid(
      m, "Ellipsoid",
      "A validated ellipsoid: a symmetric 4x4 matrix E with X^T E X = 0 on the surface, X = (x, y, z, 1) "
      "(sign-normalized: inside is negative).");
  ellipsoid.def(py::init([](py::handle description) { return relpos_python::ellipsoid_from_python(description); }),
                "description"_a,
                "From a 4x4 matrix or a dict in any JSON form of the CLI (relpos.Ellipsoid.__init__).");
  bind_quadric_common(ellipsoid, "relpos.Ellipsoid");

  py::class_<relpos::Paraboloid> paraboloid(
      m, "Paraboloid", "A validated elliptic paraboloid: a symmetric 4x4 matrix (inside the cup is negative).");
  paraboloid.def(py::init([](py::handle description) { return relpos_python::paraboloid_from_python(description); }),
                 "description"_a,
                 "From a 4x4 matrix or a dict in any JSON form of the CLI (relpos.Paraboloid.__init__).");
  bind_quadric_common(paraboloid, "relpos.Paraboloid");

  m.def(
      "_rebuild",
      [](py::handle cls, const py::tuple& texts) -> py::object {
        const relpos::Matrix4 matrix = matrix_from_texts(texts);
        if (cls.is(py::type::of<relpos::Ellipsoid>())) return py::cast(relpos::Ellipsoid::from_matrix(matrix));
        if (cls.is(py::type::of<relpos::Paraboloid>())) return py::cast(relpos::Paraboloid::from_matrix(matrix));
        throw py::type_error("relpos._rebuild: not a relpos quadric class");
      },
      "cls"_a, "texts"_a, "The quadric pickled by __reduce__.");

  m.def(
      "_is_built",
      [](py::handle x) {
        return relpos_python::is_built<relpos::Ellipsoid>(x) || relpos_python::is_built<relpos::Paraboloid>(x);
      },
      "x"_a, "Whether x is an Ellipsoid or Paraboloid whose __init__ has run.");

  m.def(
      "_classify_json",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, bool full) {
        std::string text;
        {
          py::gil_scoped_release release;
          const relpos::Classification c =
              relpos::classify(e, p, full ? relpos::Evidence::Full : relpos::Evidence::Minimal);
          text = relpos::io::classification_json_text(c);
        }
        return text;
      },
      "e"_a, "p"_a, "full"_a = true, "The JSON object of `relpos batch` for the pair (without \"id\"), as text.");

  m.def(
      "_verify",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, const std::string& position,
         const std::string& certificate) -> std::optional<std::string> {
        const auto* found = std::find_if(relpos::kAllPositions.begin(), relpos::kAllPositions.end(),
                                         [&](relpos::Position q) { return relpos::to_string(q) == position; });
        if (found == relpos::kAllPositions.end())
          throw relpos::InputError("position \"" + position + "\" is not one of I, TI, C, TE, E");
        const relpos::Certificate c = relpos::certificate_from_json(certificate);
        py::gil_scoped_release release;
        return relpos::verify_certificate(e, p, *found, c);
      },
      "e"_a, "p"_a, "position"_a, "certificate"_a,
      "The independent verifier's reason why the certificate (JSON text) does not prove the position, or None.");

  m.def(
      "_contact_json",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p) {
        std::string text;
        {
          py::gil_scoped_release release;
          relpos::check_normalized_pair_size(e, p);
          text = relpos::io::contact_json_text(relpos::contact(e, p));
        }
        return text;
      },
      "e"_a, "p"_a, "The JSON object of `relpos classify --contact-only --json` for the pair, as text.");

  relpos_python::bind_decide(m);
  relpos_python::bind_motion(m);
  relpos_python::bind_batch(m);
}
