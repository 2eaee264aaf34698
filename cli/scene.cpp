// relpos scene: one paraboloid against many ellipsoids, on all cores (doc/cli.md, "relpos scene").
//
//   relpos scene (--paraboloid Q | --standard-paraboloid A,B) [FILE|-] [--format jsonl|csv]
//                [--threads N] [--summary-only] [--no-progress]
//   relpos scene --generate N [--seed S] [--standard-paraboloid A,B]
//
// The input is read in blocks; each block is parsed and classified on all threads
// (relpos::Scene), and its answers are written in input order. Exit codes as in main.cpp.
#include "relpos/scene.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "relpos/error.hpp"
#include "relpos/io.hpp"
#include "scene/demo.hpp"

namespace {

using Json = nlohmann::ordered_json;

constexpr int kExitOk = 0;
constexpr int kExitInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitIo = 3;
constexpr std::size_t kBlockLines = std::size_t(1) << 16;

struct SceneUsageError {
  std::string message;
};

void print_scene_help(std::ostream& os) {
  os << "Usage: relpos scene (--paraboloid Q | --standard-paraboloid A,B) [FILE|-] [--format jsonl|csv]\n"
        "                    [--threads N] [--summary-only] [--no-progress]\n"
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
        "  {\"id\": ..., \"position\": \"I|TI|C|TE|E|unclassified\", \"contact\": true|false|null, \"stage\": ...}\n"
        "or {\"id\": ..., \"line\": N, \"error\": \"...\"} for a line that cannot be read (the scene goes on).\n"
        "The id is the input id, or the 1-based line number. At the end one JSON line on standard error:\n"
        "  {\"summary\": {\"bodies\", \"errors\", \"positions\", \"stages\", \"threads\", \"seconds\",\n"
        "               \"bodies_per_second\"}}\n"
        "A progress bar is drawn on standard error while it is a terminal.\n"
        "\n"
        "Options:\n"
        "  --paraboloid Q             the paraboloid as inline JSON (see `relpos classify --help`)\n"
        "  --standard-paraboloid A,B  x^2/A^2 + y^2/B^2 = z\n"
        "  --format jsonl|csv         input format\n"
        "  --threads N                worker threads (default: all cores)\n"
        "  --summary-only             print only the summary (on standard error)\n"
        "  --no-progress              no progress bar\n"
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
        "Exit codes: 0 success (every body answered, error lines included), 1 the paraboloid cannot be\n"
        "read, 2 usage error, 3 I/O error, 4 internal error.\n";
}

// ------------------------------------------------------------------------------------------------
// Small helpers (the same conventions as main.cpp)

/// "--name value" or "--name=value" at args[i]; advances i.
bool take(const std::vector<std::string>& args, std::size_t& i, const char* name, std::string* value) {
  const std::string& a = args[i];
  const std::string n(name);
  if (a == n) {
    if (value) {
      if (i + 1 >= args.size()) throw SceneUsageError{"option " + n + " needs a value"};
      *value = args[i + 1];
      i += 2;
    } else {
      ++i;
    }
    return true;
  }
  if (a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=') {
    if (!value) throw SceneUsageError{"option " + n + " takes no value"};
    *value = a.substr(n.size() + 1);
    ++i;
    return true;
  }
  return false;
}

unsigned long long parse_count(const std::string& text, const char* what, unsigned long long lo,
                               unsigned long long hi) {
  std::size_t used = 0;
  unsigned long long n = 0;
  try {
    if (!text.empty() && text[0] != '-') n = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || n < lo || n > hi)
    throw SceneUsageError{std::string(what) + " needs an integer from " + std::to_string(lo) + " to " +
                          std::to_string(hi) + ", got '" + text + "'"};
  return n;
}

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

relpos::Paraboloid standard_paraboloid(const std::string& text, relpos::Rational* a_out = nullptr,
                                       relpos::Rational* b_out = nullptr) {
  const auto parts = split_commas(text);
  if (parts.size() != 2)
    throw relpos::InputError("--standard-paraboloid: expected 2 comma-separated numbers, got " +
                             std::to_string(parts.size()) + " in '" + text + "'");
  relpos::Rational ab[2];
  for (std::size_t i = 0; i < 2; ++i) {
    try {
      ab[i] = relpos::parse_rational(parts[i]);
    } catch (const relpos::InputError& e) {
      throw relpos::InputError("--standard-paraboloid[" + std::to_string(i) + "]: " + e.what());
    }
  }
  if (a_out) *a_out = ab[0];
  if (b_out) *b_out = ab[1];
  try {
    const relpos::Rational zero(0);
    return relpos::Paraboloid::standard({zero, zero, zero}, ab[0], ab[1]);
  } catch (const relpos::InputError& e) {
    throw relpos::InputError(std::string("paraboloid: ") + e.what());
  }
}

// ------------------------------------------------------------------------------------------------
// Reading bodies

enum class Format { Jsonl, Csv };

/// One input line, parsed.
struct Parsed {
  bool skip = false;  ///< CSV comment or blank line: no output
  long line = 0;
  Json id;
  std::optional<relpos::Ellipsoid> body;
  std::string error;
};

bool is_blank(const std::string& s) {
  for (char ch : s)
    if (ch != ' ' && ch != '\t' && ch != '\r' && ch != '\n') return false;
  return true;
}

void parse_jsonl(const std::string& line, Parsed& out) {
  if (is_blank(line)) throw relpos::InputError("empty line");
  const Json doc = relpos::io::parse_json_exact(line);
  if (!doc.is_object()) throw relpos::InputError("expected a JSON object {\"id\": ..., \"ellipsoid\": ...}");
  if (doc.contains("id")) {
    try {
      out.id = Json::parse(line)["id"];  // echo the id as the JSON value it was
    } catch (const nlohmann::json::exception&) {
      out.id = doc["id"];  // a number beyond double range somewhere: floats stay as text
    }
  }
  for (const auto& item : doc.items()) {
    const std::string& k = item.key();
    if (k != "id" && k != "ellipsoid" && k != "comment")
      throw relpos::InputError("unknown key \"" + k.substr(0, 40) +
                               "\" (a scene line takes \"id\", \"ellipsoid\" and \"comment\")");
  }
  if (!doc.contains("ellipsoid")) throw relpos::InputError("ellipsoid: missing");
  out.body = relpos::io::ellipsoid_from_json(doc["ellipsoid"], "ellipsoid");
}

void parse_csv(const std::string& raw, Parsed& out) {
  const std::string line = trim(raw);
  if (line.empty() || line[0] == '#') {
    out.skip = true;
    return;
  }
  std::vector<std::string> f = split_commas(line);
  if (f.size() == 5 || f.size() == 11) {
    out.id = f.front();
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
}

/// Parse a line; never throws (errors land in out.error).
void parse_line(const std::string& line, Format format, Parsed& out) {
  try {
    if (format == Format::Jsonl)
      parse_jsonl(line, out);
    else
      parse_csv(line, out);
  } catch (const relpos::InputError& e) {
    out.error = e.what();
  } catch (const std::bad_alloc&) {
    out.error = "out of memory while reading this line";
  } catch (const std::exception& e) {
    out.error = std::string("internal error: ") + e.what();
  }
  if (!out.error.empty()) out.body.reset();
}

/// Run f(i) for i in [0, n) on `threads` threads (static split; parsing costs about the same per line).
template <class F>
void parallel_for(std::size_t n, unsigned threads, F f) {
  threads = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, n / 64 + 1)));
  std::vector<std::thread> pool;
  auto part = [&](unsigned w) {
    for (std::size_t i = n * w / threads; i < n * (w + 1) / threads; ++i) f(i);
  };
  for (unsigned w = 1; w < threads; ++w) pool.emplace_back(part, w);
  part(0);
  for (auto& t : pool) t.join();
}

