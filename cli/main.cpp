// relpos: command-line front end of the library (doc/cli.md).
//
//   relpos classify --ellipsoid Q --paraboloid Q [--digits N] [--json]
//   relpos batch [FILE|-] [--digits N]
//   relpos scene --paraboloid Q [FILE|-] ...   (cli/scene.cpp)
//
// Exit codes: 0 success (batch: every line answered, error lines included), 1 input error
// (classify), 2 usage error, 3 I/O error, 4 internal error.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "common.hpp"
#include "options.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"
#include "relpos/version.hpp"

namespace relpos_cli {

using Json = nlohmann::ordered_json;

constexpr const char* kExitCodes =
    "Exit codes:\n"
    "  0  success (batch: every input line was answered, even if some answers are errors)\n"
    "  1  input error (classify: the quadrics could not be read or are not an ellipsoid and an\n"
    "     elliptic paraboloid)\n"
    "  2  usage error (unknown command or option, missing or conflicting options)\n"
    "  3  I/O error (cannot open or read the input file, cannot write the output)\n"
    "  4  internal error (an unexpected exception)\n"
    "  5  time budget exceeded (motion --max-seconds)\n";

namespace {

/// One screen: the commands, one line each; `relpos COMMAND --help` tells the rest.
void print_main_help(std::ostream& os) {
  os << "relpos " RELPOS_VERSION
        " - exact relative position of an ellipsoid and an elliptic paraboloid\n"
        "\n"
        "Usage: relpos COMMAND [options]      relpos COMMAND --help      relpos --help | --version\n"
        "\n"
        "Commands:\n"
        "  classify  one pair from the command line: position, rule, smallness, roots of f\n"
        "  batch     JSON Lines of pairs, one answer line per input line (--evidence, --threads, ...)\n"
        "  scene     one paraboloid against many ellipsoids (JSON Lines or CSV), on all cores\n"
        "  motion    a body moving by a polynomial translation and rotation: when the position changes\n"
        "  verify    check the certificates of a batch output against its input\n"
        "\n"
        "Positions: I (interior), TI (tangent from inside), C (crossing), TE (tangent from outside),\n"
        "E (exterior): every valid pair gets one of them, whatever the ellipsoid's size.\n"
        "Numbers are exact: JSON numbers are read from their decimal text (0.1 is 1/10) and strings\n"
        "such as \"92281/129600\" or \"1.5e-7\" are accepted anywhere a number is. See doc/cli.md.\n"
        "\n"
     << kExitCodes;
}

}  // namespace

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
        "  --contact-only             answer only whether the surfaces meet: none, touching or crossing,\n"
        "                             certified like the position (doc/contact.md)\n"
        "  -h, --help                 this help\n"
        "\n"
        "Example:\n"
        "  relpos classify --standard-paraboloid 1.2,1.5 \\\n"
        "      --ellipsoid '{\"sphere\":{\"center\":[0,\"1/2\",\"92281/129600\"],\"radius\":\"1/4\"}}'\n"
        "\n"
     << kExitCodes;
}

void print_batch_help(std::ostream& os) {
  os << "Usage: relpos batch [FILE|-] [--digits N] [--contact-only] [--evidence full|minimal]\n"
        "                    [--threads N] [--numbers exact|double] [--max-line-bytes N]\n"
        "\n"
        "Read JSON Lines from FILE (or standard input when FILE is '-' or absent), one pair per line:\n"
        "  {\"id\": ANY, \"ellipsoid\": Q, \"paraboloid\": Q, \"comment\": ANY}\n"
        "(Q as for `relpos classify --help`; \"id\" and \"comment\" are optional). Write JSON Lines to\n"
        "standard output: exactly one line per input line, in input order; the output is flushed whenever\n"
        "the input has nothing more ready (so interactive use is answered line by line):\n"
        "  {\"id\": ..., \"position\": \"I|TI|C|TE|E\", \"small\": ..., \"contact\": ...,\n"
        "   \"rho_vs_one\": ..., \"rho\": ..., \"rho_approx\": ..., \"rule\": ..., \"stage\": ..., ...}\n"
        "or {\"id\": ..., \"error\": \"...\"} for a line that cannot be classified (blank lines included).\n"
        "The id is echoed back byte for byte; a missing id is replaced by the 1-based line number.\n"
        "Duplicate keys are errors; CRLF line ends and a UTF-8 byte order mark at the start are accepted.\n"
        "\n"
        "Options:\n"
        "  --digits N       significant digits of root approximations (default 12, 1..1000)\n"
        "  --contact-only   answer {\"id\", \"contact\", \"position\", \"rule\", \"decided_by\"} only:\n"
        "                   contact is none, touching or crossing (doc/contact.md)\n"
        "  --evidence full|minimal   full (default): the whole report with its certificate;\n"
        "                   minimal: id, position, small, contact, rule, stage\n"
        "  --threads N      worker threads (default: all cores); output stays in input order\n"
        "  --numbers exact|double    exact (default): decimals read exactly; double: each JSON\n"
        "                   number is the IEEE double nearest its text (a float program's input)\n"
        "  --max-line-bytes N        longest input line (default 67108864 = 64 MiB); a longer line\n"
        "                   is answered with an error and the run goes on\n"
        "  -h, --help       this help\n"
        "\n"
     << kExitCodes;
}

