// relpos motion: the certified first-contact time and the timeline of positions of a moving
// ellipsoid (doc/cli.md). Parsing of quadrics and exact numbers is shared with `classify` through
// relpos/io.hpp; this file adds the motion polynomials and the rendering of exact instants.
#include "relpos/motion.hpp"

#include <gmp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "algebra/polynomial_text.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "io/json_tree.hpp"
#include "io/motion_json.hpp"
#include "io/report_text.hpp"
#include "motion/polynomial_motion.hpp"
#include "options.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos_cli {
namespace {

using relpos::Rational;
using relpos::detail::io::Json;

/// Above this degree the text report names the defining polynomial by its degree only (the JSON
/// output always has every coefficient).
constexpr int kMaxShownDegree = 8;

}  // namespace

void print_motion_help(std::ostream& os) {
  os << "Usage: relpos motion (--ellipsoid Q | --sphere X,Y,Z,R)\n"
        "                     (--paraboloid Q | --standard-paraboloid A,B)\n"
        "                     [--translation '[CX, CY, CZ]'] [--rotation '[QW, QX, QY, QZ]']\n"
        "                     [--pivot origin|center|X,Y,Z] --t0 T0 --t1 T1\n"
        "                     [--first-contact] [--digits N] [--json]\n"
        "\n"
        "The ellipsoid Q (placed as given) moves by x(t) = R(t)(y - p) + p + c(t): c(t) is the\n"
        "translation, R(t) the rotation of the quaternion q(t) (not necessarily unit), p the pivot.\n"
        "Each of CX, CY, CZ, QW, ..., QZ is a polynomial in t given as a JSON array of exact\n"
        "coefficients, lowest degree first: [\"-9/4\", 0, 1] is t^2 - 9/4. The paraboloid is fixed.\n"
        "\n"
        "Prints the certified first-contact time (the first t in (t0, t1] where the ellipsoid is\n"
        "no longer exterior; contact at t0 is reported as such) and the timeline: the position on\n"
        "every piece of [t0, t1] and every instant where it changes. Instants are exact: a rational,\n"
        "or the only root of a square-free integer polynomial in an isolating interval, shown as a\n"
        "correctly rounded decimal.\n"
        "\n"
        "Options:\n"
        "  --ellipsoid Q, --sphere X,Y,Z,R             as for `relpos classify`\n"
        "  --paraboloid Q, --standard-paraboloid A,B   as for `relpos classify`\n"
        "  --translation '[CX, CY, CZ]'   c(t) (default: no translation)\n"
        "  --rotation '[QW, QX, QY, QZ]'  q(t) (default: no rotation); must not vanish on [t0, t1]\n"
        "  --pivot origin|center|X,Y,Z    the fixed point of the rotation (default: origin);\n"
        "                                 center = the centre of the ellipsoid as given\n"
        "  --t0 T0, --t1 T1               the time interval (exact numbers, T0 <= T1)\n"
        "  --first-contact                only the first contact (faster: no timeline)\n"
        "  --digits N                     significant digits of the decimals (default 12, 1..200)\n"
        "  --max-seconds S                time budget (default 60): beyond it the command stops with a\n"
        "                                 message and exit code 5\n"
        "  --no-progress                  no progress indication (shown on a terminal's stderr)\n"
        "  --json                         one JSON object instead of the report\n"
        "  -h, --help                     this help\n"
        "\n"
        "Example (contact at t = sqrt(2)):\n"
        "  relpos motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 \\\n"
        "      --translation '[[], [], [\"-9/4\", 0, 1]]' --t0 0 --t1 2\n"
        "\n"
        "Limits: each polynomial of degree at most 12, coefficients of at most 512 bits (numerator and\n"
        "denominator).\n"
        "Exit codes: 0 success, 1 input error, 2 usage error, 3 output error, 4 internal error,\n"
        "5 time budget exceeded.\n";
}

