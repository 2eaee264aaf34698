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
#include <condition_variable>
#include <csignal>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "algebra/pair_size.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "io/answer_json.hpp"
#include "io/batch.hpp"
#include "io/general_io.hpp"
#include "io/json_tree.hpp"
#include "io/report_text.hpp"
#include "margin/family.hpp"
#include "options.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"
#include "relpos/margin.hpp"
#include "relpos/version.hpp"

namespace relpos_cli {

using relpos::detail::io::Json;

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
        "  cases     hard pairs of known position for judging float code (doc/oracle.md)\n"
        "  judge     a float code's answers against the cases: error rates, confusion, misses, chart\n"
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
        "                       [--contact-only] [--margin] [--margin-bits B] [--max-bits N]\n"
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
        "  --quadric Q                any real quadric in place of the paraboloid (doc/quadrics.md): a 4x4\n"
        "                             matrix, {\"coefficients\": [A..J]} or {\"type\": T, ...}, T one of sphere,\n"
        "                             ellipsoid, hyperboloid of one sheet, hyperboloid of two sheets, elliptic\n"
        "                             cone, elliptic paraboloid, hyperbolic paraboloid, elliptic cylinder,\n"
        "                             hyperbolic cylinder, parabolic cylinder, slab, half-space (doc/cli.md)\n"
        "  --sphere X,Y,Z,R           shorthand: sphere with centre (X,Y,Z) and radius R\n"
        "  --standard-paraboloid A,B  shorthand: x^2/A^2 + y^2/B^2 = z (vertex at the origin, axis z)\n"
        "  --digits N                 significant digits of the approximations (default 12, 1..1000)\n"
        "  --json                     print the JSON object of `relpos batch` instead of the report\n"
        "  --contact-only             answer only whether the surfaces meet: none, touching or crossing,\n"
        "                             certified like the position (doc/contact.md)\n"
        "  --margin                   also s*, the factor by which the ellipsoid scaled about its centre\n"
        "                             first touches the paraboloid, exactly and with its proof (JSON:\n"
        "                             \"margin\"; doc/certificates.md, \"Margins\")\n"
        "  --margin-bits B            the margin's enclosure: relative width 2^-B (default 40, 1..1000;\n"
        "                             implies --margin)\n"
        "  --max-bits N               the pair size limit (default 4096, at least 4096): entries of each\n"
        "                             matrix's primitive integer form (doc/cli.md, Limits)\n"
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
        "                    [--threads N] [--numbers exact|double] [--max-line-bytes N] [--max-bits N]\n"
        "                    [--margin] [--margin-bits B]\n"
        "\n"
        "Read JSON Lines from FILE (or standard input when FILE is '-' or absent), one pair per line:\n"
        "  {\"id\": ANY, \"ellipsoid\": Q, \"paraboloid\": Q, \"comment\": ANY}\n"
        "(Q as for `relpos classify --help`; \"id\" and \"comment\" are optional; \"quadric\": Q in place of\n"
        "\"paraboloid\" for any real quadric, doc/quadrics.md). Write JSON Lines to\n"
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
        "  --margin         every answer ends with \"margin\": s*, the factor by which the ellipsoid\n"
        "                   scaled about its centre first touches the paraboloid, exactly, with its\n"
        "                   proof (doc/certificates.md, \"Margins\")\n"
        "  --margin-bits B  the margin's enclosure: relative width 2^-B (default 40, 1..1000; implies\n"
        "                   --margin)\n"
        "  --max-bits N     the pair size limit (default 4096, at least 4096): entries of each matrix's\n"
        "                   primitive integer form; the cost of a pair grows with it (doc/cli.md, Limits)\n"
        "  -h, --help       this help\n"
        "\n"
     << kExitCodes;
}

