// judge.hpp: reading the cases and the answers, the truth of each case, the tallies and the reports.
#include "oracle/judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "algebra/centre.hpp"
#include "io/batch.hpp"
#include "io/quadric_json.hpp"
#include "oracle/float_matrices.hpp"
#include "oracle/float_rules.hpp"
#include "oracle/json_text.hpp"
#include "oracle/nearest.hpp"
#include "oracle/tolerance.hpp"
#include "relpos/classify.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::detail::oracle {

namespace {

std::optional<Position> position_from_text(const Json& j) {
  if (!j.is_string()) return std::nullopt;
  const std::string s = j.get<std::string>();
  for (const Position p : {Position::I, Position::TI, Position::C, Position::TE, Position::E})
    if (s == to_string(p)) return p;
  return std::nullopt;
}

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> out;
  for (std::size_t begin = 0; begin < text.size();) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    out.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return out;
}

bool blank(std::string_view line) { return line.find_first_not_of(" \t\r") == std::string_view::npos; }

const Json* member(const Json& j, const char* key) {
  if (!j.is_object()) return nullptr;
  const auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}
const Json* member(const Json* j, const char* key) { return j ? member(*j, key) : nullptr; }

/// A 4x4 array of JSON numbers as doubles.
std::optional<DoubleMatrix4> matrix_of(const Json* j) {
  if (!j || !j->is_array() || j->size() != 4) return std::nullopt;
  DoubleMatrix4 m;
  for (std::size_t i = 0; i < 4; ++i) {
    const Json& row = (*j)[i];
    if (!row.is_array() || row.size() != 4) return std::nullopt;
    for (std::size_t k = 0; k < 4; ++k) {
      if (!row[k].is_number()) return std::nullopt;
      m[4 * i + k] = row[k].get<double>();
    }
  }
  return m;
}

/// Every JSON number replaced by the exact text of its double ("p/q"): a pair a float code reads,
/// written so that `relpos classify` reads the same doubles.
Json exactified(const Json& j) {
  if (j.is_number_float()) return exact_text(j.get<double>());
  if (j.is_array() || j.is_object()) {
    Json out = j;
    for (auto& x : out) x = exactified(x);
    return out;
  }
  return j;
}

