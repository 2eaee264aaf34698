// relpos: command-line front end of the library (doc/cli.md).
//
//   relpos classify --ellipsoid Q --paraboloid Q [--digits N] [--json]
//   relpos batch [FILE|-] [--digits N]
//   relpos scene --paraboloid Q [FILE|-] ...   (cli/scene.cpp)
//
// Exit codes: 0 success (batch: every line answered, error lines included), 1 input error
// (classify), 2 usage error, 3 I/O error, 4 internal error.
#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "motion.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

/// `relpos scene` (cli/scene.cpp): exit code; handles its own usage errors.
int run_scene_command(const std::vector<std::string>& args);
int run_verify(int argc, char** argv);  // `relpos verify` (cli/verify.cpp)

#ifndef RELPOS_VERSION
#define RELPOS_VERSION "unknown"
#endif

namespace {

using Json = nlohmann::ordered_json;

constexpr int kExitOk = 0;
constexpr int kExitInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitIo = 3;
constexpr int kExitInternal = 4;

constexpr const char* kExitCodes =
    "Exit codes:\n"
    "  0  success (batch: every input line was answered, even if some answers are errors)\n"
    "  1  input error (classify: the quadrics could not be read or are not an ellipsoid and an\n"
    "     elliptic paraboloid)\n"
    "  2  usage error (unknown command or option, missing or conflicting options)\n"
    "  3  I/O error (cannot open or read the input file, cannot write the output)\n"
    "  4  internal error (an unexpected exception)\n";

void print_main_help(std::ostream& os) {
  os << "relpos " RELPOS_VERSION
        " - exact relative position of an ellipsoid and an elliptic paraboloid\n"
        "\n"
        "Usage:\n"
        "  relpos classify --ellipsoid Q --paraboloid Q [--digits N] [--json]\n"
        "  relpos batch [FILE|-] [--digits N]\n"
        "  relpos scene (--paraboloid Q | --standard-paraboloid A,B) [FILE|-] [options]\n"
        "  relpos motion (--ellipsoid Q | --sphere ..) (--paraboloid Q | ..) [--translation P3] [--rotation P4] ...\n"
        "  relpos verify INPUT.jsonl ANSWERS.jsonl [--quiet]   (check the certificates of a batch output)\n"
        "  relpos --help | --version\n"
        "  relpos COMMAND --help\n"
        "\n"
        "Positions: I (interior), TI (tangent from inside), C (crossing), TE (tangent from outside),\n"
        "E (exterior), or unclassified (outside the theory: the ellipsoid is not small).\n"
        "Numbers are exact: JSON numbers are read from their decimal text (0.1 is 1/10) and strings\n"
        "such as \"92281/129600\" or \"1.5e-7\" are accepted anywhere a number is. See doc/cli.md.\n"
        "\n"
     << kExitCodes;
}

void print_classify_help(std::ostream& os) {
  os << "Usage: relpos classify (--ellipsoid Q | --sphere X,Y,Z,R)\n"
        "                       (--paraboloid Q | --standard-paraboloid A,B) [--digits N] [--json]\n"
        "                       [--contact-only]\n"
        "\n"
        "Classify one pair and print a report: the position and its meaning, the deciding rule,\n"
        "smallness (rho against 1), the characteristic polynomial f with exact coefficients, its real\n"
        "roots as certified decimals with multiplicities (tangency or special root), the non-real count.\n"
        "\n"
        "Options:\n"
        "  --ellipsoid Q              the ellipsoid as inline JSON: a 4x4 symmetric matrix, {\"matrix\": ...},\n"
        "                             {\"coefficients\": [A..J]}, {\"sphere\": {\"center\": [x,y,z], \"radius\": r}},\n"
        "                             {\"center\": [..], \"axes\": [a,b,c], \"rotation\": [w,x,y,z]},\n"
        "                             {\"center\": [..], \"axes\": [..], \"rotation_matrix\": 3x3},\n"
        "                             {\"center\": [..], \"map\": 3x3}\n"
        "  --paraboloid Q             the paraboloid as inline JSON: a 4x4 matrix, {\"matrix\": ...},\n"
        "                             {\"coefficients\": [A..J]}, {\"vertex\": [..], \"a\": a, \"b\": b,\n"
        "                             \"rotation\": [w,x,y,z]} (x'^2/a^2 + y'^2/b^2 = z'),\n"
        "                             {\"map\": 3x3, \"translation\": [..]} (image of z = x^2 + y^2)\n"
        "  --sphere X,Y,Z,R           shorthand: sphere with centre (X,Y,Z) and radius R\n"
        "  --standard-paraboloid A,B  shorthand: x^2/A^2 + y^2/B^2 = z (vertex at the origin, axis z)\n"
        "  --digits N                 significant digits of the approximations (default 12, 1..1000)\n"
        "  --json                     print the JSON object of `relpos batch` instead of the report\n"
        "  --contact-only             answer only whether the surfaces meet: none, touching, crossing,\n"
        "                             meet (kind not certified) or unknown; certified like the position,\n"
        "                             and also for bodies that are not small when a containment\n"
        "                             certificate proves they do not meet (doc/contact.md)\n"
        "  -h, --help                 this help\n"
        "\n"
        "Example:\n"
        "  relpos classify --standard-paraboloid 1.2,1.5 \\\n"
        "      --ellipsoid '{\"sphere\":{\"center\":[0,\"1/2\",\"92281/129600\"],\"radius\":\"1/4\"}}'\n"
        "\n"
     << kExitCodes;
}

void print_batch_help(std::ostream& os) {
  os << "Usage: relpos batch [FILE|-] [--digits N] [--contact-only]\n"
        "\n"
        "Read JSON Lines from FILE (or standard input when FILE is '-' or absent), one pair per line:\n"
        "  {\"id\": ANY, \"ellipsoid\": Q, \"paraboloid\": Q, \"comment\": ANY}\n"
        "(Q as for `relpos classify --help`; \"id\" and \"comment\" are optional). Write JSON Lines to\n"
        "standard output: exactly one line per input line, in order, flushed after each line:\n"
        "  {\"id\": ..., \"position\": \"I|TI|C|TE|E|unclassified\", \"small\": ..., \"contact\": ...,\n"
        "   \"rho_vs_one\": ..., \"rho\": ..., \"rho_approx\": ..., \"rule\": ..., \"stage\": ..., ...}\n"
        "or {\"id\": ..., \"error\": \"...\"} for a line that cannot be classified (blank lines included).\n"
        "The id is echoed back; a missing id is replaced by the 1-based line number.\n"
        "\n"
        "Options:\n"
        "  --digits N       significant digits of root approximations (default 12, 1..1000)\n"
        "  --contact-only   answer {\"id\", \"contact\", \"position\", \"rule\", \"decided_by\"} only:\n"
        "                   contact is none, touching, crossing, meet or unknown (doc/contact.md)\n"
        "  -h, --help       this help\n"
        "\n"
     << kExitCodes;
}

struct UsageError {
  std::string message;
};

/// Command-line options of one subcommand: "--name value" or "--name=value"; flags take no value.
class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}
  bool done() const { return pos_ >= args_.size(); }
  const std::string& peek() const { return args_[pos_]; }

  /// If the next argument is option `name`, consume it (and its value when `value` is non-null).
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
    if (value && a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=') {
      *value = a.substr(n.size() + 1);
      ++pos_;
      return true;
    }
    if (!value && a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=')
      throw UsageError{"option " + n + " takes no value"};
    return false;
  }
  std::string next() { return args_[pos_++]; }

 private:
  std::vector<std::string> args_;
  std::size_t pos_ = 0;
};

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

