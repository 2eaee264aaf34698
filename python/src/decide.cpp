// relpos._relpos._decide_positions: the positions of many pairs given as numpy matrices, exactly, on
// every core (doc/python.md, "decide_positions").
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/general_classify.hpp>
#include <relpos/numbers.hpp>
#include <relpos/scene.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "algebra/pair_size.hpp"
#include "base/worker_pool.hpp"
#include "decide/stages.hpp"
#include "io/general_io.hpp"
#include "module.hpp"
#include "scene/chunk_loop.hpp"
#include "scene/scene_pool.hpp"
#include "signals.hpp"

namespace relpos_python {

namespace {

using namespace pybind11::literals;

// An int64 or uint64 entry converts to long double exactly only with a 64-bit significand (x86-64's
// extended precision, or a quad type).
static_assert(std::numeric_limits<long double>::digits >= 64, "long double must hold every 64-bit integer");

/// Code of a position in relpos.POSITION_NAMES; kInvalid for a pair that could not be read.
std::int8_t position_code(relpos::Position p) { return static_cast<std::int8_t>(p); }
constexpr std::int8_t kInvalid = -1;
static_assert(static_cast<int>(relpos::Position::I) == 0 && static_cast<int>(relpos::Position::E) == 4,
              "codes are the order of relpos.POSITION_NAMES");

/// The exact value of a long double (a dyadic rational): its significand peeled into doubles, each
/// exact (the remainder of rounding to a double is a long double again), times 2^exponent.
relpos::Rational exact_rational(long double x) {
  if (!std::isfinite(x)) return relpos::exact_rational(static_cast<double>(x));  // the library's refusal
  int exponent = 0;
  long double m = std::frexp(x, &exponent);  // x = m 2^exponent, 1/2 <= |m| < 1
  relpos::Rational r(0);
  while (m != 0) {
    const double d = static_cast<double>(m);
    r += relpos::exact_rational(d);
    m -= d;
  }
  relpos::Integer power;
  mpz_setbit(power.mpz(), static_cast<mp_bitcnt_t>(std::abs(exponent)));
  return exponent >= 0 ? r * relpos::Rational(power) : r / relpos::Rational(power);
}

/// The lower triangle of a row-major 4x4 matrix replaced by its upper one (symmetrize="upper").
template <class T>
void mirror_upper(T* m) {
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < i; ++j) m[4 * i + j] = m[4 * j + i];
}

/// One input array: float64 read directly, or long double (for numpy.longdouble and 64-bit integer
/// arrays, converted exactly) whose matrices take the double path when every entry is a double.
/// With `upper`, each matrix is read from its upper triangle (doc/python.md, "symmetrize").
struct Matrices {
  py::array array;
  const double* doubles = nullptr;
  const long double* extended = nullptr;
  bool upper = false;

  /// Matrix i as doubles, mirrored when asked (doubles arrays only).
  relpos::DoubleMatrix4 doubles_at(std::size_t i) const {
    relpos::DoubleMatrix4 d;
    std::copy(doubles + 16 * i, doubles + 16 * i + 16, d.begin());
    if (upper) mirror_upper(d.data());
    return d;
  }