// ------------------------------------------------------------------------------------------------
// Progress bar (stderr, only when it is a terminal)

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
        std::fprintf(stderr, "\r[%s%s] %3d%% %zu/%zu lines, %.3g lines/s\033[K", std::string(fill, '#').c_str(),
                     std::string(width - fill, '.').c_str(), static_cast<int>(frac * 100), shown, total_, rate);
      } else {
        std::fprintf(stderr, "\r%zu lines, %.3g lines/s\033[K", done, rate);
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

const char* position_text(relpos::Position p) {
  switch (p) {
    case relpos::Position::I:
      return "I";
    case relpos::Position::TI:
      return "TI";
    case relpos::Position::C:
      return "C";
    case relpos::Position::TE:
      return "TE";
    case relpos::Position::E:
      return "E";
    case relpos::Position::Unclassified:
      return "unclassified";
  }
  return "unclassified";
}

std::string dump(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

int run_generate(unsigned long long n, unsigned long long seed, const std::optional<std::string>& standard) {
  relpos::Rational a(1), b(2);
  if (standard) standard_paraboloid(*standard, &a, &b);
  std::cout << "# relpos scene --generate " << n << " --seed " << seed
            << ": particles in the container x^2/a^2 + y^2/b^2 <= z, a = " << relpos::to_string(a)
            << ", b = " << relpos::to_string(b) << "\n# classify with: relpos scene --standard-paraboloid "
            << relpos::to_string(a) << "," << relpos::to_string(b) << " FILE.csv\n";
  relpos::DemoSceneGenerator gen(seed, a, b);
  std::string row;
  for (unsigned long long i = 0; i < n; ++i) {
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
    std::cout << row;
    if (!std::cout) {
      std::cerr << "relpos: cannot write the output\n";
      return kExitIo;
    }
  }
  std::cout.flush();
  return std::cout ? kExitOk : kExitIo;
}

int run_scene(const std::vector<std::string>& args) {
  std::optional<std::string> paraboloid, standard, file, format_text;
  std::optional<unsigned long long> generate;
  unsigned long long seed = 1;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  bool summary_only = false, progress = true;
  for (std::size_t i = 0; i < args.size();) {
    std::string v;
    if (take(args, i, "--help", nullptr) || take(args, i, "-h", nullptr)) {
      print_scene_help(std::cout);
      return kExitOk;
    } else if (take(args, i, "--paraboloid", &v)) {
      if (paraboloid) throw SceneUsageError{"option --paraboloid given twice"};
      paraboloid = v;
    } else if (take(args, i, "--standard-paraboloid", &v)) {
      if (standard) throw SceneUsageError{"option --standard-paraboloid given twice"};
      standard = v;
    } else if (take(args, i, "--format", &v)) {
      if (v != "jsonl" && v != "csv") throw SceneUsageError{"--format must be jsonl or csv, got '" + v + "'"};
      format_text = v;
    } else if (take(args, i, "--threads", &v)) {
      threads = static_cast<unsigned>(parse_count(v, "--threads", 1, 1024));
    } else if (take(args, i, "--generate", &v)) {
      generate = parse_count(v, "--generate", 0, 1000000000000ULL);
    } else if (take(args, i, "--seed", &v)) {
      seed = parse_count(v, "--seed", 0, ~0ULL);
    } else if (take(args, i, "--summary-only", nullptr)) {
      summary_only = true;
    } else if (take(args, i, "--no-progress", nullptr)) {
      progress = false;
    } else if (args[i] != "-" && args[i].rfind("-", 0) == 0) {
      throw SceneUsageError{"unknown option '" + args[i] + "'"};
    } else {
      if (file) throw SceneUsageError{"more than one input file given"};
      file = args[i++];
    }
  }
  if (paraboloid && standard) throw SceneUsageError{"give either --paraboloid or --standard-paraboloid, not both"};

  if (generate) {
    if (paraboloid || file || format_text || summary_only)
      throw SceneUsageError{"--generate takes only --seed and --standard-paraboloid"};
    try {
      return run_generate(*generate, seed, standard);
    } catch (const relpos::InputError& e) {
      std::cerr << "relpos: " << e.what() << "\n";
      return kExitInput;
    }
  }
  if (!paraboloid && !standard)
    throw SceneUsageError{"missing the paraboloid (--paraboloid Q or --standard-paraboloid A,B)"};

  std::optional<relpos::Paraboloid> p;
  try {
    if (paraboloid) {
      Json doc;
      try {
        doc = relpos::io::parse_json_exact(*paraboloid);
      } catch (const relpos::InputError& e) {
        throw relpos::InputError(std::string("paraboloid: ") + e.what());
      }
      p = relpos::io::paraboloid_from_json(doc, "paraboloid");
    } else {
      p = standard_paraboloid(*standard);
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

  std::ifstream in_file;
  std::istream* in = &std::cin;
  if (from_file) {
    in_file.open(*file, std::ios::binary);
    if (!in_file) {
      std::cerr << "relpos: cannot open '" << *file << "': " << std::strerror(errno) << "\n";
      return kExitIo;
    }
    in = &in_file;
  }

  const relpos::Scene scene(*p);
  const bool show = progress && isatty(STDERR_FILENO);
  Progress bar(show, show && from_file ? count_lines(*file) : 0);

  const auto start = std::chrono::steady_clock::now();
  double classify_seconds = 0;
  relpos::SceneCounts counts;
  std::size_t errors = 0;
  unsigned used_threads = 1;
  long line_number = 0;
  std::vector<std::string> lines;
  std::vector<Parsed> parsed;
  std::string out;
  for (bool more = true; more;) {
    lines.clear();
    std::string line;
    while (lines.size() < kBlockLines && (more = static_cast<bool>(std::getline(*in, line)))) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(std::move(line));
    }
    if (lines.empty()) break;
    parsed.assign(lines.size(), Parsed{});
    parallel_for(lines.size(), threads, [&](std::size_t i) {
      parsed[i].line = line_number + static_cast<long>(i) + 1;
      parse_line(lines[i], format, parsed[i]);
      if (parsed[i].id.is_null()) parsed[i].id = parsed[i].line;
      bar.counter().fetch_add(1, std::memory_order_relaxed);  // progress: one unit when read...
    });
    line_number += static_cast<long>(lines.size());

    std::vector<relpos::Ellipsoid> bodies;
    std::vector<std::size_t> where;
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
    options.threads = threads;
    options.progress = &bar.counter();  // ...and one when answered
    const relpos::SceneResult result = scene.classify(bodies, options);
    classify_seconds += result.seconds;
    used_threads = std::max(used_threads, result.threads);
    counts.merge(result.counts);

    if (!summary_only) {
      std::vector<const relpos::SceneVerdict*> verdict_of(parsed.size(), nullptr);
      for (std::size_t k = 0; k < where.size(); ++k) verdict_of[where[k]] = &result.verdicts[k];
      out.clear();
      for (std::size_t i = 0; i < parsed.size(); ++i) {
        const Parsed& x = parsed[i];
        if (x.skip) continue;
        out += "{\"id\":" + dump(x.id);
        if (const relpos::SceneVerdict* v = verdict_of[i]) {
          out += ",\"position\":\"";
          out += position_text(v->position);
          out += "\",\"contact\":";
          out += v->contact < 0 ? "null" : (v->contact ? "true" : "false");
          out += ",\"stage\":\"" + relpos::to_string(v->stage) + "\"}\n";
        } else {
          out += ",\"line\":" + std::to_string(x.line) + ",\"error\":" + dump(Json(x.error)) + "}\n";
        }
      }
      std::cout << out;
      std::cout.flush();
      if (!std::cout) {
        bar.finish();
        std::cerr << "relpos: cannot write the output\n";
        return kExitIo;
      }
    }
  }
  bar.finish();
  if (in->bad()) {
    std::cerr << "relpos: error reading '" << (from_file ? *file : std::string("<stdin>")) << "'\n";
    return kExitIo;
  }
  const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Json positions, stages;
  for (auto pos : {relpos::Position::I, relpos::Position::TI, relpos::Position::C, relpos::Position::TE,
                   relpos::Position::E, relpos::Position::Unclassified})
    positions[position_text(pos)] = counts.count(pos);
  for (const relpos::Stage s : relpos::kAllStages) stages[relpos::to_string(s)] = counts.count(s);
  Json summary;
  summary["bodies"] = counts.bodies;
  summary["errors"] = errors;
  summary["positions"] = positions;
  summary["stages"] = stages;
  summary["threads"] = used_threads;
  summary["seconds"] = Json{{"classify", classify_seconds}, {"total", total_seconds}};
  summary["bodies_per_second"] = Json{{"classify", classify_seconds > 0 ? counts.bodies / classify_seconds : 0.0},
                                      {"total", total_seconds > 0 ? counts.bodies / total_seconds : 0.0}};
  std::cerr << dump(Json{{"summary", summary}}) << "\n";
  return kExitOk;
}

}  // namespace

/// Entry point of `relpos scene` (hooked into cli/main.cpp's dispatch). Handles its own usage errors.
int run_scene_command(const std::vector<std::string>& args) {
  try {
    return run_scene(args);
  } catch (const SceneUsageError& u) {
    std::cerr << "relpos: " << u.message << "\nTry 'relpos --help' or 'relpos scene --help'.\n";
    return kExitUsage;
  }
}