namespace {

/// --digits N of classify and batch.
int parse_digits(const std::string& text) { return static_cast<int>(parse_count(text, "--digits", 1, 1000)); }

void write_json_line(const Json& j) { std::cout << relpos::detail::io::dump_json(j) << '\n'; }

/// --margin and --margin-bits B (classify and batch): bits > 0 asks for the margin.
bool take_margin(Args& args, int& bits) {
  std::string v;
  if (args.flag("--margin")) {
    if (bits == 0) bits = relpos::kDefaultMarginBits;
    return true;
  }
  if (!args.value("--margin-bits", v)) return false;
  bits = static_cast<int>(parse_count(v, "--margin-bits", 1, relpos::detail::kMaxMarginBits));
  return true;
}

/// An answer's JSON text with "margin" as its last member (when there is a margin), by the answer writer.
std::string with_margin(std::string answer, const std::optional<relpos::Margin>& m,
                        const relpos::io::RenderOptions& options) {
  if (m) relpos::detail::io::append_margin_member(*m, options.digits, answer);
  return answer;
}

/// `relpos classify --quadric Q`: an ellipsoid against a general quadric (doc/quadrics.md).
int run_classify_general(const ShapeOptions& shapes, const std::string& quadric, int digits, bool json,
                         bool contact_only, const relpos::SizeLimit& limit) {
  if (shapes.paraboloid || shapes.standard)
    throw UsageError{"give either --quadric or a paraboloid (--paraboloid, --standard-paraboloid), not both"};
  if (!shapes.ellipsoid && !shapes.sphere)
    throw UsageError{"missing the ellipsoid (--ellipsoid Q or --sphere X,Y,Z,R)"};
  if (shapes.ellipsoid && shapes.sphere) throw UsageError{"give either --ellipsoid or --sphere, not both"};
  try {
    const relpos::Ellipsoid e = shapes.make_ellipsoid();
    const relpos::Quadric q = relpos::detail::io::quadric_from_json(parse_inline(quadric, "quadric"), "quadric");
    const std::size_t bits =
        relpos::detail::io::check_general_pair_size(e, q, limit);  // as a batch line with "quadric"
    if (contact_only) {
      const relpos::QuadricVerdict v =
          relpos::detail::io::with_stack_for_general(bits, [&] { return relpos::decide_position(e, q); });
      if (json)
        std::cout << relpos::detail::io::answer_text(256, v) << '\n';
      else
        std::cout << "contact: " << relpos::to_string(relpos::contact_of(v.position)) << " (position "
                  << relpos::to_string(v.position) << "; " << relpos::describe(v.rule) << "; decided by "
                  << relpos::to_string(v.stage) << ")\n";
      return finish_cout();
    }
    const relpos::QuadricClassification c =
        relpos::detail::io::with_stack_for_general(bits, [&] { return relpos::classify(e, q); });
    if (json)
      std::cout << relpos::detail::io::answer_text(2048, c, digits) << '\n';
    else
      std::cout << relpos::detail::io::general_answer_text(c, digits);
    return finish_cout();
  } catch (const relpos::InputError& err) {
    if (json) write_json_line(Json{{"error", err.what()}});
    std::cerr << "relpos: " << err.what() << "\n";
    return finish_cout() == kExitOk ? kExitInput : kExitIo;
  }
}

// ------------------------------------------------------------------------------------------------

}  // namespace

int run_classify(Args& args) {
  ShapeOptions shapes;
  int digits = 12, margin_bits = 0;
  bool json = false, contact_only = false;
  std::optional<std::string> quadric;
  relpos::SizeLimit limit;
  while (!args.done()) {
    if (args.help()) {
      print_classify_help(std::cout);
      return finish_cout();
    }
    std::string v;
    if (shapes.take(args) || args.flag("--json", json) || args.flag("--contact-only", contact_only)) continue;
    if (take_margin(args, margin_bits)) continue;
    if (args.value("--quadric", v)) {
      quadric = v;
      continue;
    }
    if (args.value("--max-bits", v)) {
      limit.max_bits = parse_max_bits(v);
      continue;
    }
    if (!args.value("--digits", v)) args.unexpected();
    digits = parse_digits(v);
  }
  if (quadric && margin_bits > 0)
    throw UsageError{"--margin: the margin s* is defined for an ellipsoid and an elliptic paraboloid only"};
  if (quadric) return run_classify_general(shapes, *quadric, digits, json, contact_only, limit);
  shapes.check(/*need_ellipsoid=*/true);

  relpos::io::RenderOptions options;
  options.digits = digits;
  try {
    const std::optional<relpos::Ellipsoid> e = shapes.make_ellipsoid();
    const std::optional<relpos::Paraboloid> p = shapes.make_paraboloid();
    const std::optional<relpos::Margin> m =
        margin_bits > 0 ? std::optional<relpos::Margin>(relpos::margin(*e, *p, margin_bits)) : std::nullopt;
    if (contact_only) {
      relpos::detail::check_normalized_pair_size(*e, *p, limit);  // as `relpos batch --contact-only`
      const relpos::ContactAnswer a = relpos::contact(*e, *p, limit);
      if (json)
        std::cout << with_margin(relpos::io::contact_json_text(a), m, options) << '\n';
      else
        std::cout << "contact: " << relpos::to_string(a.contact) << " (position " << relpos::to_string(a.position)
                  << "; " << relpos::describe(a.rule) << "; decided by " << relpos::decided_by(a.stage) << ")\n"
                  << (m ? relpos::detail::io::margin_to_text(*m, options) : "") << std::flush;
      return std::cout ? kExitOk : kExitIo;
    }
    const relpos::Classification c = relpos::classify(*e, *p, relpos::Evidence::Full, limit);
    if (json)
      std::cout << with_margin(relpos::io::classification_json_text(c, options), m, options) << '\n';
    else
      std::cout << relpos::io::classification_to_text(c, options)
                << (m ? relpos::detail::io::margin_to_text(*m, options) : "");
    return finish_cout();
  } catch (const relpos::InputError& err) {
    if (json) write_json_line(Json{{"error", err.what()}});
    std::cerr << "relpos: " << err.what() << "\n";
    return finish_cout() == kExitOk ? kExitInput : kExitIo;
  }
}