  template <class Q, class FromDoubles, class FromMatrix>
  Q at(std::size_t i, FromDoubles from_doubles, FromMatrix from_matrix) const {
    relpos::DoubleMatrix4 d;
    if (doubles) return from_doubles(doubles_at(i));
    std::array<long double, 16> m;
    std::copy(extended + 16 * i, extended + 16 * i + 16, m.begin());
    if (upper) mirror_upper(m.data());
    bool all_doubles = true;
    for (std::size_t k = 0; k < 16; ++k) {
      d[k] = static_cast<double>(m[k]);
      all_doubles = all_doubles && static_cast<long double>(d[k]) == m[k];
    }
    if (all_doubles) return from_doubles(d);
    relpos::Matrix4 exact;
    for (std::size_t k = 0; k < 16; ++k) exact.a[k] = exact_rational(m[k]);
    return from_matrix(exact);
  }
  relpos::Ellipsoid ellipsoid(std::size_t i) const {
    return at<relpos::Ellipsoid>(i, relpos::Ellipsoid::from_doubles, relpos::Ellipsoid::from_matrix);
  }
  relpos::Paraboloid paraboloid(std::size_t i) const {
    return at<relpos::Paraboloid>(i, relpos::Paraboloid::from_doubles, relpos::Paraboloid::from_matrix);
  }
};

/// The array `x` read without rounding, or TypeError for a dtype that cannot be (complex, bool,
/// object, str, ...). float16/32 and integers of up to 32 bits widen to float64 exactly; float64 as
/// is; longdouble and 64-bit integers as long double.
Matrices read_array(py::handle x, const char* name) {
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(x);
  } catch (const py::error_already_set& err) {  // ragged nesting, objects numpy cannot hold
    if (!err.matches(PyExc_ValueError) && !err.matches(PyExc_TypeError)) throw;
    throw py::type_error(std::string(name) + ": expected an array (n, 4, 4) of numbers, got " +
                         py::str(py::type::handle_of(x).attr("__name__")).cast<std::string>() + " that is not one (" +
                         err.what() + ")");
  }
  const char kind = a.dtype().kind();
  const py::ssize_t size = a.dtype().itemsize();
  Matrices out;
  if ((kind == 'f' && size <= 8) || ((kind == 'i' || kind == 'u') && size <= 4)) {
    out.array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    out.doubles = static_cast<const double*>(out.array.data());
  } else if (kind == 'f' || kind == 'i' || kind == 'u') {
    out.array = py::array_t<long double, py::array::c_style | py::array::forcecast>::ensure(a);
    out.extended = static_cast<const long double*>(out.array.data());
  } else {
    throw py::type_error(std::string(name) + ": expected an array of floats or integers (read exactly), got dtype " +
                         py::str(a.dtype()).cast<std::string>());
  }
  if (!out.array) throw py::error_already_set();
  return out;
}

/// Shape check: (n, 4, 4), or (4, 4) when `allow_single`. Returns n (nullopt for a single matrix).
std::optional<std::size_t> batch_size(const py::array& a, const char* name, bool allow_single) {
  if (allow_single && a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 4) return std::nullopt;
  if (a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 4) return static_cast<std::size_t>(a.shape(0));
  std::string shape = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
  shape += a.ndim() == 1 ? ",)" : ")";
  throw relpos::InputError(std::string(name) + ": expected shape (n, 4, 4)" + (allow_single ? " or (4, 4)" : "") +
                           ", got " + shape);
}

std::string shape_text(const py::array& a) {
  std::string shape = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
  return shape + (a.ndim() == 1 ? ",)" : ")");
}

/// The parameters of one side, as arrays read exactly (doc/python.md, "Parameters"): an ellipsoid's
/// "center" (n, 3), "axes" (n, 3) and "rotation" (n, 4), or a paraboloid's "vertex" (n, 3), "a" (n,),
/// "b" (n,) and "rotation" (n, 4); "rotation" may be left out (no rotation), and an array without the
/// leading n is shared by every pair. The quadrics are the JSON forms' (doc/cli.md): congruences of
/// the standard forms, never refused for their shape.
struct Parameters {
  struct Column {
    Matrices values;
    std::size_t width = 0;
    bool shared = true;
    /// Entry k of row i, exactly: a double, or the exact value of a long double.
    bool double_at(std::size_t i, std::size_t k, double& out) const {
      const std::size_t at = (shared ? 0 : i * width) + k;
      if (values.doubles) return out = values.doubles[at], true;
      out = static_cast<double>(values.extended[at]);
      return static_cast<long double>(out) == values.extended[at];
    }
    relpos::Rational exact_at(std::size_t i, std::size_t k) const {
      const std::size_t at = (shared ? 0 : i * width) + k;
      return values.doubles ? relpos::exact_rational(values.doubles[at]) : exact_rational(values.extended[at]);
    }
  };
  std::vector<Column> columns;  // ellipsoid: center, axes, rotation; paraboloid: vertex, a, b, rotation
  std::optional<std::size_t> n;
  bool has_rotation = false;

