// relpos scene: one paraboloid, or any real quadric, against many ellipsoids, on all cores (doc/cli.md,
// "relpos scene").
//
//   relpos scene (--paraboloid Q | --standard-paraboloid A,B | --quadric Q) [FILE|-] [--format jsonl|csv]
//                [--threads N] [--summary-only] [--no-progress]
//   relpos scene --generate N [--seed S] [--standard-paraboloid A,B]
//
// The input is read in blocks; each block is parsed and classified on all threads
// (relpos::Scene, or relpos::classify_scene for a general quadric), and its answers are written in
// input order. Exit codes as in main.cpp.
#include "relpos/scene.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "algebra/pair_size.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "decide/stages.hpp"
#include "general/decision.hpp"
#include "io/answer_json.hpp"
#include "io/batch.hpp"
#include "io/general_io.hpp"
#include "io/json_tree.hpp"
#include "relpos/error.hpp"
#include "relpos/general_scene.hpp"
#include "relpos/io.hpp"
#include "scene/demo.hpp"
#include "scene/scene_pool.hpp"

namespace relpos_cli {
namespace {

using relpos::detail::io::Json;

constexpr std::size_t kBlockLines = std::size_t(1) << 12;

}  // namespace

void print_scene_help(std::ostream& os) {
  os << "Usage: relpos scene (--paraboloid Q | --standard-paraboloid A,B | --quadric Q) [FILE|-]\n"
        "                    [--format jsonl|csv] [--threads N] [--summary-only] [--no-progress]\n"
        "       relpos scene --generate N [--seed S] [--standard-paraboloid A,B]\n"
        "\n"
        "Classify many ellipsoids against one paraboloid, on all cores. Every body gets exactly the\n"
        "answer of `relpos classify`; bodies certified strictly inside or outside are settled by a\n"
        "cheap interval test, the others by the full exact classifier.\n"
        "\n"
        "Input (FILE, or standard input when FILE is '-' or absent):\n"
        "  jsonl  one body per line: {\"id\": ANY, \"ellipsoid\": Q, \"comment\": ANY} (\"id\", \"comment\"\n"
        "         optional; Q as for `relpos classify --help`). Blank lines are answered with an error.\n"
        "  csv    one body per line: cx,cy,cz,r (a sphere) or the 10 coefficients A..J of\n"
        "         A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J, either optionally\n"
        "         preceded by an id field; exact numbers (\"1/3\", \"0.1\", \"2e-5\"). Lines starting with '#'\n"
        "         and blank lines are skipped.\n"
        "  --format defaults to csv for a FILE ending in .csv, else jsonl.\n"
        "\n"
        "Output: one JSON line per body, in input order, on standard output:\n"
        "  {\"id\": ..., \"position\": \"I|TI|C|TE|E\", \"contact\": true|false, \"stage\": ...}\n"
        "or {\"id\": ..., \"line\": N, \"error\": \"...\"} for a line that cannot be read (the scene goes on).\n"
        "The id is the input id, or the 1-based line number. At the end one JSON line on standard error:\n"
        "  {\"summary\": {\"bodies\", \"errors\", \"positions\", \"stages\", \"threads\", \"seconds\",\n"
        "               \"bodies_per_second\"}}\n"
        "A progress bar is drawn on standard error while it is a terminal.\n"
        "\n"
        "Options:\n"
        "  --paraboloid Q             the paraboloid as inline JSON (see `relpos classify --help`)\n"
        "  --standard-paraboloid A,B  x^2/A^2 + y^2/B^2 = z\n"
        "  --quadric Q                any real quadric in place of the paraboloid (doc/quadrics.md; Q as\n"
        "                             for `relpos classify --quadric`): positions I, TI, C, TE, E, and O,\n"
        "                             TO, EQ when Q is an ellipsoid; stages filter and exact\n"
        "  --format jsonl|csv         input format\n"
        "  --threads N                worker threads (default: all cores)\n"
        "  --summary-only             print only the summary (on standard error)\n"
        "  --no-progress              no progress bar\n"
        "  --max-line-bytes N         longest input line (default 64 MiB); longer lines are errors\n"
        "  --max-bits N               the pair size limit (default 4096, at least 4096): entries of each\n"
        "                             matrix's primitive integer form (doc/cli.md, Limits)\n"
        "  --generate N               write a demo scene of N bodies as CSV to standard output instead:\n"
        "                             particles in the container x^2/A^2 + y^2/B^2 <= z (default A,B =\n"
        "                             1,2), see doc/performance.md\n"
        "  --seed S                   seed of --generate (default 1)\n"
        "  -h, --help                 this help\n"
        "\n"
        "Example:\n"
        "  relpos scene --generate 100000 --seed 7 > scene.csv\n"
        "  relpos scene --standard-paraboloid 1,2 scene.csv > answers.jsonl\n"
        "\n"
        "Lines are read as by `relpos batch` (the same errors, limits and id echo).\n"
        "Exit codes: 0 success (every body answered, error lines included), 1 the paraboloid (or the\n"
        "quadric) cannot be read, 2 usage error, 3 I/O error, 4 internal error.\n";
}

namespace {

// ------------------------------------------------------------------------------------------------
// Small helpers

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts(1);
  for (char ch : text) {
    if (ch == ',')
      parts.emplace_back();
    else
      parts.back() += ch;
  }
  for (auto& p : parts) p = trim(p);
  return parts;
}

// ------------------------------------------------------------------------------------------------
// Reading bodies

enum class Format { Jsonl, Csv };

/// The scene's fixed body: the paraboloid, or a general quadric (--quadric).
struct FixedBody {
  std::optional<relpos::Paraboloid> paraboloid;
  std::optional<relpos::Quadric> quadric;
  std::optional<relpos::detail::io::GeneralPairSize> quadric_size;  ///< the quadric's size, computed once
  /// The pair size limit of `relpos batch` for a body against it.
  void check_size(const relpos::Ellipsoid& e, const relpos::SizeLimit& limit) const {
    if (quadric)
      quadric_size->check(e);
    else
      relpos::detail::check_normalized_pair_size(e, *paraboloid, limit);
  }
};

/// One input line, parsed.
struct Parsed {
  bool skip = false;  ///< CSV comment or blank line: no output
  long line = 0;
  std::string id;    ///< JSON text of the id
  std::string meta;  ///< JSON text of the "meta" member, echoed at the end of the answer (or empty)
  std::optional<relpos::Ellipsoid> body;
  std::string error;
};

void parse_csv(std::string_view raw, const relpos::detail::io::BatchOptions& options, const FixedBody& fixed,
               Parsed& out) {
  const std::string line = trim(std::string(relpos::detail::io::normalize_line(raw, out.line, options.max_line_bytes)));
  if (line.empty() || line[0] == '#') {
    out.skip = true;
    return;
  }
  std::vector<std::string> f = split_commas(line);
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f[i].empty())
      throw relpos::InputError("field " + std::to_string(i + 1) + " of " + std::to_string(f.size()) + " is empty" +
                               (i + 1 == f.size() ? " (a trailing separator?)" : ""));
  if (f.size() == 5 || f.size() == 11) {
    out.id = relpos::detail::io::dump_json(Json(f.front()));
    f.erase(f.begin());
  }
  if (f.size() != 4 && f.size() != 10)
    throw relpos::InputError("expected 4 numbers (cx,cy,cz,r) or 10 coefficients, optionally preceded by an id; got " +
                             std::to_string(f.size()) + " fields");
  static const char* const kSphere[] = {"cx", "cy", "cz", "r"};
  static const char* const kCoef[] = {"A", "B", "C", "D", "E", "F", "G", "H", "I", "J"};
  std::vector<relpos::Rational> x;
  for (std::size_t i = 0; i < f.size(); ++i) {
    try {
      x.push_back(relpos::parse_rational(f[i]));
    } catch (const relpos::InputError& e) {
      throw relpos::InputError(std::string("field ") + (f.size() == 4 ? kSphere[i] : kCoef[i]) + ": " + e.what());
    }
  }
  try {
    if (x.size() == 4) {
      out.body = relpos::Ellipsoid::sphere({x[0], x[1], x[2]}, x[3]);
    } else {
      relpos::Coefficients10 c;
      std::copy(x.begin(), x.end(), c.begin());
      out.body = relpos::Ellipsoid::from_coefficients(c);
    }
  } catch (const relpos::InputError& e) {
    throw relpos::InputError(std::string("ellipsoid: ") + e.what());
  }
  fixed.check_size(*out.body, options.size_limit);  // the limit of `relpos batch`
}

