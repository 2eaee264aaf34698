// relpos._relpos: the compiled part of the Python package relpos (doc/python.md).
//
// Only the public headers of the library are used. Every number handed in from Python is converted
// exactly: int and str through relpos::parse_rational, float through relpos::exact_rational (the
// dyadic value of the double), fractions.Fraction through its integer numerator and denominator.
// relpos::InputError becomes ValueError with the library's message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using relpos::InputError;
using relpos::Rational;

// ------------------------------------------------------------------------------------------------
// Exact numbers from Python objects.
// ------------------------------------------------------------------------------------------------

/// module.attr, imported once and kept for the life of the interpreter.
py::handle cached(const char* module, const char* attr) {
  return py::object(py::module_::import(module).attr(attr)).release();
}

std::string type_name(py::handle x) { return py::str(py::type::handle_of(x).attr("__name__")).cast<std::string>(); }

Rational rational_from_int(py::handle x) {
  // str() of a Python int is exact at any size (up to sys.get_int_max_str_digits()).
  return relpos::parse_rational(py::str(x).cast<std::string>());
}

/// The exact value of one entry; `path` names it in error messages ("ellipsoid.matrix[1][2]").
Rational to_rational(py::handle x, const std::string& path) {
  try {
    if (PyBool_Check(x.ptr())) throw InputError("expected a number, got " + py::repr(x).cast<std::string>());
    if (PyUnicode_Check(x.ptr())) return relpos::parse_rational(x.cast<std::string>());
    if (PyLong_Check(x.ptr())) return rational_from_int(x);
    if (PyFloat_Check(x.ptr())) return relpos::exact_rational(x.cast<double>());  // numpy.float64 too
    static const py::handle fraction = cached("fractions", "Fraction");
    if (py::isinstance(x, fraction)) {
      const Rational num = rational_from_int(x.attr("numerator"));
      const Rational den = rational_from_int(x.attr("denominator"));
      return num / den;
    }
    if (py::hasattr(x, "__index__")) return rational_from_int(py::module_::import("operator").attr("index")(x));
    // numpy.float32, numpy.float16: widened to double exactly.
    static const py::handle floating = cached("numpy", "floating");
    if (py::isinstance(x, floating)) return relpos::exact_rational(py::float_(x.attr("__float__")()).cast<double>());
    throw InputError("expected int, float, fractions.Fraction or str, got " + type_name(x));
  } catch (const InputError& err) {
    throw InputError(path + ": " + err.what());
  } catch (const py::error_already_set& err) {
    throw InputError(path + ": " + err.what());
  }
}

/// A sequence of `n` entries (list, tuple, numpy array); `path` names it in error messages.
std::vector<py::object> items(py::handle x, std::size_t n, const std::string& path) {
  const bool sequence = PySequence_Check(x.ptr()) && !PyUnicode_Check(x.ptr()) && !PyBytes_Check(x.ptr());
  if (!sequence || py::len(x) != n)
    throw InputError(path + ": expected " + std::to_string(n) + " entries, got " +
                     (sequence ? std::to_string(py::len(x)) + " entries" : type_name(x)));
  std::vector<py::object> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(x[py::int_(i)]);
  return out;
}

relpos::Matrix4 matrix4(py::handle m, const std::string& path) {
  relpos::Matrix4 out;
  const auto rows = items(m, 4, path);
  for (int i = 0; i < 4; ++i) {
    const std::string row_path = path + "[" + std::to_string(i) + "]";
    const auto row = items(rows[static_cast<std::size_t>(i)], 4, row_path);
    for (int j = 0; j < 4; ++j)
      out(i, j) = to_rational(row[static_cast<std::size_t>(j)], row_path + "[" + std::to_string(j) + "]");
  }
  return out;
}

template <std::size_t N>
std::array<Rational, N> vector_n(py::handle v, const std::string& path) {
  std::array<Rational, N> out;
  const auto x = items(v, N, path);
  for (std::size_t i = 0; i < N; ++i) out[i] = to_rational(x[i], path + "[" + std::to_string(i) + "]");
  return out;
}