  Parameters(py::handle mapping, const char* name, bool ellipsoid) {
    const std::vector<std::pair<const char*, std::size_t>> keys =
        ellipsoid
            ? std::vector<std::pair<const char*, std::size_t>>{{"center", 3}, {"axes", 3}, {"rotation", 4}}
            : std::vector<std::pair<const char*, std::size_t>>{{"vertex", 3}, {"a", 1}, {"b", 1}, {"rotation", 4}};
    const py::dict d = py::reinterpret_borrow<py::dict>(mapping);
    for (const auto& item : d) {
      const std::string key = py::str(item.first).cast<std::string>();
      if (std::none_of(keys.begin(), keys.end(), [&](const auto& k) { return key == k.first; }) &&
          !(ellipsoid && key == "centre"))
        throw relpos::InputError(
            std::string(name) + ": unknown key '" + key + "' (the parameters of " +
            (ellipsoid ? "an ellipsoid: center, axes, rotation)" : "a paraboloid: vertex, a, b, rotation)"));
    }
    for (const auto& [key, width] : keys) {
      py::object value;
      if (d.contains(key))
        value = d[key];
      else if (ellipsoid && std::string(key) == "center" && d.contains("centre"))
        value = d["centre"];
      if (!value) {
        if (std::string(key) != "rotation") throw relpos::InputError(std::string(name) + ": '" + key + "' is missing");
        value = py::module_::import("numpy").attr("array")(py::make_tuple(1.0, 0.0, 0.0, 0.0));
      } else if (std::string(key) == "rotation") {
        has_rotation = true;
      }
      const std::string path = std::string(name) + "['" + key + "']";
      Column c{read_array(value, path.c_str()), width, true};
      const py::array& a = c.values.array;
      const bool one = width == 1 ? a.ndim() == 0 : a.ndim() == 1 && a.shape(0) == static_cast<py::ssize_t>(width);
      const bool many = width == 1 ? a.ndim() == 1 : a.ndim() == 2 && a.shape(1) == static_cast<py::ssize_t>(width);
      if (!one && !many)
        throw relpos::InputError(path + ": expected shape " +
                                 (width == 1
                                      ? std::string("(n,) or ()")
                                      : "(n, " + std::to_string(width) + ") or (" + std::to_string(width) + ",)") +
                                 ", got " + shape_text(a));
      if (many) {
        c.shared = false;
        const std::size_t rows = static_cast<std::size_t>(a.shape(0));
        if (n && *n != rows)
          throw relpos::InputError(path + ": " + std::to_string(rows) + " rows for " + std::to_string(*n) + " pairs");
        n = rows;
      }
      columns.push_back(std::move(c));
    }
  }

  template <std::size_t N>
  bool doubles(std::size_t column, std::size_t i, std::array<double, N>& out) const {
    bool all = true;
    for (std::size_t k = 0; k < N; ++k) all = columns[column].double_at(i, k, out[k]) && all;
    return all;
  }
  template <std::size_t N>
  std::array<relpos::Rational, N> exact(std::size_t column, std::size_t i) const {
    std::array<relpos::Rational, N> out;
    for (std::size_t k = 0; k < N; ++k) out[k] = columns[column].exact_at(i, k);
    return out;
  }

  relpos::Ellipsoid ellipsoid(std::size_t i) const {
    std::array<double, 3> c, ax;
    std::array<double, 4> q;
    if (doubles(0, i, c) & doubles(1, i, ax) & doubles(2, i, q)) return relpos::Ellipsoid::from_axes(c, ax, q);
    return relpos::Ellipsoid::from_axes(exact<3>(0, i), exact<3>(1, i), exact<4>(2, i));
  }
  relpos::Paraboloid paraboloid(std::size_t i) const {
    std::array<double, 3> v;
    std::array<double, 1> a, b;
    std::array<double, 4> q;
    if (doubles(0, i, v) & doubles(1, i, a) & doubles(2, i, b) & doubles(3, i, q))
      return relpos::Paraboloid::standard(v, a[0], b[0], q);
    return relpos::Paraboloid::standard(exact<3>(0, i), exact<1>(1, i)[0], exact<1>(2, i)[0], exact<4>(3, i));
  }
};

/// One side of decide_positions: matrices (n, 4, 4) or (4, 4), or parameters.
struct Side {
  std::optional<Matrices> matrices;
  std::optional<Parameters> parameters;
  std::optional<std::size_t> n;  // nullopt: one quadric shared by every pair

