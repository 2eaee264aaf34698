// relpos motion: the certified first-contact time and the timeline of positions of a moving
// ellipsoid (doc/cli.md). Parsing of quadrics and exact numbers is shared with `classify` through
// relpos/io.hpp; this file adds the motion polynomials and the rendering of exact instants.
#include "motion.hpp"

#include <gmp.h>

#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "relpos/error.hpp"
#include "relpos/io.hpp"
#include "relpos/motion.hpp"

namespace relpos_cli {
namespace {

using Json = nlohmann::ordered_json;
using relpos::Rational;

constexpr int kExitOk = 0, kExitInput = 1, kExitUsage = 2, kExitIo = 3, kExitInternal = 4;

/// Above this degree the text report names the defining polynomial by its degree only (the JSON
/// output always has every coefficient).
constexpr int kMaxShownDegree = 8;

struct UsageError {
  std::string message;
};

void print_help(std::ostream& os) {
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
        "  --digits N                     significant digits of the decimals (default 12, 1..1000)\n"
        "  --json                         one JSON object instead of the report\n"
        "  -h, --help                     this help\n"
        "\n"
        "Example (contact at t = sqrt(2)):\n"
        "  relpos motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 \\\n"
        "      --translation '[[], [], [\"-9/4\", 0, 1]]' --t0 0 --t1 2\n"
        "\n"
        "Exit codes: 0 success, 1 input error, 2 usage error, 3 output error, 4 internal error.\n";
}

/// Options "--name value" or "--name=value"; flags take no value.
class Args {
 public:
  explicit Args(const std::vector<std::string>& a) : args_(a) {}
  bool done() const { return pos_ >= args_.size(); }
  bool take(const char* name, std::string* value) {
    const std::string& a = args_[pos_];
    const std::string n(name);
    if (a == n) {
      ++pos_;
      if (value) {
        if (done()) throw UsageError{"option " + n + " needs a value"};
        *value = args_[pos_++];
      }
      return true;
    }
    if (a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=') {
      if (!value) throw UsageError{"option " + n + " takes no value"};
      *value = a.substr(n.size() + 1);
      ++pos_;
      return true;
    }
    return false;
  }
  std::string next() { return args_[pos_++]; }