void set_once(std::optional<std::string>& slot, const char* name, std::string value) {
  if (slot) throw UsageError{std::string("option ") + name + " given twice"};
  slot = std::move(value);
}

/// "a,b,c" -> exact numbers; `what` names the option in messages.
std::vector<relpos::Rational> comma_numbers(const std::string& text, std::size_t count, const std::string& what) {
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
  std::vector<relpos::Rational> out;
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

void write_json_line(const Json& j) {
  std::cout << j.dump(-1, ' ', false, Json::error_handler_t::replace) << '\n';
  std::cout.flush();
}

/// The contact-only answer as JSON (doc/contact.md).
Json contact_json(const relpos::ContactAnswer& a) {
  Json j;
  j["contact"] = relpos::to_string(a.contact);
  j["position"] = relpos::to_string(a.position);
  j["rule"] = relpos::describe(a.rule);
  j["decided_by"] = relpos::to_string(a.by);
  return j;
}

// ------------------------------------------------------------------------------------------------

int run_classify(Args& args) {
  std::optional<std::string> ellipsoid, paraboloid, sphere, standard;
  int digits = 12;
  bool json = false, contact_only = false;
  while (!args.done()) {
    std::string v;
    if (args.take("--help", nullptr) || args.take("-h", nullptr)) {
      print_classify_help(std::cout);
      return kExitOk;
    } else if (args.take("--ellipsoid", &v)) {
      set_once(ellipsoid, "--ellipsoid", v);
    } else if (args.take("--paraboloid", &v)) {
      set_once(paraboloid, "--paraboloid", v);
    } else if (args.take("--sphere", &v)) {
      set_once(sphere, "--sphere", v);
    } else if (args.take("--standard-paraboloid", &v)) {
      set_once(standard, "--standard-paraboloid", v);
    } else if (args.take("--digits", &v)) {
      digits = parse_digits(v);
    } else if (args.take("--json", nullptr)) {
      json = true;
    } else if (args.take("--contact-only", nullptr)) {
      contact_only = true;
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

  relpos::io::RenderOptions options;
  options.digits = digits;
  try {
    std::optional<relpos::Ellipsoid> e;
    if (ellipsoid) {
      e = relpos::io::ellipsoid_from_json(parse_inline(*ellipsoid, "ellipsoid"), "ellipsoid");
    } else {
      auto x = comma_numbers(*sphere, 4, "--sphere");
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
      auto x = comma_numbers(*standard, 2, "--standard-paraboloid");
      try {
        const relpos::Rational zero(0);
        p = relpos::Paraboloid::standard({zero, zero, zero}, x[0], x[1]);
      } catch (const relpos::InputError& err) {
        throw relpos::InputError(std::string("paraboloid: ") + err.what());
      }
    }
    relpos::io::check_pair_size(*e, *p);  // doc/cli.md, Limits
    if (contact_only) {
      const Json j = contact_json(relpos::contact(*e, *p));
      if (json)
        write_json_line(j);
      else
        std::cout << "contact: " << j["contact"].get<std::string>() << " (position " << j["position"].get<std::string>()
                  << "; " << j["rule"].get<std::string>() << "; decided by " << j["decided_by"].get<std::string>()
                  << ")\n"
                  << std::flush;
      return std::cout ? kExitOk : kExitIo;
    }
    const relpos::Classification c = relpos::classify(*e, *p, relpos::Evidence::Full);
    if (json)
      write_json_line(relpos::io::classification_to_json(c, options));
    else
      std::cout << relpos::io::classification_to_text(c, options) << std::flush;
    return std::cout ? kExitOk : kExitIo;
  } catch (const relpos::InputError& err) {
    if (json) write_json_line(Json{{"error", err.what()}});
    std::cerr << "relpos: " << err.what() << "\n";
    return kExitInput;
  }
}

// ------------------------------------------------------------------------------------------------

bool is_blank(const std::string& s) {
  for (char ch : s)
    if (ch != ' ' && ch != '\t' && ch != '\r' && ch != '\n') return false;
  return true;
}

/// The answer to one input line (never throws).
Json answer_line(const std::string& line, long line_number, const relpos::io::RenderOptions& options,
                 bool contact_only) {
  Json id = line_number;
  try {
    if (is_blank(line)) throw relpos::InputError("empty line");
    // The exact document (floats kept as text) for the quadrics; the ordinary parse only for the id,
    // so that it is echoed back as the JSON value it was.
    const Json doc = relpos::io::parse_json_exact(line);
    if (!doc.is_object())
      throw relpos::InputError("expected a JSON object {\"id\": ..., \"ellipsoid\": ..., \"paraboloid\": ...}");
    if (doc.contains("id")) {
      try {
        id = Json::parse(line)["id"];
      } catch (const nlohmann::json::exception&) {
        id = doc["id"];  // a number beyond double range somewhere: its floats stay as text
      }
    }
    for (const auto& item : doc.items()) {
      const std::string& k = item.key();
      if (k != "id" && k != "ellipsoid" && k != "paraboloid" && k != "comment")
        throw relpos::InputError("unknown key \"" + k.substr(0, 40) +
                                 "\" (a line takes \"id\", \"ellipsoid\", \"paraboloid\" and \"comment\")");
    }
    if (!doc.contains("ellipsoid")) throw relpos::InputError("ellipsoid: missing");
    if (!doc.contains("paraboloid")) throw relpos::InputError("paraboloid: missing");
    const relpos::Ellipsoid e = relpos::io::ellipsoid_from_json(doc["ellipsoid"], "ellipsoid");
    const relpos::Paraboloid p = relpos::io::paraboloid_from_json(doc["paraboloid"], "paraboloid");
    relpos::io::check_pair_size(e, p);  // doc/cli.md, Limits
    Json out;
    out["id"] = id;
    if (contact_only) {
      Json answer = contact_json(relpos::contact(e, p));  // named: items() must not outlive it
      for (auto& item : answer.items()) out[item.key()] = std::move(item.value());
      return out;
    }
    const relpos::Classification c = relpos::classify(e, p, relpos::Evidence::Full);
    Json report = relpos::io::classification_to_json(c, options);
    for (auto& item : report.items()) out[item.key()] = std::move(item.value());
    return out;
  } catch (const relpos::InputError& err) {
    return Json{{"id", id}, {"error", err.what()}};
  } catch (const std::bad_alloc&) {
    return Json{{"id", id}, {"error", "out of memory while classifying this line"}};
  } catch (const std::exception& err) {
    return Json{{"id", id}, {"error", std::string("internal error: ") + err.what()}};
  } catch (...) {
    return Json{{"id", id}, {"error", "internal error: unknown exception"}};
  }
}

int run_batch(Args& args) {
  std::optional<std::string> file;
  relpos::io::RenderOptions options;
  bool contact_only = false;
  while (!args.done()) {
    std::string v;
    if (args.take("--help", nullptr) || args.take("-h", nullptr)) {
      print_batch_help(std::cout);
      return kExitOk;
    } else if (args.take("--digits", &v)) {
      options.digits = parse_digits(v);
    } else if (args.take("--contact-only", nullptr)) {
      contact_only = true;
    } else if (args.peek() != "-" && args.peek().rfind("-", 0) == 0) {
      throw UsageError{"unknown option '" + args.next() + "'"};
    } else {
      if (file) throw UsageError{"more than one input file given"};
      file = args.next();
    }
  }
  std::ifstream in_file;
  std::istream* in = &std::cin;
  const std::string name = file && *file != "-" ? *file : "<stdin>";
  if (file && *file != "-") {
    in_file.open(*file, std::ios::binary);
    if (!in_file) {
      std::cerr << "relpos: cannot open '" << *file << "': " << std::strerror(errno) << "\n";
      return kExitIo;
    }
    in = &in_file;
  }
  std::string line;
  long number = 0;
  while (std::getline(*in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    write_json_line(answer_line(line, number, options, contact_only));
    if (!std::cout) {
      std::cerr << "relpos: cannot write the output\n";
      return kExitIo;
    }
  }
  if (in->bad()) {
    std::cerr << "relpos: error reading '" << name << "'\n";
    return kExitIo;
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty()) {
    print_main_help(std::cerr);
    return kExitUsage;
  }
  const std::string command = all.front();
  Args args(std::vector<std::string>(all.begin() + 1, all.end()));
  try {
    if (command == "--help" || command == "-h" || command == "help") {
      print_main_help(std::cout);
      return kExitOk;
    }
    if (command == "--version") {
      std::cout << "relpos " RELPOS_VERSION "\n";
      return kExitOk;
    }
    if (command == "classify") return run_classify(args);
    if (command == "batch") return run_batch(args);
    if (command == "verify") return run_verify(argc - 1, argv + 1);
    if (command == "scene") return run_scene_command(std::vector<std::string>(all.begin() + 1, all.end()));
    if (command == "motion") return relpos_cli::run_motion(std::vector<std::string>(all.begin() + 1, all.end()));
    throw UsageError{(command.rfind("-", 0) == 0 ? "unknown option '" : "unknown command '") + command + "'"};
  } catch (const UsageError& u) {
    std::cerr << "relpos: " << u.message << "\nTry 'relpos --help'";
    if (command == "classify" || command == "batch") std::cerr << " or 'relpos " << command << " --help'";
    std::cerr << ".\n";
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    std::cerr << "relpos: out of memory\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "relpos: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