  Side(py::handle x, const char* name, bool ellipsoid, bool upper) {
    if (PyDict_Check(x.ptr())) {
      parameters.emplace(x, name, ellipsoid);
      n = parameters->n;
      return;
    }
    matrices = read_array(x, name);
    matrices->upper = upper;
    n = batch_size(matrices->array, name, !ellipsoid);
  }
  const double* doubles() const { return matrices ? matrices->doubles : nullptr; }
  relpos::Ellipsoid ellipsoid(std::size_t i) const {
    return matrices ? matrices->ellipsoid(i) : parameters->ellipsoid(i);
  }
  relpos::Paraboloid paraboloid(std::size_t i) const {
    return matrices ? matrices->paraboloid(i) : parameters->paraboloid(i);
  }
};

/// What to pass instead of a matrix the library refuses (doc/python.md, "decide_positions").
std::string hint(bool ellipsoid, const std::string& message) {
  if (message.find("not symmetric") != std::string::npos)
    return "; a float code's R D R^T is symmetric only up to rounding: symmetrize='upper' reads the upper triangle";
  if (ellipsoid && message.find("not an ellipsoid") != std::string::npos)
    return "; the matrix of a small or far ellipsoid can lose its shape when rounded to doubles: pass the "
           "parameters instead, E={'center': (n, 3), 'axes': (n, 3), 'rotation': (n, 4)}, read exactly";
  if (!ellipsoid && message.find("not an elliptic paraboloid") != std::string::npos)
    return "; a rotated paraboloid's matrix rounded to doubles keeps no exact zero eigenvalue: pass the "
           "parameters instead, P={'vertex': (n, 3), 'a': (n,), 'b': (n,), 'rotation': (n, 4)}, read exactly";
  return "";
}

/// Pairs per work item of decide_positions: a thread takes 64 pairs at a time.
constexpr std::size_t kChunk = 64;

/// The error a decide_positions call raises: the lowest index's, whichever thread meets it first.
class FirstError {
 public:
  /// Keeps message() for pair i if no lower pair has failed (message is called only then).
  template <class Message>
  void offer(std::size_t i, const Message& message) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (i >= index_) return;
    index_ = i;
    text_ = message();
  }
  const std::string& text() const { return text_; }

 private:
  std::mutex mutex_;
  std::size_t index_ = std::numeric_limits<std::size_t>::max();
  std::string text_;
};

/// chunk(begin, end) for the chunks of kChunk pairs of [0, n), on `threads` threads (0: every core;
/// at most one per chunk) of one worker pool (src/base/worker_pool.hpp); the calling thread polls
/// Python's signals between its chunks, and every thread stops at its next chunk once one arrived.
/// The caller releases the GIL.
template <class Chunk>
void in_chunks(std::size_t n, unsigned threads, SignalWatch& watch, const Chunk& chunk) {
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  unsigned workers = threads > 0 ? threads : std::thread::hardware_concurrency();
  workers = static_cast<unsigned>(std::clamp<std::size_t>(workers, 1, std::max<std::size_t>(1, chunks)));
  std::atomic<std::size_t> next{0};
  relpos::detail::WorkerPool pool(workers);
  pool.run_on_each([&](unsigned w) {
    for (;;) {
      if (w == 0 ? watch.poll() : watch.stopped()) return;
      const std::size_t begin = next.fetch_add(kChunk);
      if (begin >= n) return;
      chunk(begin, std::min(n, begin + kChunk));
    }
  });
}