namespace {

/// --digits N of classify and batch.
int parse_digits(const std::string& text) { return static_cast<int>(parse_count(text, "--digits", 1, 1000)); }

void write_json_line(const Json& j) { std::cout << relpos::io::dump_json(j) << '\n'; }

// ------------------------------------------------------------------------------------------------

}  // namespace

int run_classify(Args& args) {
  ShapeOptions shapes;
  int digits = 12;
  bool json = false, contact_only = false;
  while (!args.done()) {
    if (args.help()) {
      print_classify_help(std::cout);
      return finish_cout();
    }
    std::string v;
    if (shapes.take(args) || args.flag("--json", json) || args.flag("--contact-only", contact_only)) continue;
    if (!args.value("--digits", v)) args.unexpected();
    digits = parse_digits(v);
  }
  shapes.check(/*need_ellipsoid=*/true);

  relpos::io::RenderOptions options;
  options.digits = digits;
  try {
    const std::optional<relpos::Ellipsoid> e = shapes.make_ellipsoid();
    const std::optional<relpos::Paraboloid> p = shapes.make_paraboloid();
    relpos::check_normalized_pair_size(*e, *p);  // doc/cli.md, Limits
    if (contact_only) {
      const Json j = relpos::io::contact_to_json(relpos::contact(*e, *p));
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
      std::cout << relpos::io::classification_json_text(c, options) << '\n';
    else
      std::cout << relpos::io::classification_to_text(c, options);
    return finish_cout();
  } catch (const relpos::InputError& err) {
    if (json) write_json_line(Json{{"error", err.what()}});
    std::cerr << "relpos: " << err.what() << "\n";
    return finish_cout() == kExitOk ? kExitInput : kExitIo;
  }
}

// ------------------------------------------------------------------------------------------------

namespace {

/// Answer lines[i] into answers[i] for i < n, on the pool's threads. Both vectors keep their
/// strings from chunk to chunk: a line costs no allocation once the buffers have grown (with two
/// threads, every malloc takes an arena lock).
/// Capacity kept in every answer buffer: an out-of-memory error line fits without allocating.
constexpr std::size_t kAnswerReserve = 256;

/// {"id":N,"error":"message"} and a newline, written in pieces (no allocation); message is plain ASCII.
void write_error_line(Output& out, long number, std::string_view message) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, number).ptr;
  out.write("{\"id\":");
  out.write(std::string_view(digits, static_cast<std::size_t>(end - digits)));
  out.write(",\"error\":\"");
  out.write(message);
  out.write("\"}");
}

void answer_all(const std::vector<std::string>& lines, std::size_t n, long first_number,
                const relpos::io::BatchOptions& options, WorkerPool& pool, std::vector<std::string>& answers) {
  if (answers.size() < n) answers.resize(n);
  pool.run(n, [&](std::size_t i) {
    relpos::io::answer_batch_line(lines[i], first_number + static_cast<long>(i), options, answers[i]);
  });
}

}  // namespace