/// Parse a line; never throws (errors land in out.error). JSON Lines go through the reader of
/// `relpos batch` (relpos::detail::io::read_batch_line), so both commands answer a line alike.
void parse_line(const std::string& line, Format format, const relpos::detail::io::BatchOptions& options,
                const FixedBody& fixed, Parsed& out) {
  out.id = std::to_string(out.line);
  try {
    if (format == Format::Jsonl) {
      relpos::detail::io::BatchLine in;
      try {
        if (fixed.quadric)
          relpos::detail::io::read_batch_line(line, out.line, options, *fixed.quadric_size, in);
        else
          relpos::detail::io::read_batch_line(line, out.line, options, &*fixed.paraboloid, in);
      } catch (...) {
        out.id = std::move(in.id);
        out.meta = std::move(in.meta);
        throw;
      }
      out.id = std::move(in.id);
      out.meta = std::move(in.meta);
      out.body = std::move(in.ellipsoid);
    } else {
      parse_csv(line, options, fixed, out);
    }
  } catch (const relpos::InputError& e) {
    out.error = e.what();
  } catch (const std::bad_alloc&) {
    out.error = "out of memory while reading this line";
  } catch (const std::exception& e) {
    out.error = std::string("internal error: ") + e.what();
  }
  if (!out.error.empty()) out.body.reset();
}