py::array_t<std::int8_t> decide_positions(py::handle e_input, py::handle p_input, unsigned threads, bool raise_errors,
                                          bool upper, std::size_t max_bits) {
  const relpos::SizeLimit limit{max_bits};
  const Side e_side(e_input, "E", true, upper);
  const Side p_side(p_input, "P", false, upper);
  if (!e_side.n) throw relpos::InputError("E: expected n ellipsoids (an array with a leading n), got one");
  const std::size_t n = *e_side.n;
  const std::optional<std::size_t> np = p_side.n;
  if (np && *np != n)
    throw relpos::InputError("P: " + std::to_string(*np) + " matrices for " + std::to_string(n) + " ellipsoids");
  py::array_t<std::int8_t> out(static_cast<py::ssize_t>(n));
  std::int8_t* codes = out.mutable_data();

  std::optional<relpos::Paraboloid> shared;
  std::string error_message;  // the shared paraboloid's, else first_error's
  FirstError first_error;
  SignalWatch watch;  // Ctrl-C: the calling thread polls between its chunks, every thread stops
  {
    py::gil_scoped_release release;
    if (!np) {
      try {
        shared = p_side.paraboloid(0);
      } catch (const relpos::InputError& err) {
        error_message = std::string("P: paraboloid: ") + err.what() + (p_side.matrices ? hint(false, err.what()) : "");
        if (!raise_errors) std::fill(codes, codes + n, kInvalid);
      }
    }
    if (error_message.empty() && n > 0) {
      // float64 matrices read whole (not symmetrize='upper'): decided in lanes across pairs.
      const bool lanes = !upper && e_side.doubles() && p_side.doubles();
      std::vector<double> shared_p;  // the one paraboloid's doubles, once for each pair of a chunk
      if (lanes && shared)
        for (std::size_t k = 0; k < kChunk; ++k)
          shared_p.insert(shared_p.end(), p_side.doubles(), p_side.doubles() + 16);
      in_chunks(n, threads, watch, [&](std::size_t begin, std::size_t end) {
        // float64 matrices: decided in lanes (decide_positions: decide_position's positions); a pair
        // it refuses is asked again below, which words its error.
        std::array<relpos::PairStatus, kChunk> status;
        status.fill(relpos::PairStatus::InvalidEllipsoid);
        if (lanes) {
          std::array<relpos::Position, kChunk> positions;
          relpos::decide_positions(e_side.doubles() + 16 * begin,
                                   shared ? shared_p.data() : p_side.doubles() + 16 * begin, end - begin,
                                   positions.data(), status.data());
          for (std::size_t i = begin; i < end; ++i)
            if (status[i - begin] == relpos::PairStatus::Decided) codes[i] = position_code(positions[i - begin]);
        }
        for (std::size_t i = begin; i < end; ++i) {
          if (status[i - begin] == relpos::PairStatus::Decided) continue;
          const char* failed = "E";
          if (!shared && e_side.doubles() && p_side.doubles()) {
            // Both float64: the one-call decision (the shapes' last signs read off the pencil). An
            // error is asked again of the two steps below, which say which matrix it is.
            try {
              codes[i] = position_code(
                  relpos::decide_position(e_side.matrices->doubles_at(i), p_side.matrices->doubles_at(i)).position);
              continue;
            } catch (const std::exception&) {
            }
          }
          try {
            const relpos::Ellipsoid e = e_side.ellipsoid(i);
            if (shared) {
              codes[i] = position_code(relpos::decide_position(e, *shared, limit).position);
            } else {
              failed = "P";
              codes[i] = position_code(relpos::decide_position(e, p_side.paraboloid(i), limit).position);
            }
          } catch (const std::exception& err) {
            codes[i] = kInvalid;
            if (!raise_errors) continue;
            first_error.offer(i, [&] {
              const bool is_e = failed[0] == 'E';
              const bool matrix = is_e ? e_side.matrices.has_value() : p_side.matrices.has_value();
              return std::string(failed) + "[" + std::to_string(i) + "]: " + (is_e ? "ellipsoid: " : "paraboloid: ") +
                     err.what() + (matrix ? hint(is_e, err.what()) : "");
            });
          }
        }
      });
      error_message = first_error.text();
    }
  }
  watch.raise_if_stopped();
  if (raise_errors && !error_message.empty()) throw relpos::InputError(error_message);
  return out;
}

