// relpos judge CASES ANSWERS [--truth exact|double|matrix] [--tolerance T] [--by KEYS]
//                            [--format md|csv|json] [--plot FILE.png] [--misses N] [--no-baselines]:
// an implementation's answers against the cases (src/oracle/judge.hpp; doc/oracle.md).
#include "oracle/judge.hpp"

#include <unistd.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "common.hpp"
#include "oracle/chart.hpp"
#include "relpos/error.hpp"

namespace relpos_cli {

void print_judge_help(std::ostream& os) {
  os << "Usage: relpos judge CASES ANSWERS [--truth exact|double|matrix] [--tolerance T] [--by KEYS]\n"
        "                    [--format md|csv|json] [--plot FILE.png] [--misses N] [--no-baselines]\n"
        "\n"
        "Judge any implementation's answers, JSON Lines {\"id\": ..., \"position\": \"I|TI|C|TE|E\"} (other\n"
        "members ignored; any other position, null or an \"error\" member is undecided), against CASES\n"
        "(the lines of `relpos cases`, or any `relpos batch` input). Either file may be '-' (standard\n"
        "input; ANSWERS is read first). Prints the error rate (wrong, undecided and missing answers) per\n"
        "group, the confusion matrix, the answers that match no case (malformed, unknown or duplicate\n"
        "id; the first answer of a case counts) and a `relpos classify` command for each miss, beside\n"
        "the error rates of relpos's float baselines on the cases' float matrices (doc/oracle.md).\n"
        "\n"
        "Options:\n"
        "  --truth T      exact (default): the exact pair (meta.position, else relpos on the line);\n"
        "                 double: the doubles of the parameters (meta.double_position, else relpos\n"
        "                 on the line read as doubles); matrix: the float code's matrices\n"
        "                 (meta.matrix_position; a case without one has no truth)\n"
        "  --tolerance T  excuse an answer that is the position of the pair with the ellipsoid scaled\n"
        "                 about its centre by a factor in [1 - T, 1 + T] (T an exact number >= 0),\n"
        "                 decided exactly from the case's or the answer's \"margin\"\n"
        "  --by KEYS      meta members that group the cases, comma-separated (default family,eps)\n"
        "  --format F     md (default), csv or json (json lists every miss and the chart's curves)\n"
        "  --plot FILE    write the chart of error rate against eps (log axis) as a PNG, with the\n"
        "                 float baselines' curves\n"
        "  --misses N     misses listed in md (default 20)\n"
        "  --no-baselines do not run the float baselines\n"
        "  -h, --help     this help\n"
        "\n"
        "Exit: 0 (whatever the error rate), 1 unreadable cases, 2 usage error, 3 I/O error.\n"
        "\n"
        "Example:\n"
        "  relpos cases all --n 50 > cases.jsonl\n"
        "  python3 my_adapter.py < cases.jsonl > answers.jsonl\n"
        "  relpos judge cases.jsonl answers.jsonl --tolerance 1e-9 --plot errors.png\n";
}

namespace {

/// The whole of FILE ("-": standard input); false after printing why not.
bool read_all(const std::string& file, std::string& out) {
  const int fd = open_input(file);
  if (fd < 0) return false;
  out.clear();
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      std::cerr << "relpos: error reading '" << file << "'\n";
      if (fd != 0) ::close(fd);
      return false;
    }
    if (n == 0) break;
    out.append(buffer, static_cast<std::size_t>(n));
  }
  if (fd != 0) ::close(fd);
  return true;
}

}  // namespace

int run_judge(Args& args) {
  std::vector<std::string> files;
  relpos::detail::oracle::JudgeOptions options;
  std::string format = "md", plot;
  std::size_t max_misses = 20;
  while (!args.done()) {
    std::string v;
    if (args.help()) {
      print_judge_help(std::cout);
      return finish_cout();
    } else if (args.value("--truth", v)) {
      if (v != "exact" && v != "double" && v != "matrix")
        throw UsageError{"--truth must be exact, double or matrix, got '" + v + "'"};
      options.truth = v == "exact" ? relpos::detail::oracle::Truth::Exact
                                   : (v == "double" ? relpos::detail::oracle::Truth::Double
                                                    : relpos::detail::oracle::Truth::Matrix);
    } else if (args.value("--tolerance", v)) {
      const relpos::Rational tau = exact_option(v, "--tolerance");
      if (tau < 0) throw UsageError{"--tolerance must be at least 0, got '" + v + "'"};
      options.tolerance = tau;
    } else if (args.value("--by", v)) {
      options.by.clear();
      std::stringstream in(v);
      for (std::string k; std::getline(in, k, ',');) {
        if (k.empty()) throw UsageError{"--by: an empty key in '" + v + "'"};
        options.by.push_back(k);
      }
      if (options.by.empty()) throw UsageError{"--by needs at least one key"};
    } else if (args.value("--format", v)) {
      if (v != "md" && v != "csv" && v != "json") throw UsageError{"--format must be md, csv or json, got '" + v + "'"};
      format = v;
    } else if (args.value("--plot", v)) {
      plot = v;
    } else if (args.value("--misses", v)) {
      max_misses = parse_count(v, "--misses", 0, 1000000000);
    } else if (args.flag("--no-baselines")) {
      options.baselines = false;
    } else if (args.peek() != "-" && args.peek().rfind("-", 0) == 0) {
      args.unexpected();
    } else {
      files.push_back(args.next());
    }
  }
  if (files.size() != 2) throw UsageError{"expected CASES and ANSWERS"};
  if (files[0] == "-" && files[1] == "-") throw UsageError{"CASES and ANSWERS cannot both be standard input"};
  std::string cases, answers;
  if (!read_all(files[1], answers) || !read_all(files[0], cases)) return kExitIo;
  const relpos::detail::oracle::JudgeReport report = relpos::detail::oracle::judge(cases, answers, options);
  if (!plot.empty()) {
    const std::string png = relpos::detail::oracle::chart_png(report);
    std::ofstream f(plot, std::ios::binary);
    f.write(png.data(), static_cast<std::streamsize>(png.size()));
    if (!f.flush()) {
      std::cerr << "relpos: cannot write '" << plot << "'\n";
      return kExitIo;
    }
  }
  if (format == "md")
    std::cout << relpos::detail::oracle::report_markdown(report, max_misses);
  else if (format == "csv")
    std::cout << relpos::detail::oracle::report_csv(report);
  else
    std::cout << relpos::detail::oracle::report_json(report);
  return finish_cout();
}

}  // namespace relpos_cli