namespace {

/// Limits of `relpos motion` (doc/cli.md, "Limits"; those on the polynomials are
/// relpos::detail::io::kMaxMotionDegree and kMaxMotionCoefficientBits).
constexpr int kMaxMotionDigits = 200;
constexpr unsigned long long kDefaultMaxSeconds = 60;

/// A JSON array of `N` polynomials (relpos::detail::io::motion_polynomials).
template <std::size_t N>
std::array<relpos::TimePolynomial, N> polynomials(const std::string& text, const std::string& role) {
  const std::vector<relpos::TimePolynomial> p =
      relpos::detail::io::motion_polynomials(parse_inline(text, role), N, role);
  std::array<relpos::TimePolynomial, N> out;
  std::copy(p.begin(), p.end(), out.begin());
  return out;
}

std::string poly_text(const relpos::TimePolynomial& p) {
  return relpos::detail::polynomial_text(p.data(), p.size(), "t");
}

Json poly_json(const relpos::TimePolynomial& p) {
  Json a = Json::array();
  for (const auto& c : p) a.push_back(relpos::to_string(c));
  return a;
}

Json time_json(const relpos::AlgebraicReal& t, int digits) {
  Json j;
  j["exact"] = t.is_rational() ? Json(relpos::to_string(*t.exact())) : Json(nullptr);
  j["interval"] = Json::array({relpos::to_string(t.lower()), relpos::to_string(t.upper())});
  Json p = Json::array();
  for (const auto& c : t.polynomial()) p.push_back(relpos::to_string(c));
  j["polynomial"] = p;
  j["decimal"] = t.decimals(digits);
  return j;
}

std::string time_text(const relpos::AlgebraicReal& t, int digits) { return t.decimals(digits); }

/// "exactly 17/15" or "the only root of t^2 - 2 in [181/128, 363/256]".
std::string time_exact_text(const relpos::AlgebraicReal& t) {
  if (t.is_rational()) return "exactly " + relpos::to_string(*t.exact());
  const int degree = static_cast<int>(t.polynomial().size()) - 1;
  const std::string poly = degree <= kMaxShownDegree ? relpos::polynomial_text(t.polynomial())
                                                     : "an irreducible polynomial of degree " + std::to_string(degree);
  std::string interval = "[" + relpos::to_string(t.lower()) + ", " + relpos::to_string(t.upper()) + "]";
  if (interval.size() > 60) {
    // Long exact ends (after refinement) are in the JSON output; the report gives the width.
    const relpos::Rational w = t.upper() - t.lower();
    const long log2w = static_cast<long>(mpz_sizeinbase(w.numerator().mpz(), 2)) -
                       static_cast<long>(mpz_sizeinbase(w.denominator().mpz(), 2));
    interval = "an isolating interval of width about 2^" + std::to_string(log2w) + " (exact ends: --json)";
  }
  return "the only root of " + poly + " in " + interval;
}

Json first_contact_json(const relpos::FirstContact& fc, int digits) {
  Json j;
  j["kind"] = relpos::to_string(fc.kind);
  j["start_position"] = relpos::to_string(fc.start_position);
  j["time"] = fc.time ? time_json(*fc.time, digits) : Json(nullptr);
  j["position"] = fc.time ? Json(relpos::to_string(fc.position)) : Json(nullptr);
  j["how"] = fc.how;
  return j;
}

Json timeline_json(const relpos::Timeline& tl, int digits) {
  Json j;
  j["discriminant_identically_zero"] = tl.discriminant_identically_zero;
  j["event_degree"] = tl.event_degree;
  Json inst = Json::array();
  for (const auto& i : tl.instants) {
    Json causes = Json::array();
    for (const auto& c : relpos::detail::cause_names(i.causes)) causes.push_back(c);
    inst.push_back(Json{{"time", time_json(i.time, digits)},
                        {"position", relpos::to_string(i.position)},
                        {"small", i.small},
                        {"causes", causes},
                        {"how", i.how}});
  }
  j["instants"] = inst;
  Json ivs = Json::array();
  for (const auto& iv : tl.intervals)
    ivs.push_back(Json{
        {"sample", relpos::to_string(iv.sample)}, {"position", relpos::to_string(iv.position)}, {"small", iv.small}});
  j["intervals"] = ivs;
  Json spans = Json::array();
  for (const auto& s : tl.spans())
    spans.push_back(Json{{"from", time_json(s.from, digits)},
                         {"from_closed", s.from_closed},
                         {"to", time_json(s.to, digits)},
                         {"to_closed", s.to_closed},
                         {"position", relpos::to_string(s.position)}});
  j["spans"] = spans;
  Json changes = Json::array();
  for (const auto& c : tl.changes())
    changes.push_back(Json{{"time", time_json(c.time, digits)},
                           {"before", c.before ? Json(relpos::to_string(*c.before)) : Json(nullptr)},
                           {"at", relpos::to_string(c.at)},
                           {"after", c.after ? Json(relpos::to_string(*c.after)) : Json(nullptr)}});
  j["changes"] = changes;
  return j;
}

/// Spans are built from copies of the timeline's instants: equal representation = same instant.
bool same_instant(const relpos::AlgebraicReal& a, const relpos::AlgebraicReal& b) {
  if (a.is_rational() || b.is_rational()) return a.is_rational() && b.is_rational() && *a.exact() == *b.exact();
  return a.polynomial() == b.polynomial() && a.lower() == b.lower() && a.upper() == b.upper();
}

std::string first_contact_text(const relpos::FirstContact& fc, int digits) {
  std::ostringstream os;
  switch (fc.kind) {
    case relpos::FirstContact::Kind::NotExteriorAtStart:
      os << "first contact: not exterior at t0 = " << time_text(*fc.time, digits) << ": position "
         << relpos::to_string(fc.position) << " - " << relpos::detail::io::position_meaning(fc.position) << "\n";
      break;
    case relpos::FirstContact::Kind::Contact:
      os << "first contact: t* = " << time_text(*fc.time, digits) << "  (" << time_exact_text(*fc.time) << ")\n"
         << "  position at t*: " << relpos::to_string(fc.position) << " - "
         << relpos::detail::io::position_meaning(fc.position) << "\n"
         << "  decided: " << fc.how << "\n";
      break;
    case relpos::FirstContact::Kind::None:
      os << "first contact: none - exterior (E) on the whole interval\n";
      break;
  }
  return os.str();
}

std::string timeline_text(const relpos::Timeline& tl, int digits) {
  std::ostringstream os;
  os << "timeline: " << tl.instants.size() << " instants (candidates: real zeros of polynomials of total degree "
     << tl.event_degree << (tl.discriminant_identically_zero ? "; Disc_l f = 0 for every t" : "") << ")\n";
  for (const auto& s : tl.spans()) {
    const bool point = s.from_closed && s.to_closed && same_instant(s.from, s.to);
    const std::string when = point ? "t = " + time_text(s.from, digits)
                                   : std::string(s.from_closed ? "[" : "(") + time_text(s.from, digits) + ", " +
                                         time_text(s.to, digits) + (s.to_closed ? "]" : ")");
    os << "  " << when << std::string(when.size() < 36 ? 36 - when.size() : 1, ' ') << relpos::to_string(s.position)
       << "\n";
  }
  const auto changes = tl.changes();
  os << "changes: " << changes.size() << "\n";
  for (const auto& c : changes)
    os << "  t = " << time_text(c.time, digits) << ": " << (c.before ? relpos::to_string(*c.before) : "start") << " -> "
       << relpos::to_string(c.at) << " -> " << (c.after ? relpos::to_string(*c.after) : "end") << "   ("
       << time_exact_text(c.time) << ")\n";
  os << "instants:\n";
  for (const auto& i : tl.instants) {
    std::string causes;
    for (const auto& c : relpos::detail::cause_names(i.causes)) causes += (causes.empty() ? "" : ",") + c;
    os << "  t = " << time_text(i.time, digits) << "  " << relpos::to_string(i.position)
       << (i.small ? "" : " (not small)") << "  [" << causes << "]  " << i.how << "\n";
  }
  return os.str();
}

/// Everything `relpos motion` computes and prints, from the parsed options (runs on a worker
/// thread). Returns the text to print; throws InputError, and relpos::Interrupted past the budget.
std::string compute(const ShapeOptions& shapes, const std::optional<std::string>& translation,
                    const std::optional<std::string>& rotation, const std::optional<std::string>& pivot,
                    const std::string& t0s, const std::string& t1s, int digits, bool json, bool only_first,
                    const relpos::Interrupt& budget) {
  const relpos::Ellipsoid e = shapes.make_ellipsoid();
  const relpos::Paraboloid p = shapes.make_paraboloid();
  relpos::RigidMotion m;
  if (translation) m.translation = polynomials<3>(*translation, "translation");
  if (rotation) m.rotation = polynomials<4>(*rotation, "rotation");
  if (pivot) {
    if (*pivot == "origin") {
      m.pivot = relpos::Pivot::Origin;
    } else if (*pivot == "center" || *pivot == "centre") {
      m.pivot = relpos::Pivot::Centre;
    } else {
      std::vector<Rational> x;
      try {
        x = comma_numbers(*pivot, 3, "--pivot");
      } catch (const relpos::InputError& err) {
        throw relpos::InputError(std::string(err.what()) + " (--pivot takes origin|center|X,Y,Z)");
      }
      m.pivot = relpos::Pivot::Point;
      m.pivot_point = {x[0], x[1], x[2]};
    }
  }
  const Rational t0 = exact_option(t0s, "--t0");
  const Rational t1 = exact_option(t1s, "--t1");

  const relpos::FirstContact fc = relpos::first_contact(e, m, p, t0, t1, &budget);
  std::optional<relpos::Timeline> tl;
  if (!only_first) tl = relpos::timeline(e, m, p, t0, t1, &budget);

  if (json) {
    Json out;
    out["t0"] = relpos::to_string(t0);
    out["t1"] = relpos::to_string(t1);
    Json motion;
    Json tr = Json::array();
    for (const auto& c : m.translation) tr.push_back(poly_json(c));
    motion["translation"] = tr;
    if (m.rotation) {
      Json ro = Json::array();
      for (const auto& c : *m.rotation) ro.push_back(poly_json(c));
      motion["rotation"] = ro;
    } else {
      motion["rotation"] = nullptr;
    }
    Json pv = Json::array();
    for (const auto& c : relpos::detail::pivot_of(e, m)) pv.push_back(relpos::to_string(c));
    motion["pivot"] = pv;
    out["motion"] = motion;
    out["first_contact"] = first_contact_json(fc, digits);
    if (tl) out["timeline"] = timeline_json(*tl, digits);
    return relpos::detail::io::dump_json(out) + "\n";
  }
  std::ostringstream os;
  os << "motion on [" << relpos::to_string(t0) << ", " << relpos::to_string(t1) << "]: c(t) = ("
     << poly_text(m.translation[0]) << ", " << poly_text(m.translation[1]) << ", " << poly_text(m.translation[2])
     << ")";
  if (m.rotation) {
    const auto pv = relpos::detail::pivot_of(e, m);
    os << ", q(t) = (" << poly_text((*m.rotation)[0]) << ", " << poly_text((*m.rotation)[1]) << ", "
       << poly_text((*m.rotation)[2]) << ", " << poly_text((*m.rotation)[3]) << ") about (" << relpos::to_string(pv[0])
       << ", " << relpos::to_string(pv[1]) << ", " << relpos::to_string(pv[2]) << ")";
  } else {
    os << ", no rotation";
  }
  os << "\n" << first_contact_text(fc, digits);
  if (tl) os << timeline_text(*tl, digits);
  return os.str();
}

}  // namespace