/// decide_positions against one general quadric (doc/python.md, "Any real quadric"): the codes of
/// relpos.QUADRIC_POSITION_NAMES (0 = I ... 4 = E, 5 = O, 6 = TO, 7 = EQ), each pair by
/// decide_position(e, q) (the general part has no lanes across pairs), the size limit as a batch
/// line's ("E[i]: numbers too large: ..."). Errors and threads as for the paraboloid.
py::array_t<std::int8_t> decide_positions_quadric(py::handle e_input, const relpos::Quadric& q, unsigned threads,
                                                  bool raise_errors, bool upper, std::size_t max_bits) {
  static_assert(static_cast<int>(relpos::QuadricPosition::E) == 4 && static_cast<int>(relpos::QuadricPosition::EQ) == 7,
                "codes are the order of relpos.QUADRIC_POSITION_NAMES");
  const Side e_side(e_input, "E", true, upper);
  if (!e_side.n) throw relpos::InputError("E: expected n ellipsoids (an array with a leading n), got one");
  const std::size_t n = *e_side.n;
  py::array_t<std::int8_t> out(static_cast<py::ssize_t>(n));
  std::int8_t* codes = out.mutable_data();
  const relpos::detail::io::GeneralPairSize size(q, relpos::SizeLimit{max_bits});  // the quadric's size once
  FirstError first_error;
  SignalWatch watch;  // Ctrl-C: the calling thread polls between its chunks, every thread stops
  {
    py::gil_scoped_release release;
    in_chunks(n, threads, watch, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        try {
          const relpos::Ellipsoid e = e_side.ellipsoid(i);
          const std::size_t bits = size.check(e);
          codes[i] = static_cast<std::int8_t>(
              relpos::detail::io::with_stack_for_general(bits, [&] { return relpos::decide_position(e, q); }).position);
        } catch (const std::exception& err) {
          codes[i] = kInvalid;
          if (!raise_errors) continue;
          first_error.offer(i, [&] {
            return "E[" + std::to_string(i) + "]: ellipsoid: " + err.what() +
                   (e_side.matrices ? hint(true, err.what()) : "");
          });
        }
      }
    });
  }
  watch.raise_if_stopped();
  if (raise_errors && !first_error.text().empty()) throw relpos::InputError(first_error.text());
  return out;
}

/// Bodies read or checked between two polls of Python's signals (a few microseconds each at most).
constexpr std::size_t kPollEvery = 256;

/// The bodies of a scene: a sequence of relpos.Ellipsoid (empty included), or matrices as for
/// decide_positions. Errors name the body: "bodies[3]: ...".
std::vector<relpos::Ellipsoid> scene_bodies(py::handle bodies, SignalWatch& watch) {
  std::vector<relpos::Ellipsoid> out;
  if (PyList_Check(bodies.ptr()) || PyTuple_Check(bodies.ptr())) {
    const auto seq = py::reinterpret_borrow<py::sequence>(bodies);
    bool ellipsoids = seq.size() == 0;
    for (const py::handle b : seq) ellipsoids = ellipsoids || py::isinstance<relpos::Ellipsoid>(b);
    if (ellipsoids) {  // a sequence of Ellipsoid objects: every entry must be one
      out.reserve(seq.size());
      for (std::size_t i = 0; i < seq.size(); ++i) {
        const py::handle b = seq[i];
        if (!py::isinstance<relpos::Ellipsoid>(b))
          throw py::type_error("bodies[" + std::to_string(i) + "]: expected a relpos.Ellipsoid, got " +
                               py::str(py::type::handle_of(b).attr("__name__")).cast<std::string>() +
                               " (bodies is a sequence of Ellipsoid objects or an array (n, 4, 4) of matrices)");
        out.push_back(b.cast<const relpos::Ellipsoid&>());  // an object made by __new__ alone: TypeError
      }
      return out;
    }
  }
  const Matrices e = read_array(bodies, "bodies");
  const std::size_t n = *batch_size(e.array, "bodies", false);
  out.reserve(n);
  py::gil_scoped_release release;
  for (std::size_t i = 0; i < n && !(i % kPollEvery == 0 && watch.poll()); ++i) {
    try {
      out.push_back(e.ellipsoid(i));
    } catch (const relpos::InputError& err) {
      throw relpos::InputError("bodies[" + std::to_string(i) + "]: ellipsoid: " + err.what());
    }
  }
  return out;
}

/// The stage code of a scene body: its index in kSceneStages (and in relpos.STAGE_NAMES).
std::int8_t scene_stage_code(relpos::Stage s) {
  for (std::size_t k = 0; k < relpos::detail::kSceneStages.size(); ++k)
    if (relpos::detail::kSceneStages[k] == s) return static_cast<std::int8_t>(k);
  throw std::logic_error("scene: a stage a scene never ends in");
}

/// The pair size limit for every body, naming the first body beyond it ("bodies[3]: numbers too
/// large: ..."): the scene's own check, on its worker threads, could not say which. Free for bodies
/// of doubles and of short decimals (check_normalized_pair_size).
void check_body_sizes(const relpos::Paraboloid& p, const std::vector<relpos::Ellipsoid>& bodies,
                      const relpos::SizeLimit& limit, SignalWatch& watch) {
  for (std::size_t i = 0; i < bodies.size() && !(i % kPollEvery == 0 && watch.poll()); ++i) {
    try {
      relpos::detail::check_normalized_pair_size(bodies[i], p, limit);
    } catch (const relpos::InputError& err) {
      throw relpos::InputError("bodies[" + std::to_string(i) + "]: " + err.what());
    }
  }
}