/// Runs `make` and prefixes a library InputError with the role, as the CLI does ("ellipsoid: ...").
template <class F>
auto with_role(const std::string& role, F make) {
  try {
    return make();
  } catch (const InputError& err) {
    const std::string what = err.what();
    if (what.rfind(role, 0) == 0) throw;
    throw InputError(role + ": " + what);
  }
}

py::list matrix_to_python(const relpos::Matrix4& m) {
  static const py::handle fraction = cached("fractions", "Fraction");
  py::list rows;
  for (int i = 0; i < 4; ++i) {
    py::list row;
    for (int j = 0; j < 4; ++j) row.append(fraction(relpos::to_string(m(i, j))));
    rows.append(row);
  }
  return rows;
}

py::tuple matrix_to_strings(const relpos::Matrix4& m) {
  py::tuple out(16);
  for (std::size_t k = 0; k < 16; ++k) out[k] = py::str(relpos::to_string(m.a[k]));
  return out;
}

relpos::Matrix4 matrix_from_strings(const py::tuple& t) {
  if (t.size() != 16) throw std::runtime_error("relpos: invalid pickled quadric");
  relpos::Matrix4 m;
  for (std::size_t k = 0; k < 16; ++k) m.a[k] = relpos::parse_rational(t[k].cast<std::string>());
  return m;
}

std::string matrix_repr(const char* name, const relpos::Matrix4& m) {
  std::string s = std::string(name) + "([";
  for (int i = 0; i < 4; ++i) {
    s += i ? ", [" : "[";
    for (int j = 0; j < 4; ++j) s += (j ? ", '" : "'") + relpos::to_string(m(i, j)) + "'";
    s += "]";
  }
  return s + "])";
}

// ------------------------------------------------------------------------------------------------
// decide_positions: float64 matrices.
// ------------------------------------------------------------------------------------------------

// ---- THE place where decide_positions builds its quadrics from float64 matrices. ----
// from_doubles: the shape is certified in doubles (no GMP, no heap allocation); the exact rationals
// are built only if an exact stage of decide_position needs them.
relpos::DoubleMatrix4 double_matrix(const double* m) {
  relpos::DoubleMatrix4 out;
  std::copy(m, m + 16, out.begin());
  return out;
}
relpos::Ellipsoid ellipsoid_from_doubles(const double* m) { return relpos::Ellipsoid::from_doubles(double_matrix(m)); }
relpos::Paraboloid paraboloid_from_doubles(const double* m) {
  return relpos::Paraboloid::from_doubles(double_matrix(m));
}
// ---- end of the construction place. ----

/// Code of a position in relpos.POSITION_NAMES (every pair gets one of the five positions).
std::int8_t position_code(relpos::Position p) {
  switch (p) {
    case relpos::Position::I:
      return 0;
    case relpos::Position::TI:
      return 1;
    case relpos::Position::C:
      return 2;
    case relpos::Position::TE:
      return 3;
    case relpos::Position::E:
      return 4;
  }
  throw std::logic_error("internal error: position_code: not a Position");
}

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Shape check: (n, 4, 4), or (4, 4) when `allow_single`. Returns n (0 for a single matrix).
std::optional<std::size_t> batch_size(const DoubleArray& a, const char* name, bool allow_single) {
  if (allow_single && a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 4) return std::nullopt;
  if (a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 4) return static_cast<std::size_t>(a.shape(0));
  std::string shape = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
  shape += a.ndim() == 1 ? ",)" : ")";
  throw InputError(std::string(name) + ": expected shape (n, 4, 4)" + (allow_single ? " or (4, 4)" : "") + ", got " +
                   shape);
}