int run_motion(Args& args) {
  ShapeOptions shapes;
  std::optional<std::string> translation, rotation, pivot, t0s, t1s;
  int digits = 12;
  unsigned long long max_seconds = kDefaultMaxSeconds;
  bool json = false, only_first = false;
  bool quiet = false;
  while (!args.done()) {
    if (args.help()) {
      print_motion_help(std::cout);
      return finish_cout();
    }
    std::string v;
    if (shapes.take(args) || args.flag("--first-contact", only_first) || args.flag("--json", json) ||
        args.flag("--no-progress", quiet))
      continue;
    if (args.value("--translation", v))
      translation = v;
    else if (args.value("--rotation", v))
      rotation = v;
    else if (args.value("--pivot", v))
      pivot = v;
    else if (args.value("--t0", v))
      t0s = v;
    else if (args.value("--t1", v))
      t1s = v;
    else if (args.value("--digits", v))
      digits = static_cast<int>(parse_count(v, "--digits", 1, kMaxMotionDigits));
    else if (args.value("--max-seconds", v))
      max_seconds = parse_count(v, "--max-seconds", 1, 86400);
    else if (args.value("--quadric", v))  // doc/cli.md, "relpos motion": what is not supported
      throw UsageError{
          "--quadric: a motion is decided against an elliptic paraboloid only (its first contact and timeline "
          "follow the pencil through time, doc/math.md §7); for the position at one instant, place the ellipsoid "
          "there and run `relpos classify --quadric Q`"};
    else
      args.unexpected();
  }
  shapes.check(/*need_ellipsoid=*/true);
  if (!t0s || !t1s) throw UsageError{"missing the time interval (--t0 T0 --t1 T1)"};

  // The work runs on a worker thread and stops itself at its first check past the budget
  // (relpos/interrupt.hpp); this thread shows the progress.
  const auto budget = std::make_shared<relpos::Interrupt>(std::chrono::seconds(max_seconds));
  struct Result {
    std::mutex m;
    std::condition_variable cv;
    bool done = false;
    std::string text, error;
    int code = kExitOk;
  };
  auto result = std::make_shared<Result>();
  std::thread worker([=] {
    std::string text, error;
    int code = kExitOk;
    try {
      text = compute(shapes, translation, rotation, pivot, *t0s, *t1s, digits, json, only_first, *budget);
    } catch (const relpos::Interrupted&) {
      error = "motion: the computation exceeded its time budget of " + std::to_string(max_seconds) +
              " s (--max-seconds) and was stopped; try a shorter interval, lower degrees or a larger budget";
      code = kExitBudget;
    } catch (const relpos::InputError& err) {
      error = err.what();
      code = kExitInput;
    } catch (const std::bad_alloc&) {
      error = "out of memory";
      code = kExitInternal;
    } catch (const std::exception& err) {
      error = std::string("internal error: ") + err.what();
      code = kExitInternal;
    }
    std::lock_guard<std::mutex> lock(result->m);
    result->text = std::move(text);
    result->error = std::move(error);
    result->code = code;
    result->done = true;
    result->cv.notify_all();
  });
  const bool show = !quiet && isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  {
    std::unique_lock<std::mutex> lock(result->m);
    while (!result->done) {
      result->cv.wait_for(lock, std::chrono::milliseconds(500));
      if (show && !result->done) {
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "\rrelpos motion: computing... %.0f s of at most %llu s\033[K", secs, max_seconds);
        std::fflush(stderr);
      }
    }
  }
  worker.join();
  if (show) std::cerr << "\r\033[K";
  if (result->code != kExitOk) {
    if (json && result->code == kExitInput)
      std::cout << relpos::detail::io::dump_json(Json{{"error", result->error}}) << "\n";
    std::cerr << "relpos: " << result->error << "\n";
    return finish_cout() == kExitOk ? result->code : kExitIo;
  }
  std::cout << result->text;
  return finish_cout();
}

}  // namespace relpos_cli