// ------------------------------------------------------------------------------------------------
// Progress bar (stderr, only when it is a terminal)

/// Seconds as m:ss (h:mm:ss from an hour on).
std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

class Progress {
 public:
  Progress(bool enabled, std::size_t total) : enabled_(enabled), total_(total) {
    if (enabled_) ticker_ = std::thread([this] { run(); });
  }
  ~Progress() { finish(); }
  /// Two units per input line: one when it is read, one when it is answered.
  std::atomic<std::size_t>& counter() { return done_; }
  void finish() {
    if (!enabled_) return;
    {
      std::lock_guard<std::mutex> lock(m_);
      stop_ = true;
    }
    cv_.notify_all();
    if (ticker_.joinable()) ticker_.join();
    std::fprintf(stderr, "\r\033[K");  // erase the bar
    std::fflush(stderr);
    enabled_ = false;
  }

 private:
  void run() {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(m_);
    while (!cv_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stop_; })) {
      const std::size_t done = done_.load(std::memory_order_relaxed) / 2;  // two units per line
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double rate = secs > 0 ? done / secs : 0;
      if (total_ > 0) {
        const double frac = std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
        const std::size_t shown = std::min(done, total_);
        const int width = 30, fill = static_cast<int>(frac * width);
        const std::string eta = rate > 0 ? ", ETA " + clock_text((total_ - shown) / rate) : std::string();
        std::fprintf(stderr, "\r[%s%s] %3d%% %zu/%zu lines, %.3g lines/s, %s elapsed%s\033[K",
                     std::string(fill, '#').c_str(), std::string(width - fill, '.').c_str(),
                     static_cast<int>(frac * 100), shown, total_, rate, clock_text(secs).c_str(), eta.c_str());
      } else {
        std::fprintf(stderr, "\r%zu lines, %.3g lines/s, %s elapsed\033[K", done, rate, clock_text(secs).c_str());
      }
      std::fflush(stderr);
    }
  }
  bool enabled_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  std::thread ticker_;
  std::mutex m_;
  std::condition_variable cv_;
  bool stop_ = false;
};

/// Number of lines of a regular file (for the progress bar), 0 when unknown.
std::size_t count_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return 0;
  std::size_t n = 0;
  char buf[1 << 16];
  bool last_newline = true;
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i) n += buf[i] == '\n';
    last_newline = buf[got - 1] == '\n';
  }
  return n + (last_newline ? 0 : 1);
}

// ------------------------------------------------------------------------------------------------

std::string dump(const Json& j) { return relpos::detail::io::dump_json(j); }