py::array_t<std::int8_t> decide_positions(const DoubleArray& e_array, const DoubleArray& p_array, int threads) {
  const std::size_t n = *batch_size(e_array, "E", false);
  const std::optional<std::size_t> np = batch_size(p_array, "P", true);
  if (np && *np != n)
    throw InputError("P: " + std::to_string(*np) + " matrices for " + std::to_string(n) + " ellipsoids");
  if (threads < 0) throw InputError("threads: expected >= 0, got " + std::to_string(threads));
  py::array_t<std::int8_t> out(static_cast<py::ssize_t>(n));
  const double* e_data = e_array.data();
  const double* p_data = p_array.data();
  std::int8_t* codes = out.mutable_data();

  std::optional<relpos::Paraboloid> shared;
  std::size_t error_index = std::numeric_limits<std::size_t>::max();
  std::string error_message;
  {
    py::gil_scoped_release release;
    if (!np) {
      try {
        shared = paraboloid_from_doubles(p_data);
      } catch (const InputError& err) {
        error_message = std::string("P: paraboloid: ") + err.what();
      }
    }
    if (error_message.empty() && n > 0) {
      unsigned workers = threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
      constexpr std::size_t kChunk = 64;
      const std::size_t chunks = (n + kChunk - 1) / kChunk;
      workers = static_cast<unsigned>(std::clamp<std::size_t>(workers, 1, chunks));
      std::atomic<std::size_t> next{0};
      std::mutex error_mutex;
      auto work = [&] {
        for (;;) {
          const std::size_t begin = next.fetch_add(kChunk);
          if (begin >= n) return;
          const std::size_t end = std::min(n, begin + kChunk);
          for (std::size_t i = begin; i < end; ++i) {
            const char* failed = "E";
            try {
              const relpos::Ellipsoid e = ellipsoid_from_doubles(e_data + 16 * i);
              if (shared) {
                codes[i] = position_code(relpos::decide_position(e, *shared).position);
              } else {
                failed = "P";
                const relpos::Paraboloid p = paraboloid_from_doubles(p_data + 16 * i);
                codes[i] = position_code(relpos::decide_position(e, p).position);
              }
            } catch (const std::exception& err) {
              codes[i] = -1;
              const std::lock_guard<std::mutex> lock(error_mutex);
              if (i < error_index) {
                error_index = i;
                error_message = std::string(failed) + "[" + std::to_string(i) +
                                "]: " + (failed[0] == 'E' ? "ellipsoid: " : "paraboloid: ") + err.what();
              }
            }
          }
        }
      };
      std::vector<std::thread> pool;
      for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
      work();
      for (auto& t : pool) t.join();
    }
  }
  if (!error_message.empty()) throw InputError(error_message);
  return out;
}

}  // namespace