/// relpos::Scene on the bodies, in pieces with Python's signals checked between them (a piece
/// takes 20 to 100 ms: its size doubles or halves to stay there): (position codes, contact (1, 0),
/// stage codes, threads used).
py::tuple scene(const relpos::Paraboloid& p, py::handle bodies, unsigned threads, bool early_outs,
                std::size_t max_bits) {
  SignalWatch watch;
  const std::vector<relpos::Ellipsoid> e = scene_bodies(bodies, watch);
  const std::size_t n = e.size();
  relpos::SceneOptions options;
  options.threads = threads;
  options.early_outs = early_outs;
  options.size_limit.max_bits = max_bits;
  relpos::SceneResult result;
  {
    py::gil_scoped_release release;
    check_body_sizes(p, e, options.size_limit, watch);
    const relpos::Scene prepared(p);
    // One pool for every piece, as relpos scene keeps one for its blocks (src/scene/scene_pool.hpp).
    relpos::detail::WorkerPool pool(relpos::detail::scene_threads(options, n));
    std::size_t piece = 4096;
    for (std::size_t begin = 0; begin < n && !watch.poll();) {
      const std::size_t count = std::min(piece, n - begin);
      const auto start = std::chrono::steady_clock::now();
      relpos::SceneResult r = relpos::detail::SceneAccess::classify(prepared, e.data() + begin, count, options, pool);
      const auto took = std::chrono::steady_clock::now() - start;
      if (took < std::chrono::milliseconds(20) && piece < (std::size_t(1) << 20)) piece *= 2;
      if (took > std::chrono::milliseconds(100) && piece > 64) piece /= 2;
      result.verdicts.insert(result.verdicts.end(), r.verdicts.begin(), r.verdicts.end());
      result.counts.merge(r.counts);
      result.threads = std::max(result.threads, r.threads);
      begin += count;
    }
  }
  watch.raise_if_stopped();
  py::array_t<std::int8_t> positions(static_cast<py::ssize_t>(n)), contact(static_cast<py::ssize_t>(n)),
      stages(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const relpos::SceneVerdict& v = result.verdicts[i];
    positions.mutable_at(static_cast<py::ssize_t>(i)) = position_code(v.position);
    contact.mutable_at(static_cast<py::ssize_t>(i)) =
        static_cast<std::int8_t>(relpos::contact_of(v.position) != relpos::Contact::None);
    stages.mutable_at(static_cast<py::ssize_t>(i)) = scene_stage_code(v.stage);
  }
  return py::make_tuple(positions, contact, stages, result.threads);
}

}  // namespace

void bind_decide(py::module_& m) {
  py::list stage_names;
  for (const relpos::Stage s : relpos::detail::kSceneStages) stage_names.append(relpos::to_string(s));
  m.attr("_STAGE_NAMES") = py::tuple(stage_names);
  m.def("_scene", &scene, "p"_a, "bodies"_a, "threads"_a, "early_outs"_a, "max_bits"_a,
        "relpos::Scene on the bodies: (position codes, contact codes, stage codes, threads used).");
  m.attr("_INVALID") = kInvalid;
  m.def("_decide_positions_quadric", &decide_positions_quadric, "E"_a, "q"_a, "threads"_a, "raise_errors"_a, "upper"_a,
        "max_bits"_a,
        "Position codes (int8, 0 = I ... 7 = EQ, -1 = invalid pair) of the ellipsoids E (n, 4, 4) or parameters "
        "against one relpos.Quadric.");
  m.def("_decide_positions", &decide_positions, "E"_a, "P"_a, "threads"_a, "raise_errors"_a, "upper"_a, "max_bits"_a,
        "Position codes (int8, 0 = I ... 4 = E, -1 = invalid pair) of the matrices E (n, 4, 4) against P "
        "(n, 4, 4) or (4, 4), or of parameter dicts; with upper, each matrix read from its upper triangle.");
}

}  // namespace relpos_python
