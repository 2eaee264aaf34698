// relpos._relpos motion bindings (doc/python.md, "Motion"): the certified first contact and the
// timeline of positions of an ellipsoid moved by a rigid polynomial motion (relpos/motion.hpp),
// with exact instants (relpos::AlgebraicReal).
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <relpos/algebraic_real.hpp>
#include <relpos/motion.hpp>
#include <sstream>
#include <string>

#include "io/json_values.hpp"
#include "io/motion_json.hpp"
#include "module.hpp"
#include "motion/polynomial_motion.hpp"
#include "signals.hpp"

namespace relpos_python {

namespace {

using namespace pybind11::literals;

/// `count` polynomials in t, read and limited as `relpos motion` reads --translation / --rotation.
std::vector<relpos::TimePolynomial> polynomials(py::handle x, std::size_t count, const std::string& role) {
  return relpos::detail::io::motion_polynomials(to_json(x, role), count, role);
}

relpos::RigidMotion rigid_motion(py::handle translation, py::handle rotation, py::handle pivot) {
  relpos::RigidMotion m;
  if (!translation.is_none()) {
    const auto c = polynomials(translation, 3, "translation");
    std::copy(c.begin(), c.end(), m.translation.begin());
  }
  if (!rotation.is_none()) {
    const auto q = polynomials(rotation, 4, "rotation");
    m.rotation.emplace();
    std::copy(q.begin(), q.end(), m.rotation->begin());
  }
  if (PyUnicode_Check(pivot.ptr())) {
    const std::string p = pivot.cast<std::string>();
    if (p == "origin") {
      m.pivot = relpos::Pivot::Origin;
    } else if (p == "center" || p == "centre") {  // both spellings, as `relpos motion --pivot`
      m.pivot = relpos::Pivot::Centre;
    } else {
      throw relpos::InputError("pivot: expected origin, center (or centre) or a point, got " + p);
    }
  } else {
    m.pivot = relpos::Pivot::Point;
    const Json point = to_json(pivot, "pivot");
    if (!point.is_array() || point.size() != 3) throw relpos::InputError("pivot: expected origin, center or a point");
    for (std::size_t i = 0; i < 3; ++i)
      m.pivot_point[i] = relpos::detail::io::rational_from_json(point[i], "pivot[" + std::to_string(i) + "]");
  }
  return m;
}

/// this <, =, > other: -1, 0, +1 exactly, for `other` an Instant or a real number (int, float,
/// Fraction, Decimal, a numpy integer or float, read exactly); None for any other object (Python
/// then answers NotImplemented: == is False, < raises TypeError).
py::object compare_instant(const relpos::AlgebraicReal& t, py::handle other) {
  if (is_built<relpos::AlgebraicReal>(other)) return py::int_(t.compare(other.cast<const relpos::AlgebraicReal&>()));
  static const py::handle real = py::object(py::module_::import("numbers").attr("Real")).release();
  static const py::handle decimal = py::object(py::module_::import("decimal").attr("Decimal")).release();
  if (PyBool_Check(other.ptr()) || !(py::isinstance(other, real) || py::isinstance(other, decimal))) return py::none();
  relpos::Rational q;
  try {
    q = to_rational(other, "other");
  } catch (const relpos::InputError&) {  // NaN, infinities: no order with an instant
    return py::none();
  }
  return py::int_(t.compare(q));
}

py::object position_name(const std::optional<relpos::Position>& p) {
  return p ? py::object(py::str(relpos::to_string(*p))) : py::object(py::none());
}

/// Binds `name` to a motion computation of the library (first_contact, timeline): the motion read
/// from Python as `relpos motion` reads it, run with the GIL released on a worker thread that stops
/// on Ctrl-C (signals.hpp) or past `max_seconds` (0: no budget; `relpos motion --max-seconds`):
/// TimeoutError with the CLI's message.
template <class Result>
void def_motion(py::module_& m, const char* name,
                Result (*run)(const relpos::Ellipsoid&, const relpos::RigidMotion&, const relpos::Paraboloid&,
                              const relpos::Rational&, const relpos::Rational&, const relpos::Interrupt*)) {
  m.def(
      name,
      [run](const relpos::Ellipsoid& e, const relpos::Paraboloid& p, py::handle t0, py::handle t1,
            py::handle translation, py::handle rotation, py::handle pivot, double max_seconds) {
        const relpos::RigidMotion motion = rigid_motion(translation, rotation, pivot);
        const relpos::Rational a = to_rational(t0, "t0"), b = to_rational(t1, "t1");
        std::optional<relpos::Interrupt> interrupt;
        if (max_seconds > 0)
          interrupt.emplace(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
              std::chrono::duration<double>(max_seconds)));
        else
          interrupt.emplace();
        try {
          return run_watched(*interrupt, [&] { return run(e, motion, p, a, b, &*interrupt); });
        } catch (const relpos::Interrupted& err) {
          if (!err.budget()) throw;
          std::ostringstream seconds;
          seconds << max_seconds;
          PyErr_SetString(PyExc_TimeoutError,
                          ("motion: the computation exceeded its time budget of " + seconds.str() +
                           " s (max_seconds) and was stopped; try a shorter interval, lower degrees or a larger budget")
                              .c_str());
          throw py::error_already_set();
        }
      },
      "e"_a, "p"_a, "t0"_a, "t1"_a, "translation"_a, "rotation"_a, "pivot"_a, "max_seconds"_a);
}

/// __reduce__ of a result class that does not pickle: a TypeError at every protocol (without it,
/// protocols 0 and 1 would build the object through copyreg, which pybind11 cannot do).
template <class T>
void refuse_pickling(py::class_<T>& c) {
  c.def("__reduce__", [](py::handle self) -> py::object {
    throw py::type_error("cannot pickle 'relpos." +
                         py::str(py::type::handle_of(self).attr("__name__")).cast<std::string>() + "' object");
  });
}

}  // namespace

