// `relpos judge` and relpos.testing.judge (doc/oracle.md, "Judging"): any implementation's answers,
// JSON Lines {"id": ..., "position": ...} (other members ignored), against a file of cases (the
// lines of `relpos cases`, or any `relpos batch` input): error rates by group, the confusion matrix,
// undecided and missing answers, answers that match no case, a reproduction command for each miss,
// the float baselines on the same cases, and the curves of the chart (chart.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relpos/position.hpp"

namespace relpos::detail::oracle {

/// Which pair an answer is judged against (doc/oracle.md, "The three truths").
enum class Truth {
  Exact,   ///< the exact pair: meta.position (the construction), else relpos on the line read exactly
  Double,  ///< the doubles of the parameters: meta.double_position, else relpos on the line read as doubles
  Matrix,  ///< the float code's matrices: meta.matrix_position (null: no truth for that case)
};

struct JudgeOptions {
  Truth truth = Truth::Exact;
  std::optional<Rational> tolerance;             ///< tau: excuse answers within the margin (tolerance.hpp)
  std::vector<std::string> by{"family", "eps"};  ///< meta members that make the groups
  bool baselines = true;                         ///< run the float baselines on meta.double's matrices
};

/// What became of one case.
enum class Outcome { Right, Wrong, Excused, Undecided, Missing, NoTruth };

/// Tallies of a group of cases.
struct Counts {
  std::size_t cases = 0, right = 0, wrong = 0, excused = 0, undecided = 0, missing = 0, no_truth = 0;
  std::size_t errors() const { return wrong + undecided + missing; }  ///< excused answers are no errors
  std::size_t judged() const { return cases - no_truth; }
  double error_rate() const { return judged() ? static_cast<double>(errors()) / static_cast<double>(judged()) : 0; }
};

/// The float baselines (float_rules.hpp) on a group: wrong or undecided among the cases they ran on.
struct BaselineCounts {
  std::size_t cases = 0;
  std::array<std::size_t, 3> errors{};  ///< paper rule in double, in long double, minimal rule in double
  double error_rate(std::size_t k) const {
    return cases ? static_cast<double>(errors[k]) / static_cast<double>(cases) : 0;
  }
};
inline constexpr const char* kBaselineNames[3] = {"paper-double", "paper-long-double", "minimal-double"};
/// The columns of the confusion matrix: the answers.
inline constexpr const char* kAnswerColumns[7] = {"I", "TI", "C", "TE", "E", "undecided", "missing"};

struct Group {
  std::vector<std::string> key;  ///< the meta values of JudgeOptions::by, as text ("" when absent)
  Counts counts;
  BaselineCounts baselines;
};

/// One point of a curve of the chart: the cases at one eps.
struct CurvePoint {
  double eps = 0;
  std::string eps_text;
  Counts counts;
  BaselineCounts baselines;
};
struct Curve {
  std::string family;              ///< "" for all the families together
  std::vector<CurvePoint> points;  ///< in increasing eps
};

struct Miss {
  std::string id, family, eps;
  Position truth;
  std::string answer;     ///< the position, "undecided" or "missing"
  std::string reproduce;  ///< a `relpos classify` command giving the truth
};

struct JudgeReport {
  JudgeOptions options;
  std::vector<Group> groups;  ///< in the order of the cases' first appearance
  Group total;
  std::array<std::array<std::size_t, 7>, 5> confusion{};  ///< [truth][answer: I TI C TE E undecided missing]
  std::size_t malformed = 0, unknown = 0, duplicate = 0;  ///< answer lines matching no case once
  std::vector<Miss> misses;
  std::vector<Curve> curves;          ///< by eps: all families, then each family
  std::vector<std::string> warnings;  ///< case lines that could not be read, margins refused
};

/// "exact", "double" or "matrix".
const char* truth_name(Truth t);

/// Judges `answers` against `cases` (both JSON Lines text). Throws InputError when a case line is
/// not a JSON object with an id, or two cases share an id.
JudgeReport judge(std::string_view cases, std::string_view answers, const JudgeOptions& options);

/// The report as Markdown tables, CSV (one row per group, then the total) or JSON (report.cpp). At
/// most `max_misses` misses are listed in Markdown (all in JSON).
std::string report_markdown(const JudgeReport& r, std::size_t max_misses = 20);
std::string report_csv(const JudgeReport& r);
std::string report_json(const JudgeReport& r);

}  // namespace relpos::detail::oracle