int run_batch(Args& args) {
  std::optional<std::string> file;
  relpos::io::BatchOptions options;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  while (!args.done()) {
    std::string v;
    if (args.help()) {
      print_batch_help(std::cout);
      return finish_cout();
    } else if (args.value("--digits", v)) {
      options.render.digits = parse_digits(v);
    } else if (args.flag("--contact-only")) {
      options.contact_only = true;
    } else if (args.value("--evidence", v)) {
      if (v != "full" && v != "minimal") throw UsageError{"--evidence must be full or minimal, got '" + v + "'"};
      options.evidence = v == "full" ? relpos::Evidence::Full : relpos::Evidence::Minimal;
    } else if (args.value("--numbers", v)) {
      if (v != "exact" && v != "double") throw UsageError{"--numbers must be exact or double, got '" + v + "'"};
      options.numbers_as_doubles = v == "double";
    } else if (args.value("--threads", v)) {
      threads = static_cast<unsigned>(parse_count(v, "--threads", 1, 1024));
    } else if (args.value("--max-line-bytes", v)) {
      options.max_line_bytes = parse_count(v, "--max-line-bytes", 1, std::size_t(1) << 40);
    } else if (args.peek() != "-" && args.peek().rfind("-", 0) == 0) {
      args.unexpected();
    } else {
      if (file) throw UsageError{"more than one input file given"};
      file = args.next();
    }
  }
  const int fd = open_input(file ? *file : "-");
  if (fd < 0) return kExitIo;
  const std::string name = file && *file != "-" ? *file : "<stdin>";
  LineReader reader(fd, options.max_line_bytes);
  Output out;
  WorkerPool pool(threads);
  const std::string too_long = relpos::io::too_long_message(options.max_line_bytes);
  // Lines are answered in chunks (on the threads) and written in input order; the output is flushed
  // whenever the input has nothing more ready, so interactive use is answered line by line.
  const std::size_t chunk = threads > 1 ? 64 * std::size_t(threads) : 16;
  std::vector<std::string> lines(chunk), answers(chunk);  // reused: see answer_all
  std::vector<LineReader::Status> status(chunk);          // per line: read, or refused while reading
  for (auto& a : answers) a.reserve(kAnswerReserve);      // room for an out-of-memory line
  long number = 0;
  for (bool more = true; more;) {
    std::size_t n = 0;
    while (n < chunk && (n == 0 || reader.ready())) {
      status[n] = reader.next(lines[n]);
      if (status[n] == LineReader::Status::End) {
        more = false;
        break;
      }
      if (status[n] == LineReader::Status::Error) {
        out.flush();
        std::cerr << "relpos: error reading '" << name << "': " << std::strerror(reader.error()) << "\n";
        return kExitIo;
      }
      if (status[n] != LineReader::Status::Line) lines[n].clear();
      ++n;
    }
    answer_all(lines, n, number + 1, options, pool, answers);
    for (std::size_t i = 0; i < n; ++i) {
      const long line_number = number + 1 + static_cast<long>(i);
      if (status[i] == LineReader::Status::TooLong)
        write_error_line(out, line_number, too_long);
      else if (status[i] == LineReader::Status::OutOfMemory)
        write_error_line(out, line_number, "out of memory while reading this line");
      else if (answers[i].empty())  // not even the short error fitted (relpos::io::answer_batch_line)
        write_error_line(out, line_number, relpos::io::kOutOfMemoryNoIdMessage);
      else
        out.write(answers[i]);
      out.write("\n");
    }
    number += static_cast<long>(n);
    for (std::size_t i = 0; i < n; ++i) {  // a rare long line does not hold its memory for the whole run
      if (lines[i].capacity() > (std::size_t(1) << 20)) std::string().swap(lines[i]);
      if (answers[i].capacity() > (std::size_t(1) << 20)) {
        std::string().swap(answers[i]);
        try {
          answers[i].reserve(kAnswerReserve);
        } catch (const std::bad_alloc&) {  // answer_batch_line tries again
        }
      }
    }
    if (!more || !reader.ready()) out.flush();
    if (out.failed()) return out.report_failure();
  }
  return out.flush() ? kExitOk : out.report_failure();
}

}  // namespace relpos_cli

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  relpos::install_gmp_block_cache();  // before any number: see relpos/numbers.hpp
  std::signal(SIGPIPE, SIG_IGN);      // a closed pipe is a write error (exit 3 with a message), not a kill
  std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty()) {
    relpos_cli::print_main_help(std::cerr);
    return relpos_cli::kExitUsage;
  }
  const std::string command = all.front();
  using namespace relpos_cli;
  Args args(std::vector<std::string>(all.begin() + 1, all.end()));
  const bool known =
      command == "classify" || command == "batch" || command == "scene" || command == "motion" || command == "verify";
  try {
    const bool about = command == "--help" || command == "-h" || command == "help" || command == "--version";
    if (about && !args.done()) throw UsageError{command + " takes no argument, got '" + args.peek() + "'"};
    if (command == "--help" || command == "-h" || command == "help") {
      print_main_help(std::cout);
      return finish_cout();
    }
    if (command == "--version") {
      std::cout << "relpos " RELPOS_VERSION "\n";
      return finish_cout();
    }
    if (command == "classify") return run_classify(args);
    if (command == "batch") return run_batch(args);
    if (command == "verify") return run_verify(args);
    if (command == "scene") return run_scene(args);
    if (command == "motion") return run_motion(args);
    throw UsageError{(command.rfind("-", 0) == 0 ? "unknown option '" : "unknown command '") + command + "'"};
  } catch (const UsageError& u) {
    std::cerr << "relpos: " << u.message << "\nTry 'relpos --help'";
    if (known) std::cerr << " or 'relpos " << command << " --help'";
    std::cerr << ".\n";
    return kExitUsage;
  } catch (const relpos::InputError& e) {
    std::cerr << "relpos: " << e.what() << "\n";
    return kExitInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "relpos: out of memory\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "relpos: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