PYBIND11_MODULE(_relpos, m) {
  m.doc() = "relpos: exact relative position of an ellipsoid and an elliptic paraboloid (compiled part)";
  relpos::install_gmp_block_cache();  // many small GMP blocks per pair (relpos/numbers.hpp)
  // relpos::InputError derives from std::invalid_argument; translated explicitly all the same.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& err) {
      PyErr_SetString(PyExc_ValueError, err.what());
    }
  });

  py::class_<relpos::Ellipsoid>(m, "Ellipsoid",
                                "A validated ellipsoid: a symmetric 4x4 matrix E with x^T E x = 0 on the surface, "
                                "x = (x, y, z, 1) (sign-normalized: inside is negative).")
      .def(py::init([](py::handle matrix) {
             return with_role("ellipsoid",
                              [&] { return relpos::Ellipsoid::from_matrix(matrix4(matrix, "ellipsoid.matrix")); });
           }),
           "m"_a,
           "From a 4x4 nested list or numpy array of int, float (exact), fractions.Fraction or str ('p/q', "
           "decimals).")
      .def_static(
          "sphere",
          [](py::handle center, py::handle radius) {
            return with_role("ellipsoid", [&] {
              return relpos::Ellipsoid::sphere(vector_n<3>(center, "ellipsoid.center"),
                                               to_rational(radius, "ellipsoid.radius"));
            });
          },
          "center"_a, "radius"_a, "The sphere |x - center| = radius.")
      .def_static(
          "from_axes",
          [](py::handle center, py::handle axes, py::handle rotation) {
            return with_role("ellipsoid", [&] {
              return relpos::Ellipsoid::from_axes(vector_n<3>(center, "ellipsoid.center"),
                                                  vector_n<3>(axes, "ellipsoid.axes"),
                                                  vector_n<4>(rotation, "ellipsoid.rotation"));
            });
          },
          "center"_a, "axes"_a, "rotation"_a = py::make_tuple(1, 0, 0, 0),
          "Semi-axes `axes` along the columns of the rotation R(q)/|q|^2 of the quaternion q = (w, x, y, z).")
      .def(
          "matrix", [](const relpos::Ellipsoid& e) { return matrix_to_python(e.matrix()); },
          "The sign-normalized matrix as a list of lists of fractions.Fraction.")
      .def("__repr__", [](const relpos::Ellipsoid& e) { return matrix_repr("relpos.Ellipsoid", e.matrix()); })
      .def(py::pickle([](const relpos::Ellipsoid& e) { return matrix_to_strings(e.matrix()); },
                      [](const py::tuple& t) { return relpos::Ellipsoid::from_matrix(matrix_from_strings(t)); }));

  py::class_<relpos::Paraboloid>(m, "Paraboloid",
                                 "A validated elliptic paraboloid: a symmetric 4x4 matrix (inside the cup is "
                                 "negative).")
      .def(py::init([](py::handle matrix) {
             return with_role("paraboloid",
                              [&] { return relpos::Paraboloid::from_matrix(matrix4(matrix, "paraboloid.matrix")); });
           }),
           "m"_a,
           "From a 4x4 nested list or numpy array of int, float (exact), fractions.Fraction or str ('p/q', "
           "decimals).")
      .def_static(
          "standard",
          [](py::handle vertex, py::handle a, py::handle b, py::handle rotation) {
            return with_role("paraboloid", [&] {
              return relpos::Paraboloid::standard(vector_n<3>(vertex, "paraboloid.vertex"),
                                                  to_rational(a, "paraboloid.a"), to_rational(b, "paraboloid.b"),
                                                  vector_n<4>(rotation, "paraboloid.rotation"));
            });
          },
          "vertex"_a, "a"_a, "b"_a, "rotation"_a = py::make_tuple(1, 0, 0, 0),
          "x'^2/a^2 + y'^2/b^2 = z' in the frame with origin `vertex` and axes the columns of R(q)/|q|^2.")
      .def(
          "matrix", [](const relpos::Paraboloid& p) { return matrix_to_python(p.matrix()); },
          "The sign-normalized matrix as a list of lists of fractions.Fraction.")
      .def("__repr__", [](const relpos::Paraboloid& p) { return matrix_repr("relpos.Paraboloid", p.matrix()); })
      .def(py::pickle([](const relpos::Paraboloid& p) { return matrix_to_strings(p.matrix()); },
                      [](const py::tuple& t) { return relpos::Paraboloid::from_matrix(matrix_from_strings(t)); }));

  m.def(
      "_classify_json",
      [](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, bool full) {
        std::string text;
        {
          py::gil_scoped_release release;
          relpos::check_normalized_pair_size(e, p);  // the CLI's limit (doc/cli.md, Limits)
          const relpos::Classification c =
              relpos::classify(e, p, full ? relpos::Evidence::Full : relpos::Evidence::Minimal);
          text = relpos::io::classification_json_text(c);
        }
        return text;
      },
      "e"_a, "p"_a, "full"_a = true, "The JSON object of `relpos batch` for the pair (without \"id\"), as text.");

  m.def("_decide_positions", &decide_positions, "E"_a, "P"_a, "threads"_a = 0,
        "Position codes (int8, 0 = I ... 4 = E) of float64 matrices E (n, 4, 4) against P (n, 4, 4) or (4, 4).");
  void bind_batch(py::module_&);  // python/src/batch_binding.cpp
  bind_batch(m);
}
