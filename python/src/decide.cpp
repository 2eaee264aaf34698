// relpos._relpos._decide_positions: the positions of many pairs given as numpy matrices, exactly, on
// every core (doc/python.md, "decide_positions").
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/numbers.hpp>
#include <relpos/scene.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "module.hpp"
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

/// One input array: float64 read directly, or long double (for numpy.longdouble and 64-bit integer
/// arrays, converted exactly) whose matrices take the double path when every entry is a double.
struct Matrices {
  py::array array;
  const double* doubles = nullptr;
  const long double* extended = nullptr;

  template <class Q, class FromDoubles, class FromMatrix>
  Q at(std::size_t i, FromDoubles from_doubles, FromMatrix from_matrix) const {
    relpos::DoubleMatrix4 d;
    if (doubles) {
      std::copy(doubles + 16 * i, doubles + 16 * i + 16, d.begin());
      return from_doubles(d);
    }
    const long double* m = extended + 16 * i;
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

py::array_t<std::int8_t> decide_positions(py::handle e_input, py::handle p_input, unsigned threads, bool raise_errors,
                                          std::size_t max_bits) {
  const relpos::SizeLimit limit{max_bits};
  const Matrices e_array = read_array(e_input, "E");
  const Matrices p_array = read_array(p_input, "P");
  const std::size_t n = *batch_size(e_array.array, "E", false);
  const std::optional<std::size_t> np = batch_size(p_array.array, "P", true);
  if (np && *np != n)
    throw relpos::InputError("P: " + std::to_string(*np) + " matrices for " + std::to_string(n) + " ellipsoids");
  py::array_t<std::int8_t> out(static_cast<py::ssize_t>(n));
  std::int8_t* codes = out.mutable_data();

  std::optional<relpos::Paraboloid> shared;
  std::size_t error_index = std::numeric_limits<std::size_t>::max();
  std::string error_message;
  SignalWatch watch;  // Ctrl-C: the calling thread polls between its chunks, every thread stops
  {
    py::gil_scoped_release release;
    if (!np) {
      try {
        shared = p_array.paraboloid(0);
      } catch (const relpos::InputError& err) {
        error_message = std::string("P: paraboloid: ") + err.what();
        if (!raise_errors) std::fill(codes, codes + n, kInvalid);
      }
    }
    if (error_message.empty() && n > 0) {
      unsigned workers = threads > 0 ? threads : std::thread::hardware_concurrency();
      constexpr std::size_t kChunk = 64;
      const std::size_t chunks = (n + kChunk - 1) / kChunk;
      workers = static_cast<unsigned>(std::clamp<std::size_t>(workers, 1, chunks));
      std::atomic<std::size_t> next{0};
      std::mutex error_mutex;
      auto work = [&](bool caller) {
        for (;;) {
          if (caller ? watch.poll() : watch.stopped()) return;
          const std::size_t begin = next.fetch_add(kChunk);
          if (begin >= n) return;
          const std::size_t end = std::min(n, begin + kChunk);
          for (std::size_t i = begin; i < end; ++i) {
            const char* failed = "E";
            if (!shared && e_array.doubles && p_array.doubles) {
              // Both float64: the one-call decision (the shapes' last signs read off the pencil). An
              // error is asked again of the two steps below, which say which matrix it is.
              try {
                relpos::DoubleMatrix4 ed, pd;
                std::copy(e_array.doubles + 16 * i, e_array.doubles + 16 * i + 16, ed.begin());
                std::copy(p_array.doubles + 16 * i, p_array.doubles + 16 * i + 16, pd.begin());
                codes[i] = position_code(relpos::decide_position(ed, pd).position);
                continue;
              } catch (const std::exception&) {
              }
            }
            try {
              const relpos::Ellipsoid e = e_array.ellipsoid(i);
              if (shared) {
                codes[i] = position_code(relpos::decide_position(e, *shared, limit).position);
              } else {
                failed = "P";
                codes[i] = position_code(relpos::decide_position(e, p_array.paraboloid(i), limit).position);
              }
            } catch (const std::exception& err) {
              codes[i] = kInvalid;
              if (!raise_errors) continue;
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
      for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work, false);
      work(true);
      for (auto& t : pool) t.join();
    }
  }
  watch.raise_if_stopped();
  if (raise_errors && !error_message.empty()) throw relpos::InputError(error_message);
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
  for (std::size_t k = 0; k < relpos::kSceneStages.size(); ++k)
    if (relpos::kSceneStages[k] == s) return static_cast<std::int8_t>(k);
  throw std::logic_error("scene: a stage a scene never ends in");
}

/// The pair size limit for every body, naming the first body beyond it ("bodies[3]: numbers too
/// large: ..."): the scene's own check, on its worker threads, could not say which. Free for bodies
/// of doubles and of short decimals (check_normalized_pair_size).
void check_body_sizes(const relpos::Paraboloid& p, const std::vector<relpos::Ellipsoid>& bodies,
                      const relpos::SizeLimit& limit, SignalWatch& watch) {
  for (std::size_t i = 0; i < bodies.size() && !(i % kPollEvery == 0 && watch.poll()); ++i) {
    try {
      relpos::check_normalized_pair_size(bodies[i], p, limit);
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
    std::size_t piece = 4096;
    for (std::size_t begin = 0; begin < n && !watch.poll();) {
      const std::size_t count = std::min(piece, n - begin);
      const auto start = std::chrono::steady_clock::now();
      relpos::SceneResult r = prepared.classify(e.data() + begin, count, options);
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
  for (const relpos::Stage s : relpos::kSceneStages) stage_names.append(relpos::to_string(s));
  m.attr("_STAGE_NAMES") = py::tuple(stage_names);
  m.def("_scene", &scene, "p"_a, "bodies"_a, "threads"_a, "early_outs"_a, "max_bits"_a,
        "relpos::Scene on the bodies: (position codes, contact codes, stage codes, threads used).");
  m.attr("_INVALID") = kInvalid;
  m.def("_decide_positions", &decide_positions, "E"_a, "P"_a, "threads"_a, "raise_errors"_a, "max_bits"_a,
        "Position codes (int8, 0 = I ... 4 = E, -1 = invalid pair) of the matrices E (n, 4, 4) against P "
        "(n, 4, 4) or (4, 4).");
}

}  // namespace relpos_python