/// A measured time or rate to 3 significant digits (more would be noise).
double significant(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return std::strtod(text, nullptr);
}

int run_generate(unsigned long long n, unsigned long long seed, const ShapeOptions& shapes) {
  relpos::Rational a(1), b(2);
  if (shapes.standard) {
    shapes.make_paraboloid();  // the same checks as a scene's paraboloid
    const auto ab = shapes.standard_axes();
    a = ab[0];
    b = ab[1];
  }
  relpos_cli::Output out;
  out.write("# relpos scene --generate " + std::to_string(n) + " --seed " + std::to_string(seed) +
            ": particles in the container x^2/a^2 + y^2/b^2 <= z, a = " + relpos::to_string(a) +
            ", b = " + relpos::to_string(b) + "\n# classify with: relpos scene --standard-paraboloid " +
            relpos::to_string(a) + "," + relpos::to_string(b) + " FILE.csv\n");
  relpos::DemoSceneGenerator gen(seed, a, b);
  std::string row;
  for (unsigned long long i = 0; i < n && !out.failed(); ++i) {
    const relpos::DemoBody d = gen.next();
    row.clear();
    if (d.kind == relpos::DemoBody::Kind::Sphere) {
      for (const auto& x : d.centre) row += relpos::to_string(x) + ",";
      row += relpos::to_string(d.radius);
    } else {
      for (std::size_t k = 0; k < d.coefficients.size(); ++k)
        row += (k ? "," : "") + relpos::to_string(d.coefficients[k]);
    }
    row += '\n';
    out.write(row);
  }
  return out.flush() ? kExitOk : out.report_failure();
}

}  // namespace