 private:
  const std::vector<std::string>& args_;
  std::size_t pos_ = 0;
};

void set_once(std::optional<std::string>& slot, const char* name, std::string value) {
  if (slot) throw UsageError{std::string("option ") + name + " given twice"};
  slot = std::move(value);
}

int parse_digits(const std::string& text) {
  std::size_t used = 0;
  long n = 0;
  try {
    n = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || n < 1 || n > 1000)
    throw UsageError{"--digits needs an integer from 1 to 1000, got '" + text + "'"};
  return static_cast<int>(n);
}

std::vector<Rational> comma_numbers(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<std::string> parts(1);
  for (char ch : text) {
    if (ch == ',')
      parts.emplace_back();
    else
      parts.back() += ch;
  }
  if (parts.size() != count)
    throw relpos::InputError(what + ": expected " + std::to_string(count) + " comma-separated numbers, got " +
                             std::to_string(parts.size()) + " in '" + text + "'");
  std::vector<Rational> out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    try {
      out.push_back(relpos::parse_rational(parts[i]));
    } catch (const relpos::InputError& e) {
      throw relpos::InputError(what + "[" + std::to_string(i) + "]: " + e.what());
    }
  }
  return out;
}

Json parse_inline(const std::string& text, const std::string& role) {
  try {
    return relpos::io::parse_json_exact(text);
  } catch (const relpos::InputError& e) {
    throw relpos::InputError(role + ": " + e.what());
  }
}

/// A JSON array of `count` polynomials, each an array of exact coefficients (low degree first).
template <std::size_t N>
std::array<relpos::TimePolynomial, N> polynomials(const std::string& text, const std::string& role) {
  const Json v = parse_inline(text, role);
  if (!v.is_array() || v.size() != N)
    throw relpos::InputError(role + ": expected an array of " + std::to_string(N) +
                             " polynomials (arrays of coefficients, lowest degree first)");
  std::array<relpos::TimePolynomial, N> out;
  for (std::size_t i = 0; i < N; ++i) {
    const std::string path = role + "[" + std::to_string(i) + "]";
    if (v[i].is_array()) {
      for (std::size_t k = 0; k < v[i].size(); ++k)
        out[i].push_back(relpos::io::rational_from_json(v[i][k], path + "[" + std::to_string(k) + "]"));
    } else {
      out[i].push_back(relpos::io::rational_from_json(v[i], path));  // a constant
    }
  }
  return out;
}

std::string poly_text(const relpos::TimePolynomial& p) {
  std::string out;
  for (std::size_t k = p.size(); k-- > 0;) {
    if (p[k] == 0) continue;
    const bool neg = p[k] < 0;
    const Rational mag = neg ? Rational(-p[k]) : p[k];
    out += out.empty() ? (neg ? "-" : "") : (neg ? " - " : " + ");
    if (mag != 1 || k == 0) out += relpos::to_string(mag) + (k > 0 ? "*" : "");
    if (k > 0) out += k > 1 ? "t^" + std::to_string(k) : "t";
  }
  return out.empty() ? "0" : out;
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

const char* kind_name(relpos::FirstContact::Kind k) {
  switch (k) {
    case relpos::FirstContact::Kind::NotExteriorAtStart:
      return "not-exterior-at-start";
    case relpos::FirstContact::Kind::Contact:
      return "contact";
    case relpos::FirstContact::Kind::None:
      return "none";
  }
  return "?";
}

Json first_contact_json(const relpos::FirstContact& fc, int digits) {
  Json j;
  j["kind"] = kind_name(fc.kind);
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
    for (const auto& c : relpos::cause_names(i.causes)) causes.push_back(c);
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
         << relpos::to_string(fc.position) << " - " << relpos::io::position_meaning(fc.position) << "\n";
      break;
    case relpos::FirstContact::Kind::Contact:
      os << "first contact: t* = " << time_text(*fc.time, digits) << "  (" << time_exact_text(*fc.time) << ")\n"
         << "  position at t*: " << relpos::to_string(fc.position) << " - " << relpos::io::position_meaning(fc.position)
         << "\n"
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
    for (const auto& c : relpos::cause_names(i.causes)) causes += (causes.empty() ? "" : ",") + c;
    os << "  t = " << time_text(i.time, digits) << "  " << relpos::to_string(i.position)
       << (i.small ? "" : " (not small)") << "  [" << causes << "]  " << i.how << "\n";
  }
  return os.str();
}

int run(const std::vector<std::string>& argv) {
  std::optional<std::string> ellipsoid, paraboloid, sphere, standard, translation, rotation, pivot, t0s, t1s;
  int digits = 12;
  bool json = false, only_first = false;
  Args args(argv);
  while (!args.done()) {
    std::string v;
    if (args.take("--help", nullptr) || args.take("-h", nullptr)) {
      print_help(std::cout);
      return kExitOk;
    } else if (args.take("--ellipsoid", &v)) {
      set_once(ellipsoid, "--ellipsoid", v);
    } else if (args.take("--paraboloid", &v)) {
      set_once(paraboloid, "--paraboloid", v);
    } else if (args.take("--sphere", &v)) {
      set_once(sphere, "--sphere", v);
    } else if (args.take("--standard-paraboloid", &v)) {
      set_once(standard, "--standard-paraboloid", v);
    } else if (args.take("--translation", &v)) {
      set_once(translation, "--translation", v);
    } else if (args.take("--rotation", &v)) {
      set_once(rotation, "--rotation", v);
    } else if (args.take("--pivot", &v)) {
      set_once(pivot, "--pivot", v);
    } else if (args.take("--t0", &v)) {
      set_once(t0s, "--t0", v);
    } else if (args.take("--t1", &v)) {
      set_once(t1s, "--t1", v);
    } else if (args.take("--digits", &v)) {
      digits = parse_digits(v);
    } else if (args.take("--first-contact", nullptr)) {
      only_first = true;
    } else if (args.take("--json", nullptr)) {
      json = true;
    } else {
      const std::string a = args.next();
      throw UsageError{(a.rfind("-", 0) == 0 ? "unknown option '" : "unexpected argument '") + a + "'"};
    }
  }
  if (ellipsoid && sphere) throw UsageError{"give either --ellipsoid or --sphere, not both"};
  if (paraboloid && standard) throw UsageError{"give either --paraboloid or --standard-paraboloid, not both"};
  if (!ellipsoid && !sphere) throw UsageError{"missing the ellipsoid (--ellipsoid Q or --sphere X,Y,Z,R)"};
  if (!paraboloid && !standard)
    throw UsageError{"missing the paraboloid (--paraboloid Q or --standard-paraboloid A,B)"};
  if (!t0s || !t1s) throw UsageError{"missing the time interval (--t0 T0 --t1 T1)"};

  try {
    std::optional<relpos::Ellipsoid> e;
    if (ellipsoid) {
      e = relpos::io::ellipsoid_from_json(parse_inline(*ellipsoid, "ellipsoid"), "ellipsoid");
    } else {
      const auto x = comma_numbers(*sphere, 4, "--sphere");
      try {
        e = relpos::Ellipsoid::sphere({x[0], x[1], x[2]}, x[3]);
      } catch (const relpos::InputError& err) {
        throw relpos::InputError(std::string("ellipsoid: ") + err.what());
      }
    }
    std::optional<relpos::Paraboloid> p;
    if (paraboloid) {
      p = relpos::io::paraboloid_from_json(parse_inline(*paraboloid, "paraboloid"), "paraboloid");
    } else {
      const auto x = comma_numbers(*standard, 2, "--standard-paraboloid");
      try {
        const Rational zero(0);
        p = relpos::Paraboloid::standard({zero, zero, zero}, x[0], x[1]);
      } catch (const relpos::InputError& err) {
        throw relpos::InputError(std::string("paraboloid: ") + err.what());
      }
    }
    relpos::RigidMotion m;
    if (translation) m.translation = polynomials<3>(*translation, "translation");
    if (rotation) m.rotation = polynomials<4>(*rotation, "rotation");
    if (pivot) {
      if (*pivot == "origin") {
        m.pivot = relpos::Pivot::Origin;
      } else if (*pivot == "center" || *pivot == "centre") {
        m.pivot = relpos::Pivot::Centre;
      } else {
        const auto x = comma_numbers(*pivot, 3, "--pivot");
        m.pivot = relpos::Pivot::Point;
        m.pivot_point = {x[0], x[1], x[2]};
      }
    }
    Rational t0, t1;
    try {
      t0 = relpos::parse_rational(*t0s);
      t1 = relpos::parse_rational(*t1s);
    } catch (const relpos::InputError& err) {
      throw relpos::InputError(std::string("--t0/--t1: ") + err.what());
    }

    const relpos::FirstContact fc = relpos::first_contact(*e, m, *p, t0, t1);
    std::optional<relpos::Timeline> tl;
    if (!only_first) tl = relpos::timeline(*e, m, *p, t0, t1);

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
      for (const auto& c : relpos::pivot_of(*e, m)) pv.push_back(relpos::to_string(c));
      motion["pivot"] = pv;
      out["motion"] = motion;
      out["first_contact"] = first_contact_json(fc, digits);
      if (tl) out["timeline"] = timeline_json(*tl, digits);
      std::cout << out.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
    } else {
      std::cout << "motion on [" << relpos::to_string(t0) << ", " << relpos::to_string(t1) << "]: c(t) = ("
                << poly_text(m.translation[0]) << ", " << poly_text(m.translation[1]) << ", "
                << poly_text(m.translation[2]) << ")";
      if (m.rotation) {
        const auto pv = relpos::pivot_of(*e, m);
        std::cout << ", q(t) = (" << poly_text((*m.rotation)[0]) << ", " << poly_text((*m.rotation)[1]) << ", "
                  << poly_text((*m.rotation)[2]) << ", " << poly_text((*m.rotation)[3]) << ") about ("
                  << relpos::to_string(pv[0]) << ", " << relpos::to_string(pv[1]) << ", " << relpos::to_string(pv[2])
                  << ")";
      } else {
        std::cout << ", no rotation";
      }
      std::cout << "\n" << first_contact_text(fc, digits);
      if (tl) std::cout << timeline_text(*tl, digits);
    }
    std::cout.flush();
    return std::cout ? kExitOk : kExitIo;
  } catch (const relpos::InputError& err) {
    if (json) std::cout << Json{{"error", err.what()}}.dump() << "\n";
    std::cerr << "relpos: " << err.what() << "\n";
    return kExitInput;
  }
}

}  // namespace

int run_motion(const std::vector<std::string>& args) {
  try {
    return run(args);
  } catch (const UsageError& u) {
    std::cerr << "relpos: " << u.message << "\nTry 'relpos motion --help'.\n";
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    std::cerr << "relpos: out of memory\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "relpos: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

}  // namespace relpos_cli