// ------------------------------------------------------------------------------------------------

namespace {

/// Capacity kept in every answer buffer: an out-of-memory error line fits without allocating.
constexpr std::size_t kAnswerReserve = 256;

/// {"id":N,"error":"message"} and a newline, written in pieces (no allocation); message is plain ASCII.
/// With `doubles` (--numbers double) the line says so, as every answer does (detail::io::append_trailer).
void write_error_line(Output& out, long number, std::string_view message, bool doubles) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, number).ptr;
  out.write("{\"id\":");
  out.write(std::string_view(digits, static_cast<std::size_t>(end - digits)));
  out.write(",\"error\":\"");
  out.write(message);
  out.write(doubles ? "\",\"numbers\":\"double\"}" : "\"}");
}

/// The lines of `relpos batch` answered on the pool's threads and written in input order. Each
/// thread takes the next few lines from the reader (one thread reads at a time), answers them with
/// no lock held, and writes every answered group that is next in input order: reading, answering
/// and writing overlap, and no thread waits for a round to end (a slow line holds back only the
/// writing of the groups after it, up to kSlots groups). The output is flushed
/// after a group whose last line left the input with nothing more ready, so interactive use is
/// answered line by line.
class BatchPipeline {
 public:
  BatchPipeline(LineReader& reader, Output& out, const relpos::detail::io::BatchOptions& options, unsigned threads,
                std::string too_long)
      : reader_(reader),
        out_(out),
        options_(options),
        too_long_(std::move(too_long)),
        slots_(threads > 1 ? std::max(kSlots, 2 * std::size_t(threads)) : 1) {
    const std::size_t size = threads > 1 ? kGroup : kGroupOneThread;
    for (Slot& s : slots_) {  // every buffer kept from group to group: a line costs no allocation
      s.lines.resize(size);
      s.answers.resize(size);
      s.status.resize(size);
      for (auto& a : s.answers) a.reserve(kAnswerReserve);  // room for an out-of-memory line
    }
  }

  /// Thread w's part: take, answer and write groups until the input ends or cannot be read or written.
  void work() {
    for (;;) {
      Slot* slot = take();
      if (!slot) return;
      for (std::size_t i = 0; i < slot->n; ++i)
        if (slot->status[i] == LineReader::Status::Line)
          relpos::detail::io::answer_batch_line(slot->lines[i], slot->first + static_cast<long>(i), options_,
                                                slot->answers[i]);
      finish(*slot);
    }
  }

  int read_error() const { return read_error_; }

 private:
  // Enough slots that a thread the system stops for a time slice holds back only its group while
  // the others answer up to kSlots * kGroup lines (a few ms) before they wait for it.
  static constexpr std::size_t kGroup = 32, kGroupOneThread = 64, kSlots = 64;
  static constexpr std::size_t kKeep = std::size_t(1) << 14;  ///< buffers longer than this are released

  struct Slot {
    std::vector<std::string> lines, answers;
    std::vector<LineReader::Status> status;  // per line: read, or refused while reading
    std::size_t n = 0;
    long first = 0;      // the number of the first line
    bool flush = false;  // flush the output after this group
    bool done = false;   // answered, not yet written
  };