Json exact_matrix_json(const DoubleMatrix4& m) {
  Json out = Json::array();
  for (std::size_t i = 0; i < 4; ++i) {
    Json row = Json::array();
    for (std::size_t k = 0; k < 4; ++k) row.push_back(exact_text(m[4 * i + k]));
    out.push_back(row);
  }
  return out;
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct CaseLine {
  std::string_view text;
  long number = 0;
  Json json, meta;
  std::string id;  ///< the id's JSON text, as matched
};

struct Answer {
  std::optional<Position> position;  ///< nullopt: undecided
  Json margin;
};

/// The pair of a truth, as relpos reads it, with the members to reproduce it.
struct TruthPair {
  std::optional<Ellipsoid> e;
  std::optional<Paraboloid> p;
  Json ellipsoid, paraboloid;  ///< JSON forms for `relpos classify` (exact numbers)
};

TruthPair pair_of(const CaseLine& c, Truth truth) {
  TruthPair out;
  const Json* dbl = member(c.meta, "double");
  if (truth == Truth::Matrix) {
    const auto e = matrix_of(member(dbl, "E")), p = matrix_of(member(dbl, "P"));
    if (!e || !p) return out;
    out.ellipsoid = exact_matrix_json(upper_triangle(*e));
    out.paraboloid = exact_matrix_json(upper_triangle(*p));
    out.e = Ellipsoid::from_doubles(upper_triangle(*e));
    out.p = Paraboloid::from_doubles(upper_triangle(*p));
    return out;
  }
  if (truth == Truth::Double && member(dbl, "ellipsoid") && member(dbl, "paraboloid")) {
    out.ellipsoid = exactified(*member(dbl, "ellipsoid"));
    out.paraboloid = exactified(*member(dbl, "paraboloid"));
    out.e = detail::io::ellipsoid_from_tree(out.ellipsoid);
    out.p = detail::io::paraboloid_from_tree(out.paraboloid);
    return out;
  }
  detail::io::BatchOptions options;
  options.numbers_as_doubles = truth == Truth::Double;
  detail::io::BatchLine line;
  detail::io::read_batch_line(c.text, c.number, options, nullptr, line);
  out.e = std::move(line.ellipsoid);
  out.p = std::move(line.paraboloid);
  const Json* e = member(c.json, "ellipsoid");
  const Json* p = member(c.json, "paraboloid");
  out.ellipsoid = e ? (truth == Truth::Double ? exactified(*e) : *e) : Json();
  out.paraboloid = p ? (truth == Truth::Double ? exactified(*p) : *p) : Json();
  return out;
}

/// Where the ellipsoid's centre lies, exactly: the sign of the paraboloid's form at the centre.
CentreSide side_of(const Ellipsoid& e, const Paraboloid& p) {
  const std::optional<Vector3> c = detail::centre_of(e.matrix());
  if (!c) return CentreSide::On;  // not reached: an ellipsoid has a centre
  const Matrix4& m = p.matrix();
  const Rational x[4] = {(*c)[0], (*c)[1], (*c)[2], Rational(1)};
  Rational v(0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v += x[i] * m(i, j) * x[j];
  return v < 0 ? CentreSide::Inside : (v > 0 ? CentreSide::Outside : CentreSide::On);
}

std::string key_text(const Json* v) {
  if (!v) return "";
  return v->is_string() ? v->get<std::string>() : dump(*v);
}

void add(Counts& c, Outcome o) {
  ++c.cases;
  switch (o) {
    case Outcome::Right:
      ++c.right;
      break;
    case Outcome::Wrong:
      ++c.wrong;
      break;
    case Outcome::Excused:
      ++c.excused;
      break;
    case Outcome::Undecided:
      ++c.undecided;
      break;
    case Outcome::Missing:
      ++c.missing;
      break;
    case Outcome::NoTruth:
      ++c.no_truth;
      break;
  }
}

void add(BaselineCounts& b, const std::optional<std::array<bool, 3>>& wrong) {
  if (!wrong) return;
  ++b.cases;
  for (std::size_t k = 0; k < 3; ++k) b.errors[k] += (*wrong)[k];
}

/// The cases of a judge's file, by id.
struct Cases {
  std::vector<CaseLine> lines;
  std::map<std::string, std::size_t> index;
};

Cases read_cases(std::string_view text) {
  Cases out;
  long number = 0;
  for (const std::string_view line : lines_of(text)) {
    ++number;
    if (blank(line)) continue;
    CaseLine c;
    c.text = line;
    c.number = number;
    try {
      c.json = Json::parse(line);
    } catch (const nlohmann::json::exception&) {
      throw InputError("cases, line " + std::to_string(number) + ": not JSON");
    }
    if (!member(c.json, "id")) throw InputError("cases, line " + std::to_string(number) + ": no \"id\"");
    c.id = dump(c.json["id"]);
    if (const Json* m = member(c.json, "meta")) c.meta = *m;
    if (!out.index.emplace(c.id, out.lines.size()).second)
      throw InputError("cases, line " + std::to_string(number) + ": the id " + c.id + " is given twice");
    out.lines.push_back(std::move(c));
  }
  return out;
}

/// The first answer of each case (nullopt: none), counting the lines that match no case once.
std::vector<std::optional<Answer>> read_answers(std::string_view text, const Cases& cases, JudgeReport& r) {
  std::vector<std::optional<Answer>> answers(cases.lines.size());
  for (const std::string_view line : lines_of(text)) {
    if (blank(line)) continue;
    Json a;
    try {
      a = Json::parse(line);
    } catch (const nlohmann::json::exception&) {
      ++r.malformed;
      continue;
    }
    const Json* id = member(a, "id");
    if (!id) {
      ++r.malformed;
      continue;
    }
    const auto it = cases.index.find(dump(*id));
    if (it == cases.index.end()) {
      ++r.unknown;
    } else if (answers[it->second]) {
      ++r.duplicate;
    } else {
      Answer answer;
      if (!member(a, "error")) answer.position = position_from_text(a.value("position", Json()));
      if (const Json* m = member(a, "margin")) answer.margin = *m;
      answers[it->second] = std::move(answer);
    }
  }
  return answers;
}

const char* truth_key(Truth t) {
  return t == Truth::Exact ? "position" : (t == Truth::Double ? "double_position" : "matrix_position");
}
const char* margin_key(Truth t) {
  return t == Truth::Exact ? "margin" : (t == Truth::Double ? "double_margin" : "matrix_margin");
}

/// One case being judged: its line, its pair of the truth asked for (built when first needed).
struct Judged {
  const CaseLine& line;
  Truth truth_kind;
  std::optional<TruthPair> built;
  TruthPair& pair() {
    if (!built) built = pair_of(line, truth_kind);
    return *built;
  }
};

/// A miss, with a `relpos classify` command giving the pair of its truth.
Miss miss_of(Judged& c, Position truth, const std::string& answer) {
  Miss miss{c.line.json["id"].is_string() ? c.line.json["id"].get<std::string>() : c.line.id,
            key_text(member(c.line.meta, "family")),
            key_text(member(c.line.meta, "eps")),
            truth,
            answer,
            ""};
  try {
    TruthPair& p = c.pair();
    if (!p.ellipsoid.is_null() && !p.paraboloid.is_null())
      miss.reproduce = "relpos classify --ellipsoid " + shell_quoted(dump(p.ellipsoid)) + " --paraboloid " +
                       shell_quoted(dump(p.paraboloid));
  } catch (const InputError&) {
  }
  return miss;
}

/// The truth of a case: its meta member, else relpos on its pair; nullopt (and a warning) when none.
std::optional<Position> truth_of(Judged& c, JudgeReport& r) {
  try {
    if (const Json* t = member(c.line.meta, truth_key(c.truth_kind))) {
      const std::optional<Position> p = position_from_text(*t);
      if (!p && !t->is_null())
        r.warnings.push_back(c.line.id + ": meta." + truth_key(c.truth_kind) + " is not a position: " + dump(*t));
      return p;
    }
    TruthPair& p = c.pair();
    if (p.e && p.p) return decide_position(*p.e, *p.p).position;
  } catch (const InputError& err) {
    r.warnings.push_back(c.line.id + ": no " + truth_name(c.truth_kind) + " truth: " + err.what());
  }
  return std::nullopt;
}

/// Whether a wrong answer is excused within the tolerance (tolerance.hpp), by the answer's margin,
/// else the case line's, else its meta's.
bool excused(Judged& c, const Answer& a, Position truth, const Rational& tau, JudgeReport& r) {
  const Json* m = !a.margin.is_null() ? &a.margin : member(c.line.json, "margin");
  if (!m) m = member(c.line.meta, margin_key(c.truth_kind));
  if (!m) return false;
  try {
    const MarginValue margin = margin_from_json(*m);
    CentreSide side = truth == Position::I || truth == Position::TI ? CentreSide::Inside : CentreSide::Outside;
    if (truth == Position::C) side = side_of(*c.pair().e, *c.pair().p);
    return within_tolerance(*a.position, side, margin, tau);
  } catch (const InputError& err) {
    r.warnings.push_back(c.line.id + ": " + err.what());
    return false;
  }
}

/// Whether each float baseline is wrong (or undecided) on the case's float matrices, if it has them.
std::optional<std::array<bool, 3>> baselines_wrong(const CaseLine& c, Position truth) {
  const Json* dbl = member(c.meta, "double");
  const auto e = matrix_of(member(dbl, "E")), p = matrix_of(member(dbl, "P"));
  if (!e || !p) return std::nullopt;
  const std::optional<Position> b[3] = {paper_rule_double(*p, *e), paper_rule_long_double(*p, *e),
                                        minimal_rule_double(*p, *e)};
  return std::array<bool, 3>{b[0] != truth, b[1] != truth, b[2] != truth};
}

/// The curves of the chart: family ("" all) -> eps -> point, and the families in order.
struct Curves {
  std::map<std::string, std::map<double, CurvePoint>> points;
  std::vector<std::string> order{""};
  void add(const CaseLine& c, Outcome o, const std::optional<std::array<bool, 3>>& baselines) {
    const Json* eps = member(c.meta, "eps");
    if (!eps || !(eps->is_number() || eps->is_string())) return;
    double x = -1;
    try {
      x = eps->is_number() ? eps->get<double>() : nearest_double(parse_rational(eps->get<std::string>()));
    } catch (const InputError&) {
    }
    if (x < 0) return;
    const std::string family = key_text(member(c.meta, "family"));
    if (std::find(order.begin(), order.end(), family) == order.end()) order.push_back(family);
    for (const std::string& f : {std::string(), family}) {
      CurvePoint& point = points[f][x];
      point.eps = x;
      point.eps_text = key_text(eps);
      oracle::add(point.counts, o);
      oracle::add(point.baselines, baselines);
    }
  }
  std::vector<Curve> curves() {
    std::vector<Curve> out;
    for (const std::string& family : order) {
      if (!points.count(family)) continue;
      Curve curve{family, {}};
      for (auto& [eps, point] : points[family]) curve.points.push_back(point);
      out.push_back(std::move(curve));
    }
    return out;
  }
};

}  // namespace

const char* truth_name(Truth t) { return t == Truth::Exact ? "exact" : (t == Truth::Double ? "double" : "matrix"); }

JudgeReport judge(std::string_view cases_text, std::string_view answers_text, const JudgeOptions& options) {
  JudgeReport r;
  r.options = options;
  const Cases cases = read_cases(cases_text);
  const std::vector<std::optional<Answer>> answers = read_answers(answers_text, cases, r);
  std::map<std::vector<std::string>, std::size_t> group_of;
  Curves curves;
  for (std::size_t i = 0; i < cases.lines.size(); ++i) {
    Judged c{cases.lines[i], options.truth, std::nullopt};
    const std::optional<Position> truth = truth_of(c, r);
    const std::optional<Answer>& a = answers[i];
    Outcome outcome = !truth                   ? Outcome::NoTruth
                      : !a                     ? Outcome::Missing
                      : !a->position           ? Outcome::Undecided
                      : *a->position == *truth ? Outcome::Right
                                               : Outcome::Wrong;
    if (outcome == Outcome::Wrong && options.tolerance && excused(c, *a, *truth, *options.tolerance, r))
      outcome = Outcome::Excused;
    const auto baselines = options.baselines && truth ? baselines_wrong(c.line, *truth) : std::nullopt;
    std::vector<std::string> key;
    for (const std::string& k : options.by) key.push_back(key_text(member(c.line.meta, k.c_str())));
    const auto [it, fresh] = group_of.emplace(key, r.groups.size());
    if (fresh) r.groups.push_back(Group{key, {}, {}});
    for (Group* g : {&r.groups[it->second], &r.total}) {
      add(g->counts, outcome);
      add(g->baselines, baselines);
    }
    curves.add(c.line, outcome, baselines);
    if (!truth) continue;
    const std::size_t column = outcome == Outcome::Missing     ? 6
                               : outcome == Outcome::Undecided ? 5
                                                               : static_cast<std::size_t>(*a->position);
    ++r.confusion[static_cast<std::size_t>(*truth)][column];
    if (outcome == Outcome::Wrong || outcome == Outcome::Undecided || outcome == Outcome::Missing)
      r.misses.push_back(miss_of(c, *truth, column < 5 ? to_string(*a->position) : kAnswerColumns[column]));
  }
  r.total.key = {"all"};
  r.curves = curves.curves();
  return r;
}

}  // namespace relpos::detail::oracle