void bind_motion(py::module_& m) {
  py::class_<relpos::AlgebraicReal> instant(
      m, "Instant",
      "An exact real time: a rational, or the only root of an irreducible integer polynomial in an isolating "
      "interval (relpos::AlgebraicReal).");
  instant
      .def_property_readonly(
          "exact",
          [](const relpos::AlgebraicReal& t) -> py::object {
            return t.is_rational() ? to_python(*t.exact()) : py::object(py::none());
          },
          "The value as a fractions.Fraction when it is rational, else None.")
      .def_property_readonly(
          "interval",
          [](const relpos::AlgebraicReal& t) { return py::make_tuple(to_python(t.lower()), to_python(t.upper())); },
          "(lower, upper): Fractions with lower <= t <= upper (strictly inside when t is irrational).")
      .def_property_readonly(
          "polynomial",
          [](const relpos::AlgebraicReal& t) {
            py::list out;
            for (const relpos::Integer& c : t.polynomial()) out.append(to_python(c));
            return out;
          },
          "The minimal polynomial (integer coefficients, lowest degree first) of which t is a root.")
      .def(
          "_decimal",
          [](const relpos::AlgebraicReal& t, int digits) {
            if (digits < 1 || digits > 1000) throw relpos::InputError("digits: expected 1..1000");
            py::gil_scoped_release release;
            return t.decimals(digits);
          },
          "digits"_a = 12, "The correctly rounded decimal with `digits` significant digits.")
      .def("__float__", &relpos::AlgebraicReal::to_double, "The nearest double.")
      .def("_compare", &compare_instant, "other"_a,
           "-1, 0, +1 for this <, =, > other (an Instant or an exact number), exactly; None for anything else.")
      .def("__hash__",
           [](const relpos::AlgebraicReal& t) -> py::ssize_t {
             // Equal instants have equal hashes: a rational one hashes as its Fraction (so that it
             // agrees with == on numbers), an irrational one by its minimal polynomial.
             if (t.is_rational()) return py::hash(to_python(*t.exact()));
             py::list c;
             for (const relpos::Integer& x : t.polynomial()) c.append(to_python(x));
             return py::hash(py::tuple(c));
           })
      .def("__repr__", [](const relpos::AlgebraicReal& t) {
        return "relpos.Instant(" + (t.is_rational() ? relpos::to_string(*t.exact()) : "~" + t.decimals(17)) + ")";
      });

  refuse_pickling(instant);
  py::class_<relpos::FirstContact> first(m, "FirstContact",
                                         "The certified first contact of a body that starts exterior.");
  refuse_pickling(first);
  first
      .def_property_readonly(
          "kind", [](const relpos::FirstContact& f) { return relpos::to_string(f.kind); },
          "'contact' (exterior at t0, `time` is the first t in (t0, t1] where it is not), 'none' (exterior on all "
          "of [t0, t1]) or 'not-exterior-at-start'.")
      .def_property_readonly(
          "start_position", [](const relpos::FirstContact& f) { return relpos::to_string(f.start_position); },
          "The position at t0.")
      .def_property_readonly(
          "time", [](const relpos::FirstContact& f) { return f.time; }, "The instant (an Instant), or None.")
      .def_property_readonly(
          "position",
          [](const relpos::FirstContact& f) {
            return position_name(f.kind == relpos::FirstContact::Kind::None ? std::nullopt : std::optional(f.position));
          },
          "The position at `time`; None when there is no contact (kind 'none'), as `relpos motion` writes null.")
      .def_readonly("how", &relpos::FirstContact::how, "How that position was decided, one sentence.");

  py::class_<relpos::Timeline> timeline(m, "Timeline", "Every change of position of the moving body on [t0, t1].");
  refuse_pickling(timeline);
  timeline
      .def_property_readonly(
          "instants",
          [](const relpos::Timeline& tl) {
            py::list out;
            for (const relpos::MotionInstant& i : tl.instants)
              out.append(py::dict("time"_a = i.time, "position"_a = relpos::to_string(i.position), "small"_a = i.small,
                                  "causes"_a = relpos::detail::cause_names(i.causes), "how"_a = i.how));
            return out;
          },
          "The candidate instants in increasing order (t0 first, t1 last): dicts time, position, small, causes, how.")
      .def_property_readonly(
          "intervals",
          [](const relpos::Timeline& tl) {
            py::list out;
            for (const relpos::MotionInterval& i : tl.intervals)
              out.append(py::dict("sample"_a = to_python(i.sample), "position"_a = relpos::to_string(i.position),
                                  "small"_a = i.small));
            return out;
          },
          "The open intervals between consecutive instants: dicts sample (a Fraction inside), position, small.")
      .def_property_readonly(
          "spans",
          [](const relpos::Timeline& tl) {
            py::list out;
            for (const relpos::PositionSpan& s : tl.spans())
              out.append(py::dict("from"_a = s.from, "to"_a = s.to, "from_closed"_a = s.from_closed,
                                  "to_closed"_a = s.to_closed, "position"_a = relpos::to_string(s.position)));
            return out;
          },
          "Maximal stretches of one position covering [t0, t1]: dicts from, to, from_closed, to_closed, position.")
      .def_property_readonly(
          "changes",
          [](const relpos::Timeline& tl) {
            py::list out;
            for (const relpos::PositionChange& c : tl.changes())
              out.append(py::dict("time"_a = c.time, "before"_a = position_name(c.before),
                                  "at"_a = relpos::to_string(c.at), "after"_a = position_name(c.after)));
            return out;
          },
          "The instants where the position changes: dicts time, before, at, after (None at t0 / t1).")
      .def(
          "_position_at",
          [](const relpos::Timeline& tl, py::handle t) {
            return relpos::to_string(tl.position_at(to_rational(t, "t")));
          },
          "t"_a, "The position at an exact time t in [t0, t1].");

  def_motion(m, "_first_contact", &relpos::first_contact);
  def_motion(m, "_timeline", &relpos::timeline);
}

}  // namespace relpos_python