  /// The next group read into a free slot, or nullptr at the end of the input (or after a failure).
  Slot* take() {
    std::lock_guard<std::mutex> reading(read_mutex_);
    unsigned long seq;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      free_.wait(lock, [&] { return stop_ || next_read_ - next_write_ < slots_.size(); });
      if (stop_) return nullptr;
      seq = next_read_;
    }
    Slot& s = slots_[seq % slots_.size()];
    s.n = 0;
    s.first = lines_read_ + 1;
    bool end = false;
    while (s.n < s.lines.size() && (s.n == 0 || reader_.ready())) {
      const LineReader::Status st = reader_.next(s.lines[s.n]);
      if (st == LineReader::Status::End || st == LineReader::Status::Error) {
        if (st == LineReader::Status::Error) read_error_ = reader_.error();
        end = true;
        break;
      }
      s.status[s.n] = st;
      if (st != LineReader::Status::Line) s.lines[s.n].clear();
      ++s.n;
    }
    lines_read_ += static_cast<long>(s.n);
    s.flush = end || !reader_.ready();
    s.done = false;
    std::lock_guard<std::mutex> lock(mutex_);
    if (end) stop_ = true;  // the threads stop taking; the groups taken are answered and written
    if (s.n == 0) {         // nothing to answer: written (a flush) as soon as the groups before it are
      s.done = true;
      ++next_read_;
      write_ready();
      return nullptr;
    }
    ++next_read_;
    return &s;
  }

  /// Marks the slot answered and writes every answered group that is next in input order.
  void finish(Slot& s) {
    std::lock_guard<std::mutex> lock(mutex_);
    s.done = true;
    write_ready();
  }

  /// Writes the answered groups from next_write_ on (mutex_ held).
  void write_ready() {
    bool freed = false;
    while (next_write_ < next_read_) {
      Slot& s = slots_[next_write_ % slots_.size()];
      if (!s.done) break;
      write(s);
      s.done = false;
      ++next_write_;
      freed = true;
      if (out_.failed()) stop_ = true;
    }
    if (freed) free_.notify_all();
  }

  void write(Slot& s) {
    for (std::size_t i = 0; i < s.n; ++i) {
      const long line_number = s.first + static_cast<long>(i);
      if (s.status[i] == LineReader::Status::TooLong)
        write_error_line(out_, line_number, too_long_, options_.numbers_as_doubles);
      else if (s.status[i] == LineReader::Status::OutOfMemory)
        write_error_line(out_, line_number, "out of memory while reading this line", options_.numbers_as_doubles);
      else if (s.answers[i].empty())  // not even the short error fitted (relpos::detail::io::answer_batch_line)
        write_error_line(out_, line_number, relpos::detail::io::kOutOfMemoryNoIdMessage, options_.numbers_as_doubles);
      else
        out_.write(s.answers[i]);
      out_.write("\n");
    }
    for (std::size_t i = 0; i < s.n; ++i) {  // a rare long line does not hold its memory for the whole run
      if (s.lines[i].capacity() > kKeep) std::string().swap(s.lines[i]);
      if (s.answers[i].capacity() > kKeep) {
        std::string().swap(s.answers[i]);
        try {
          s.answers[i].reserve(kAnswerReserve);
        } catch (const std::bad_alloc&) {  // answer_batch_line tries again
        }
      }
    }
    if (s.flush) out_.flush();
  }

  LineReader& reader_;
  Output& out_;
  const relpos::detail::io::BatchOptions& options_;
  const std::string too_long_;
  std::vector<Slot> slots_;  // group seq is in slots_[seq % size]
  std::mutex read_mutex_;    // one reader at a time; held before mutex_, never after
  std::mutex mutex_;         // the slots' states, the counters and the output
  std::condition_variable free_;
  unsigned long next_read_ = 0, next_write_ = 0;  // groups taken; groups written
  long lines_read_ = 0;                           // under read_mutex_
  int read_error_ = 0;                            // under read_mutex_
  bool stop_ = false;
};

}  // namespace

int run_batch(Args& args) {
  std::optional<std::string> file;
  relpos::detail::io::BatchOptions options;
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
    } else if (take_margin(args, options.margin_bits)) {  // --margin, --margin-bits B
    } else if (args.value("--max-bits", v)) {
      options.size_limit.max_bits = parse_max_bits(v);
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
  BatchPipeline pipeline(reader, out, options, pool.threads(),
                         relpos::detail::io::too_long_message(options.max_line_bytes));
  pool.run_on_each([&](unsigned) { pipeline.work(); });
  if (out.failed()) return out.report_failure();
  if (pipeline.read_error() != 0) {
    out.flush();
    std::cerr << "relpos: error reading '" << name << "': " << std::strerror(pipeline.read_error()) << "\n";
    return kExitIo;
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
  const bool known = command == "classify" || command == "batch" || command == "scene" || command == "motion" ||
                     command == "verify" || command == "cases" || command == "judge";
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
    if (command == "cases") return run_cases(args);
    if (command == "judge") return run_judge(args);
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
