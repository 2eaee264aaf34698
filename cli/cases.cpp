// relpos cases FAMILY... [--n N] [--eps LIST] [--seed S] [--form exact|double|matrix] [--threads N]:
// the constructed pairs of src/oracle/ as JSON Lines (doc/oracle.md; doc/cli.md, "relpos cases").
#include "oracle/cases.hpp"

#include <iostream>
#include <string>
#include <thread>

#include "commands.hpp"
#include "common.hpp"
#include "relpos/error.hpp"

namespace relpos_cli {

void print_cases_help(std::ostream& os) {
  os << "Usage: relpos cases FAMILY... [--n N] [--eps LIST] [--seed S] [--form exact|double|matrix]\n"
        "                    [--threads N]\n"
        "       relpos cases --list\n"
        "\n"
        "Write hard pairs whose position is known by construction (not by trusting relpos), as JSON\n"
        "Lines that `relpos batch` reads and `relpos judge` judges (doc/oracle.md). Each line holds the\n"
        "exact pair (\"ellipsoid\": centre, axes, rotation; \"paraboloid\": vertex, a, b, rotation) and\n"
        "\"meta\": family, eps, side, the position by construction, relpos's position for the doubles of\n"
        "the parameters (double_position) and for the matrices a float code computes from them\n"
        "(matrix_position, or null and matrix_error), the margin s*, and those doubles and matrices.\n"
        "The same seed gives the same lines; a case does not change with --n or the other families.\n"
        "\n"
        "Families (`all` for every one; --list describes them):\n"
        "  ";
  for (const auto& f : relpos::detail::oracle::families()) os << f.name << ' ';
  os << "\n\n"
        "Options:\n"
        "  --n N          cases per family and eps (default 100)\n"
        "  --eps LIST     relative distances, exact numbers in [0, 1), comma-separated (default\n"
        "                 "
     << relpos::detail::oracle::kDefaultEps
     << "): the ellipsoid scaled by 1 +- eps\n"
        "                 about its centre touches the paraboloid; 0 gives the exact tangencies\n"
        "  --seed S       the random seed (default 1)\n"
        "  --form F       what \"ellipsoid\" and \"paraboloid\" hold: exact (default: the exact parameters,\n"
        "                 as strings), double (their nearest doubles, for `relpos batch --numbers double`)\n"
        "                 or matrix (the float code's matrices, upper triangles, as doubles)\n"
        "  --threads N    threads for the labels (default: all cores)\n"
        "  --list         the families, one line each\n"
        "  -h, --help     this help\n"
        "\n"
        "Example:\n"
        "  relpos cases offaxis special tiny --n 50 --eps 1e-3,1e-9,0 > cases.jsonl\n"
        "  relpos batch cases.jsonl | relpos judge cases.jsonl -\n";
}

int run_cases(Args& args) {
  relpos::detail::oracle::CaseOptions options;
  relpos::detail::oracle::Form form = relpos::detail::oracle::Form::Exact;
  bool list = false;
  while (!args.done()) {
    std::string v;
    if (args.help()) {
      print_cases_help(std::cout);
      return finish_cout();
    } else if (args.flag("--list")) {
      list = true;
    } else if (args.value("--n", v)) {
      options.n = parse_count(v, "--n", 0, 10000000);
    } else if (args.value("--eps", v)) {
      options.eps.clear();
      std::string item;
      for (char c : v + ",") {
        if (c != ',') {
          item += c;
          continue;
        }
        if (item.empty()) throw UsageError{"--eps: an empty item in '" + v + "'"};
        options.eps.push_back(item);
        item.clear();
      }
    } else if (args.value("--seed", v)) {
      options.seed = parse_count(v, "--seed", 0, ~0ull);
    } else if (args.value("--form", v)) {
      if (v != "exact" && v != "double" && v != "matrix")
        throw UsageError{"--form must be exact, double or matrix, got '" + v + "'"};
      form = v == "exact"
                 ? relpos::detail::oracle::Form::Exact
                 : (v == "double" ? relpos::detail::oracle::Form::Double : relpos::detail::oracle::Form::Matrix);
    } else if (args.value("--threads", v)) {
      options.threads = static_cast<unsigned>(parse_count(v, "--threads", 1, 1024));
    } else if (args.peek().rfind("-", 0) == 0) {
      args.unexpected();
    } else {
      options.families.push_back(args.next());
    }
  }
  if (list) {
    if (!options.families.empty()) throw UsageError{"--list takes no family"};
    for (const auto& f : relpos::detail::oracle::families())
      std::cout << f.name << std::string(11 - std::string(f.name).size(), ' ') << f.description << "\n";
    return finish_cout();
  }
  if (options.families.empty()) throw UsageError{"name at least one family (or all)"};
  const std::vector<relpos::detail::oracle::Case> cases = relpos::detail::oracle::make_cases(options);
  Output out;
  for (const auto& c : cases) {
    out.write(relpos::detail::oracle::case_line(c, form));
    out.write("\n");
  }
  return out.flush() ? kExitOk : out.report_failure();
}

}  // namespace relpos_cli
