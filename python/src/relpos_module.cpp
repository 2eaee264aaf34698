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
#include <relpos/general_quadric.hpp>
#include <relpos/io.hpp>
#include <relpos/margin.hpp>
#include <relpos/numbers.hpp>
#include <string>

#include "algebra/pair_size.hpp"
#include "io/answer_json.hpp"
#include "margin/family.hpp"
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

/// Whether `t` is an integer or a fraction "p/q" as relpos::to_string writes them: an optional '-',
/// decimal digits, and optionally '/' and digits with a non-zero denominator.
bool is_fraction_text(const std::string& t) {
  std::size_t i = t.size() > 0 && t[0] == '-' ? 1 : 0;
  const auto digits = [&](bool nonzero) {
    const std::size_t begin = i;
    bool any_nonzero = false;
    for (; i < t.size() && t[i] >= '0' && t[i] <= '9'; ++i) any_nonzero = any_nonzero || t[i] != '0';
    return i > begin && (!nonzero || any_nonzero);
  };
  if (!digits(false)) return false;
  if (i == t.size()) return true;
  if (t[i++] != '/') return false;
  return digits(true) && i == t.size();
}

/// The matrix __reduce__ stored (16 exact texts, row-major), read by GMP without the parser's limit
/// on one input number: a validated matrix (a sphere's e0 = |c|^2 - r^2, say) may hold longer ones.
/// Pickled data is input like any other: each text is checked before GMP reads it (a zero
/// denominator would divide by zero), and the matrix is validated by from_matrix.
relpos::Matrix4 matrix_from_texts(py::handle texts) {
  if (!PyTuple_Check(texts.ptr()) || PyTuple_GET_SIZE(texts.ptr()) != 16)
    throw relpos::InputError("pickled quadric: expected a tuple of 16 exact numbers as text");
  relpos::Matrix4 m;
  for (std::size_t k = 0; k < 16; ++k) {
    const py::handle x = PyTuple_GET_ITEM(texts.ptr(), static_cast<py::ssize_t>(k));
    const std::string where = "pickled quadric[" + std::to_string(k / 4) + "][" + std::to_string(k % 4) + "]";
    if (!PyUnicode_Check(x.ptr()))
      throw relpos::InputError(where + ": expected an exact number as text, got " +
                               py::str(py::type::handle_of(x).attr("__name__")).cast<std::string>());
    const std::string text = x.cast<std::string>();
    if (!is_fraction_text(text))
      throw relpos::InputError(where + ": not an exact number \"p/q\" with q > 0: \"" +
                               (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "\"");
    relpos::Rational q;
    mpq_set_str(q.mpq(), text.c_str(), 10);  // checked above: digits, and a non-zero denominator
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

  py::class_<relpos::Quadric> quadric(
      m, "Quadric",
      "A validated real quadric of one of eleven types (doc/quadrics.md): a symmetric 4x4 matrix Q whose solid is "
      "{X^T Q X <= 0} (sign-normalized as the library stores it).");
  quadric.def(py::init([](py::handle description) { return relpos_python::quadric_from_python(description); }),
              "description"_a,
              "From a 4x4 matrix or a dict in any form of a batch line's \"quadric\" (relpos.Quadric.__init__).");
  quadric.def(
      "_type", [](const relpos::Quadric& q) { return relpos::to_string(q.type()); },
      "The type's name: \"ellipsoid\", \"hyperboloid of one sheet\", ..., \"half-space\".");
  bind_quadric_common(quadric, "relpos.Quadric");

  m.def(
      "_rebuild",
      [](py::handle cls, py::handle texts) -> py::object {
        const bool is_ellipsoid = cls.is(py::type::of<relpos::Ellipsoid>());
        const bool is_quadric = cls.is(py::type::of<relpos::Quadric>());
        if (!is_ellipsoid && !is_quadric && !cls.is(py::type::of<relpos::Paraboloid>()))
          throw py::type_error("relpos._rebuild: not a relpos quadric class");
        const relpos::Matrix4 matrix = matrix_from_texts(texts);
        try {
          if (is_ellipsoid) return py::cast(relpos::Ellipsoid::from_matrix(matrix));
          if (is_quadric) return py::cast(relpos::Quadric::from_matrix(matrix));
          return py::cast(relpos::Paraboloid::from_matrix(matrix));
        } catch (const relpos::InputError& err) {
          throw relpos::InputError(std::string("pickled ") +
                                   (is_ellipsoid ? "ellipsoid: "
                                    : is_quadric ? "quadric: "
                                                 : "paraboloid: ") +
                                   err.what());
        }
      },
      "cls"_a, "texts"_a, "The quadric pickled by __reduce__.");

  m.def(
      "_is_built",
      [](py::handle x) {
        return relpos_python::is_built<relpos::Ellipsoid>(x) || relpos_python::is_built<relpos::Paraboloid>(x) ||
               relpos_python::is_built<relpos::Quadric>(x);
      },
      "x"_a, "Whether x is an Ellipsoid, Paraboloid or Quadric whose __init__ has run.");

  m.def(
      "_classify_json",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, bool full, std::size_t max_bits) {
        std::string text;
        {
          py::gil_scoped_release release;
          const relpos::SizeLimit limit{max_bits};
          // The minimal answer as `relpos batch --evidence minimal` computes and writes it.
          text = full ? relpos::io::classification_json_text(relpos::classify(e, p, relpos::Evidence::Full, limit))
                      : relpos::detail::io::minimal_json_text(relpos::decide_position(e, p, limit));
        }
        return text;
      },
      "e"_a, "p"_a, "full"_a = true, "max_bits"_a = relpos::kMaxNormalizedBits,
      "The JSON object of `relpos batch` (or of `relpos batch --evidence minimal`) for the pair, without \"id\", "
      "as text.");

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
      "_margin_json",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, int bits) {
        if (bits < 1 || bits > relpos::detail::kMaxMarginBits)
          throw relpos::InputError("margin_bits: expected an int from 1 to " +
                                   std::to_string(relpos::detail::kMaxMarginBits) + ", got " + std::to_string(bits));
        std::string text;
        {
          py::gil_scoped_release release;
          text = relpos::io::margin_json_text(relpos::margin(e, p, bits));
        }
        return text;
      },
      "e"_a, "p"_a, "bits"_a = relpos::kDefaultMarginBits,
      "The JSON object \"margin\" of `relpos batch --margin-bits BITS` for the pair, as text.");

  m.def(
      "_verify_margin",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, const std::string& margin) {
        const relpos::Margin parsed = relpos::io::margin_from_json_text(margin);
        py::gil_scoped_release release;
        return relpos::verify_margin(e, p, parsed);
      },
      "e"_a, "p"_a, "margin"_a, "The verifier's reason why the margin (JSON text) does not prove s*, or None.");

  m.def(
      "_contact_json",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, std::size_t max_bits) {
        std::string text;
        {
          py::gil_scoped_release release;
          const relpos::SizeLimit limit{max_bits};
          relpos::detail::check_normalized_pair_size(e, p, limit);
          text = relpos::io::contact_json_text(relpos::contact(e, p, limit));
        }
        return text;
      },
      "e"_a, "p"_a, "max_bits"_a = relpos::kMaxNormalizedBits,
      "The JSON object of `relpos classify --contact-only --json` for the pair, as text.");

  m.attr("_MAX_BITS") = relpos::kMaxNormalizedBits;
  relpos_python::bind_decide(m);
  relpos_python::bind_motion(m);
  relpos_python::bind_batch(m);
  relpos_python::bind_oracle(m);
  relpos_python::bind_general(m);
}
