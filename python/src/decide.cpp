// relpos._relpos._decide_positions: the positions of many pairs given as numpy matrices, exactly, on
// every core (doc/python.md, "decide_positions").
#include <algorithm>
#include <array>
#include <atomic>
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
  const py::array a = py::module_::import("numpy").attr("asarray")(x);
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

py::array_t<std::int8_t> decide_positions(py::handle e_input, py::handle p_input, unsigned threads, bool raise_errors) {
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
      auto work = [&] {
        std::vector<double> shared_p;  // the one paraboloid's doubles, once for each pair of a chunk
        if (shared && p_array.doubles)
          for (std::size_t k = 0; k < kChunk; ++k)
            shared_p.insert(shared_p.end(), p_array.doubles, p_array.doubles + 16);
        for (;;) {
          const std::size_t begin = next.fetch_add(kChunk);
          if (begin >= n) return;
          const std::size_t end = std::min(n, begin + kChunk);
          // float64 matrices: decided in lanes (decide_positions: decide_position's positions); a pair
          // it refuses is asked again below, which words its error.
          std::array<relpos::PairStatus, kChunk> status;
          status.fill(relpos::PairStatus::InvalidEllipsoid);
          if (e_array.doubles && p_array.doubles) {
            std::array<relpos::Position, kChunk> positions;
            relpos::decide_positions(e_array.doubles + 16 * begin,
                                     shared ? shared_p.data() : p_array.doubles + 16 * begin, end - begin,
                                     positions.data(), status.data());
            for (std::size_t i = begin; i < end; ++i)
              if (status[i - begin] == relpos::PairStatus::Decided) codes[i] = position_code(positions[i - begin]);
          }
          for (std::size_t i = begin; i < end; ++i) {
            if (status[i - begin] == relpos::PairStatus::Decided) continue;
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
                codes[i] = position_code(relpos::decide_position(e, *shared).position);
              } else {
                failed = "P";
                codes[i] = position_code(relpos::decide_position(e, p_array.paraboloid(i)).position);
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
      for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
      work();
      for (auto& t : pool) t.join();
    }
  }
  if (raise_errors && !error_message.empty()) throw relpos::InputError(error_message);
  return out;
}

/// The bodies of a scene: a sequence of relpos.Ellipsoid, or matrices as for decide_positions.
std::vector<relpos::Ellipsoid> scene_bodies(py::handle bodies) {
  std::vector<relpos::Ellipsoid> out;
  if (py::isinstance<py::sequence>(bodies) && !py::isinstance<py::array>(bodies) && py::len(bodies) > 0 &&
      py::isinstance<relpos::Ellipsoid>(py::reinterpret_borrow<py::sequence>(bodies)[0])) {
    for (py::handle b : bodies) out.push_back(b.cast<const relpos::Ellipsoid&>());
    return out;
  }
  const Matrices e = read_array(bodies, "E");
  const std::size_t n = *batch_size(e.array, "E", false);
  out.reserve(n);
  py::gil_scoped_release release;
  for (std::size_t i = 0; i < n; ++i) {
    try {
      out.push_back(e.ellipsoid(i));
    } catch (const relpos::InputError& err) {
      throw relpos::InputError("E[" + std::to_string(i) + "]: ellipsoid: " + err.what());
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

/// relpos::Scene on the bodies: (position codes, contact (1, 0), stage codes, threads used).
py::tuple scene(const relpos::Paraboloid& p, py::handle bodies, unsigned threads, bool early_outs) {
  const std::vector<relpos::Ellipsoid> e = scene_bodies(bodies);
  const std::size_t n = e.size();
  py::array_t<std::int8_t> positions(static_cast<py::ssize_t>(n)), contact(static_cast<py::ssize_t>(n)),
      stages(static_cast<py::ssize_t>(n));
  relpos::SceneOptions options;
  options.threads = threads;
  options.early_outs = early_outs;
  relpos::SceneResult result;
  {
    py::gil_scoped_release release;
    result = relpos::Scene(p).classify(e, options);
  }
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
  m.def("_scene", &scene, "p"_a, "bodies"_a, "threads"_a, "early_outs"_a,
        "relpos::Scene on the bodies: (position codes, contact codes, stage codes, threads used).");
  m.attr("_INVALID") = kInvalid;
  m.def("_decide_positions", &decide_positions, "E"_a, "P"_a, "threads"_a, "raise_errors"_a,
        "Position codes (int8, 0 = I ... 4 = E, -1 = invalid pair) of the matrices E (n, 4, 4) against P "
        "(n, 4, 4) or (4, 4).");
}

}  // namespace relpos_python