int run_scene(Args& args) {
  ShapeOptions shapes;
  std::optional<std::string> file, format_text, quadric_text;
  std::optional<unsigned long long> generate;
  unsigned long long seed = 1;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  bool summary_only = false, progress = true;
  relpos::detail::io::BatchOptions options_line;  // the line reader of `relpos batch`
  while (!args.done()) {
    std::string v;
    if (args.help()) {
      print_scene_help(std::cout);
      return relpos_cli::finish_cout();
    } else if (shapes.take(args)) {
    } else if (args.value("--quadric", v)) {
      quadric_text = v;
    } else if (args.value("--format", v)) {
      if (v != "jsonl" && v != "csv") throw UsageError{"--format must be jsonl or csv, got '" + v + "'"};
      format_text = v;
    } else if (args.value("--threads", v)) {
      threads = static_cast<unsigned>(parse_count(v, "--threads", 1, 1024));
    } else if (args.value("--generate", v)) {
      generate = parse_count(v, "--generate", 0, 1000000000000ULL);
    } else if (args.value("--seed", v)) {
      seed = parse_count(v, "--seed", 0, ~0ULL);
    } else if (args.value("--max-line-bytes", v)) {
      options_line.max_line_bytes = parse_count(v, "--max-line-bytes", 1, std::size_t(1) << 40);
    } else if (args.value("--max-bits", v)) {
      options_line.size_limit.max_bits = parse_max_bits(v);
    } else if (args.flag("--summary-only")) {
      summary_only = true;
    } else if (args.flag("--no-progress")) {
      progress = false;
    } else if (args.peek() != "-" && args.peek().rfind("-", 0) == 0) {
      args.unexpected();
    } else {
      if (file) throw UsageError{"more than one input file given"};
      file = args.next();
    }
  }
  if (generate) {
    if (shapes.paraboloid || shapes.ellipsoid || shapes.sphere || quadric_text || file || format_text || summary_only)
      throw UsageError{"--generate takes only --seed and --standard-paraboloid"};
    try {
      return run_generate(*generate, seed, shapes);
    } catch (const relpos::InputError& e) {
      std::cerr << "relpos: " << e.what() << "\n";
      return kExitInput;
    }
  }
  FixedBody fixed;
  if (quadric_text) {
    if (shapes.paraboloid || shapes.standard)
      throw UsageError{"give either --quadric or a paraboloid (--paraboloid, --standard-paraboloid), not both"};
    if (shapes.ellipsoid || shapes.sphere) throw UsageError{"this command takes no ellipsoid option"};
  } else {
    shapes.check(/*need_ellipsoid=*/false);
  }
  try {
    if (quadric_text) {
      fixed.quadric = relpos::detail::io::quadric_from_json(parse_inline(*quadric_text, "quadric"), "quadric");
      fixed.quadric_size.emplace(*fixed.quadric, options_line.size_limit);
    } else {
      fixed.paraboloid = shapes.make_paraboloid();
    }
  } catch (const relpos::InputError& e) {
    std::cerr << "relpos: " << e.what() << "\n";
    return kExitInput;
  }

  const bool from_file = file && *file != "-";
  Format format = Format::Jsonl;
  if (format_text)
    format = *format_text == "csv" ? Format::Csv : Format::Jsonl;
  else if (from_file && file->size() >= 4 && file->compare(file->size() - 4, 4, ".csv") == 0)
    format = Format::Csv;

  const int fd = relpos_cli::open_input(from_file ? *file : "-");
  if (fd < 0) return kExitIo;
  relpos_cli::LineReader reader(fd, options_line.max_line_bytes);
  relpos_cli::Output output;

  std::optional<relpos::Scene> scene;  // the paraboloid prepared once
  if (fixed.paraboloid) scene.emplace(*fixed.paraboloid);
  const bool show = progress && isatty(STDERR_FILENO);
  Progress bar(show, show && from_file ? count_lines(*file) : 0);

  const auto start = std::chrono::steady_clock::now();
  double classify_seconds = 0;
  relpos::SceneCounts counts;
  relpos::QuadricSceneResult::Counts general_counts;  // --quadric
  std::size_t errors = 0;
  unsigned used_threads = 1;
  long line_number = 0;
  std::vector<std::string> lines;
  std::vector<Parsed> parsed;
  std::string out;
  relpos_cli::WorkerPool parse_pool(threads);
  // Blocks of lines are parsed and classified on the threads and written in input order as soon as
  // they are answered; a block ends early when the input has nothing more ready.
  for (bool more = true; more;) {
    lines.clear();
    parsed.clear();
    lines.reserve(kBlockLines);
    parsed.reserve(kBlockLines);
    std::string line;
    while (lines.size() < kBlockLines && (lines.empty() || reader.ready())) {
      const relpos_cli::LineReader::Status status = reader.next(line);
      if (status == relpos_cli::LineReader::Status::End) {
        more = false;
        break;
      }
      if (status == relpos_cli::LineReader::Status::Error) {
        bar.finish();
        output.flush();
        std::cerr << "relpos: error reading '" << (from_file ? *file : std::string("<stdin>"))
                  << "': " << std::strerror(reader.error()) << "\n";
        return kExitIo;
      }
      Parsed x;
      x.line = line_number + static_cast<long>(lines.size()) + 1;
      x.id = std::to_string(x.line);
      if (status == relpos_cli::LineReader::Status::TooLong)
        x.error = relpos::detail::io::too_long_message(options_line.max_line_bytes);
      else if (status == relpos_cli::LineReader::Status::OutOfMemory)
        x.error = "out of memory while reading this line";
      parsed.push_back(std::move(x));
      lines.push_back(status == relpos_cli::LineReader::Status::Line ? std::move(line) : std::string());
    }
    if (lines.empty()) break;
    parse_pool.run(lines.size(), [&](std::size_t i) {
      if (parsed[i].error.empty()) parse_line(lines[i], format, options_line, fixed, parsed[i]);
      if (lines[i].capacity() > (std::size_t(1) << 20)) std::string().swap(lines[i]);  // read: not kept
      bar.counter().fetch_add(1, std::memory_order_relaxed);  // progress: one unit when read...
    });
    line_number += static_cast<long>(lines.size());

    std::vector<relpos::Ellipsoid> bodies;
    std::vector<std::size_t> where;
    bodies.reserve(parsed.size());
    where.reserve(parsed.size());
    for (std::size_t i = 0; i < parsed.size(); ++i) {
      if (parsed[i].body) {
        bodies.push_back(std::move(*parsed[i].body));
        where.push_back(i);
      } else if (!parsed[i].skip) {
        ++errors;
        bar.counter().fetch_add(1, std::memory_order_relaxed);
      } else {
        bar.counter().fetch_add(1, std::memory_order_relaxed);
      }
    }
    relpos::SceneOptions options;
    options.size_limit = options_line.size_limit;
    options.progress = &bar.counter();  // ...and one when answered
    // The answers of the block (relpos::SceneResult, or relpos::QuadricSceneResult for --quadric: the
    // same members), written in input order; false when the output failed.
    const auto answer = [&](const auto& result, auto& total) {
      classify_seconds += result.seconds;
      used_threads = std::max(used_threads, result.threads);
      total.merge(result.counts);
      if (summary_only) return true;
      using Verdict = typename std::decay_t<decltype(result.verdicts)>::value_type;
      std::vector<const Verdict*> verdict_of(parsed.size(), nullptr);
      for (std::size_t k = 0; k < where.size(); ++k) verdict_of[where[k]] = &result.verdicts[k];
      for (std::size_t i = 0; i < parsed.size(); ++i) {  // in pieces: a long id is not copied
        const Parsed& x = parsed[i];
        if (x.skip) continue;
        output.write("{\"id\":");
        output.write(x.id);
        out.clear();
        if (const Verdict* v = verdict_of[i]) {
          out += ",\"position\":\"";
          out += relpos::to_string(v->position);
          out += "\",\"contact\":";
          out += relpos::contact_of(v->position) != relpos::Contact::None ? "true" : "false";
          out += ",\"stage\":\"" + relpos::to_string(v->stage) + "\"}";
        } else {
          out += ",\"line\":" + std::to_string(x.line) + ",\"error\":" + dump(Json(x.error)) + "}";
        }
        relpos::detail::io::append_trailer(x.meta, false, out);
        out += '\n';
        output.write(out);
      }
      if (!more || !reader.ready()) output.flush();
      return !output.failed();
    };
    // A scene runs on the pool that parsed the block: one pool for the whole run, not one per block.
    const bool written =
        scene ? answer(relpos::detail::SceneAccess::classify(*scene, bodies.data(), bodies.size(), options, parse_pool),
                       counts)
              : answer(relpos::classify_scene(*fixed.quadric, bodies, options), general_counts);
    if (!written) {
      bar.finish();
      return output.report_failure();
    }
  }
  bar.finish();
  if (!output.flush()) return output.report_failure();
  const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Json positions, stages;
  if (fixed.quadric) {  // O, TO and EQ only when the quadric is an ellipsoid
    for (const relpos::QuadricPosition pos : relpos::detail::general::kAllQuadricPositions)
      if (static_cast<int>(pos) < static_cast<int>(relpos::QuadricPosition::O) ||
          fixed.quadric->type() == relpos::QuadricType::Ellipsoid)
        positions[relpos::to_string(pos)] = general_counts.count(pos);
    for (const relpos::QuadricStage s : {relpos::QuadricStage::Filter, relpos::QuadricStage::Exact})
      stages[relpos::to_string(s)] = general_counts.count(s);
  } else {
    for (const relpos::Position pos : relpos::kAllPositions) positions[relpos::to_string(pos)] = counts.count(pos);
    for (const relpos::Stage s : relpos::detail::kSceneStages) stages[relpos::to_string(s)] = counts.count(s);
  }
  const std::size_t classified = fixed.quadric ? general_counts.bodies : counts.bodies;
  Json summary;
  summary["bodies"] = classified;
  summary["errors"] = errors;
  summary["positions"] = positions;
  summary["stages"] = stages;
  summary["threads"] = used_threads;
  summary["seconds"] = Json{{"classify", significant(classify_seconds)}, {"total", significant(total_seconds)}};
  summary["bodies_per_second"] =
      Json{{"classify", significant(classify_seconds > 0 ? classified / classify_seconds : 0.0)},
           {"total", significant(total_seconds > 0 ? classified / total_seconds : 0.0)}};
  relpos_cli::Output err(STDERR_FILENO);  // the summary may be the only output: its loss is an error
  err.write(dump(Json{{"summary", summary}}) + "\n");
  return err.flush() ? kExitOk : err.report_failure();
}

}  // namespace relpos_cli
