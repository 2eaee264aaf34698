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
#include "oracle/float_matrices.hpp"
#include "oracle/float_rules.hpp"
#include "oracle/nearest.hpp"
#include "oracle/tolerance.hpp"
#include "relpos/classify.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::oracle {

namespace {

using Json = nlohmann::ordered_json;

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

Json matrix_json(const DoubleMatrix4& m) {
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

std::string dump(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

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
    out.ellipsoid = matrix_json(upper_triangle(*e));
    out.paraboloid = matrix_json(upper_triangle(*p));
    out.e = Ellipsoid::from_doubles(upper_triangle(*e));
    out.p = Paraboloid::from_doubles(upper_triangle(*p));
    return out;
  }
  if (truth == Truth::Double && member(dbl, "ellipsoid") && member(dbl, "paraboloid")) {
    out.ellipsoid = exactified(*member(dbl, "ellipsoid"));
    out.paraboloid = exactified(*member(dbl, "paraboloid"));
    out.e = io::ellipsoid_from_json(out.ellipsoid);
    out.p = io::paraboloid_from_json(out.paraboloid);
    return out;
  }
  io::BatchOptions options;
  options.numbers_as_doubles = truth == Truth::Double;
  io::BatchLine line;
  io::read_batch_line(c.text, c.number, options, nullptr, line);
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

const char* truth_name(Truth t) { return t == Truth::Exact ? "exact" : (t == Truth::Double ? "double" : "matrix"); }

std::string percent(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100 * x);
  return text;
}

}  // namespace

JudgeReport judge(std::string_view cases_text, std::string_view answers_text, const JudgeOptions& options) {
  JudgeReport r;
  r.options = options;
  // The cases.
  std::vector<CaseLine> cases;
  std::map<std::string, std::size_t> index;
  long number = 0;
  for (const std::string_view line : lines_of(cases_text)) {
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
    if (!index.emplace(c.id, cases.size()).second)
      throw InputError("cases, line " + std::to_string(number) + ": the id " + c.id + " is given twice");
    cases.push_back(std::move(c));
  }
  // The answers: the first answer of each case counts.
  std::vector<std::optional<Answer>> answers(cases.size());
  for (const std::string_view line : lines_of(answers_text)) {
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
    const auto it = index.find(dump(*id));
    if (it == index.end()) {
      ++r.unknown;
      continue;
    }
    if (answers[it->second]) {
      ++r.duplicate;
      continue;
    }
    Answer answer;
    if (!member(a, "error")) answer.position = position_from_text(a.value("position", Json()));
    if (const Json* m = member(a, "margin")) answer.margin = *m;
    answers[it->second] = std::move(answer);
  }
  // Each case.
  std::map<std::vector<std::string>, std::size_t> group_of;
  std::map<std::string, std::map<double, CurvePoint>> curves;  // family ("" all) -> eps -> point
  std::vector<std::string> family_order{""};
  const char* const margin_key =
      options.truth == Truth::Exact ? "margin" : (options.truth == Truth::Double ? "double_margin" : "matrix_margin");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseLine& c = cases[i];
    std::optional<Position> truth;
    std::optional<TruthPair> pair;  // built when needed
    auto the_pair = [&]() -> TruthPair& {
      if (!pair) pair = pair_of(c, options.truth);
      return *pair;
    };
    const char* const truth_key = options.truth == Truth::Exact
                                      ? "position"
                                      : (options.truth == Truth::Double ? "double_position" : "matrix_position");
    try {
      if (const Json* t = member(c.meta, truth_key)) {
        truth = position_from_text(*t);
        if (!truth && !t->is_null())
          r.warnings.push_back(c.id + ": meta." + truth_key + " is not a position: " + dump(*t));
      } else {
        TruthPair& p = the_pair();
        if (p.e && p.p) truth = decide_position(*p.e, *p.p).position;
      }
    } catch (const InputError& err) {
      r.warnings.push_back(c.id + ": no " + truth_name(options.truth) + " truth: " + err.what());
    }
    Outcome outcome;
    std::string answer_text = "missing";
    if (!truth) {
      outcome = Outcome::NoTruth;
    } else if (!answers[i]) {
      outcome = Outcome::Missing;
    } else if (!answers[i]->position) {
      outcome = Outcome::Undecided;
      answer_text = "undecided";
    } else {
      answer_text = to_string(*answers[i]->position);
      outcome = *answers[i]->position == *truth ? Outcome::Right : Outcome::Wrong;
      if (outcome == Outcome::Wrong && options.tolerance) {
        const Json* m = !answers[i]->margin.is_null() ? &answers[i]->margin : member(c.json, "margin");
        if (!m) m = member(c.meta, margin_key);
        if (m) {
          try {
            const Margin margin = margin_from_json(*m);
            CentreSide side =
                *truth == Position::I || *truth == Position::TI ? CentreSide::Inside : CentreSide::Outside;
            if (*truth == Position::C) {
              TruthPair& p = the_pair();
              side = side_of(*p.e, *p.p);
            }
            if (within_tolerance(*answers[i]->position, side, margin, *options.tolerance)) outcome = Outcome::Excused;
          } catch (const InputError& err) {
            r.warnings.push_back(c.id + ": " + err.what());
          }
        }
      }
    }
    // The baselines on the float code's matrices.
    std::optional<std::array<bool, 3>> baseline_wrong;
    if (options.baselines && truth) {
      const Json* dbl = member(c.meta, "double");
      const auto e = matrix_of(member(dbl, "E")), p = matrix_of(member(dbl, "P"));
      if (e && p) {
        const std::optional<Position> b[3] = {paper_rule_double(*p, *e), paper_rule_long_double(*p, *e),
                                              minimal_rule_double(*p, *e)};
        baseline_wrong = std::array<bool, 3>{b[0] != truth, b[1] != truth, b[2] != truth};
      }
    }
    // Tallies.
    std::vector<std::string> key;
    for (const std::string& k : options.by) key.push_back(key_text(member(c.meta, k.c_str())));
    auto [it, fresh] = group_of.emplace(key, r.groups.size());
    if (fresh) r.groups.push_back(Group{key, {}, {}});
    Group& g = r.groups[it->second];
    add(g.counts, outcome);
    add(g.baselines, baseline_wrong);
    add(r.total.counts, outcome);
    add(r.total.baselines, baseline_wrong);
    if (truth) {
      const std::size_t column = outcome == Outcome::Missing     ? 6
                                 : outcome == Outcome::Undecided ? 5
                                                                 : static_cast<std::size_t>(*answers[i]->position);
      ++r.confusion[static_cast<std::size_t>(*truth)][column];
    }
    if (const Json* eps = member(c.meta, "eps"); eps && (eps->is_number() || eps->is_string())) {
      double x = 0;
      try {
        x = eps->is_number() ? eps->get<double>() : nearest_double(parse_rational(eps->get<std::string>()));
      } catch (const InputError&) {
        x = -1;
      }
      if (x >= 0) {
        const std::string family = key_text(member(c.meta, "family"));
        if (std::find(family_order.begin(), family_order.end(), family) == family_order.end())
          family_order.push_back(family);
        for (const std::string& f : {std::string(), family}) {
          CurvePoint& point = curves[f][x];
          point.eps = x;
          point.eps_text = key_text(eps);
          add(point.counts, outcome);
          add(point.baselines, baseline_wrong);
        }
      }
    }
    if (truth && (outcome == Outcome::Wrong || outcome == Outcome::Undecided || outcome == Outcome::Missing)) {
      Miss miss{c.json["id"].is_string() ? c.json["id"].get<std::string>() : c.id,
                key_text(member(c.meta, "family")),
                key_text(member(c.meta, "eps")),
                *truth,
                answer_text,
                ""};
      try {
        TruthPair& p = the_pair();
        if (!p.ellipsoid.is_null() && !p.paraboloid.is_null())
          miss.reproduce = "relpos classify --ellipsoid " + shell_quoted(dump(p.ellipsoid)) + " --paraboloid " +
                           shell_quoted(dump(p.paraboloid));
      } catch (const InputError&) {
      }
      r.misses.push_back(std::move(miss));
    }
  }
  r.total.key = {"all"};
  for (const std::string& family : family_order) {
    if (!curves.count(family)) continue;
    Curve curve{family, {}};
    for (auto& [eps, point] : curves[family]) curve.points.push_back(point);
    r.curves.push_back(std::move(curve));
  }
  return r;
}

// ------------------------------------------------------------------------------------------------
// Reports

namespace {

const char* const kAnswerColumns[7] = {"I", "TI", "C", "TE", "E", "undecided", "missing"};

std::string tolerance_text(const JudgeOptions& o) { return o.tolerance ? to_string(*o.tolerance) : "none"; }

Json counts_json(const Counts& c) {
  return Json{
      {"cases", c.cases},         {"right", c.right},     {"wrong", c.wrong},       {"excused", c.excused},
      {"undecided", c.undecided}, {"missing", c.missing}, {"no_truth", c.no_truth}, {"error_rate", c.error_rate()}};
}

Json baselines_json(const BaselineCounts& b) {
  Json out{{"cases", b.cases}};
  for (std::size_t k = 0; k < 3; ++k) out[kBaselineNames[k]] = b.error_rate(k);
  return out;
}

std::string baseline_cell(const BaselineCounts& b, std::size_t k) { return b.cases ? percent(b.error_rate(k)) : "-"; }

}  // namespace

std::string report_markdown(const JudgeReport& r, std::size_t max_misses) {
  std::ostringstream out;
  const Counts& t = r.total.counts;
  out << "relpos judge: " << t.cases << " cases, truth " << truth_name(r.options.truth) << ", tolerance "
      << tolerance_text(r.options) << "\n\n";
  out << "|";
  for (const std::string& k : r.options.by) out << ' ' << k << " |";
  out << " cases | right | wrong | undecided | missing | excused | error rate |";
  if (r.options.baselines)
    for (const char* b : kBaselineNames) out << ' ' << b << " |";
  out << "\n|";
  for (std::size_t k = 0; k < r.options.by.size(); ++k) out << "---|";
  out << "---:|---:|---:|---:|---:|---:|---:|";
  if (r.options.baselines) out << "---:|---:|---:|";
  out << "\n";
  auto row = [&](const Group& g, bool total) {
    out << "|";
    for (std::size_t k = 0; k < r.options.by.size(); ++k)
      out << ' ' << (total ? (k == 0 ? "all" : "") : g.key[k]) << " |";
    const Counts& c = g.counts;
    out << ' ' << c.judged() << " | " << c.right << " | " << c.wrong << " | " << c.undecided << " | " << c.missing
        << " | " << c.excused << " | " << percent(c.error_rate()) << " |";
    if (r.options.baselines)
      for (std::size_t k = 0; k < 3; ++k) out << ' ' << baseline_cell(g.baselines, k) << " |";
    out << "\n";
  };
  for (const Group& g : r.groups) row(g, false);
  row(r.total, true);
  out << "\nConfusion (rows: truth; columns: answer)\n\n| truth |";
  for (const char* c : kAnswerColumns) out << ' ' << c << " |";
  out << "\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < 5; ++i) {
    out << "| " << to_string(static_cast<Position>(i)) << " |";
    for (std::size_t j = 0; j < 7; ++j) out << ' ' << r.confusion[i][j] << " |";
    out << "\n";
  }
  out << "\nAnswer lines that match no case: " << r.malformed << " malformed, " << r.unknown << " unknown id, "
      << r.duplicate << " duplicate id. Cases without a truth: " << t.no_truth << ".\n";
  if (!r.misses.empty()) {
    out << "\nMisses (" << std::min(max_misses, r.misses.size()) << " of " << r.misses.size()
        << "; --format json lists all):\n\n";
    for (std::size_t i = 0; i < r.misses.size() && i < max_misses; ++i) {
      const Miss& m = r.misses[i];
      out << "- " << m.id << ": truth " << to_string(m.truth) << ", answer " << m.answer << "\n";
      if (!m.reproduce.empty()) out << "  " << m.reproduce << "\n";
    }
  }
  for (const std::string& w : r.warnings) out << "\nwarning: " << w << "\n";
  return out.str();
}

std::string report_csv(const JudgeReport& r) {
  std::ostringstream out;
  for (const std::string& k : r.options.by) out << k << ',';
  out << "cases,right,wrong,undecided,missing,excused,no_truth,error_rate";
  if (r.options.baselines)
    for (const char* b : kBaselineNames) out << ',' << b;
  out << "\n";
  auto quoted = [](const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  auto row = [&](const Group& g, bool total) {
    for (std::size_t k = 0; k < r.options.by.size(); ++k)
      out << (total ? (k == 0 ? "all" : "") : quoted(g.key[k])) << ',';
    const Counts& c = g.counts;
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", c.error_rate());
    out << c.judged() << ',' << c.right << ',' << c.wrong << ',' << c.undecided << ',' << c.missing << ',' << c.excused
        << ',' << c.no_truth << ',' << rate;
    if (r.options.baselines)
      for (std::size_t k = 0; k < 3; ++k) {
        std::snprintf(rate, sizeof rate, "%.6g", g.baselines.error_rate(k));
        out << ',' << (g.baselines.cases ? rate : "");
      }
    out << "\n";
  };
  for (const Group& g : r.groups) row(g, false);
  row(r.total, true);
  return out.str();
}

std::string report_json(const JudgeReport& r) {
  Json out;
  out["truth"] = truth_name(r.options.truth);
  out["tolerance"] = r.options.tolerance ? Json(to_string(*r.options.tolerance)) : Json(nullptr);
  out["by"] = r.options.by;
  Json groups = Json::array();
  for (const Group& g : r.groups) {
    Json j;
    Json key;
    for (std::size_t k = 0; k < r.options.by.size(); ++k) key[r.options.by[k]] = g.key[k];
    j["key"] = key;
    j.update(counts_json(g.counts));
    if (r.options.baselines) j["baselines"] = baselines_json(g.baselines);
    groups.push_back(j);
  }
  out["groups"] = groups;
  Json total = counts_json(r.total.counts);
  if (r.options.baselines) total["baselines"] = baselines_json(r.total.baselines);
  out["total"] = total;
  Json confusion;
  for (std::size_t i = 0; i < 5; ++i) {
    Json row;
    for (std::size_t j = 0; j < 7; ++j) row[kAnswerColumns[j]] = r.confusion[i][j];
    confusion[to_string(static_cast<Position>(i))] = row;
  }
  out["confusion"] = confusion;
  out["unmatched"] = Json{{"malformed", r.malformed}, {"unknown", r.unknown}, {"duplicate", r.duplicate}};
  Json misses = Json::array();
  for (const Miss& m : r.misses)
    misses.push_back(Json{{"id", m.id},
                          {"family", m.family},
                          {"eps", m.eps},
                          {"truth", to_string(m.truth)},
                          {"answer", m.answer},
                          {"reproduce", m.reproduce}});
  out["misses"] = misses;
  Json curves = Json::array();
  for (const Curve& c : r.curves) {
    Json points = Json::array();
    for (const CurvePoint& p : c.points) {
      Json j{{"eps", p.eps}, {"eps_text", p.eps_text}};
      j.update(counts_json(p.counts));
      if (r.options.baselines) j["baselines"] = baselines_json(p.baselines);
      points.push_back(j);
    }
    curves.push_back(Json{{"family", c.family.empty() ? Json(nullptr) : Json(c.family)}, {"points", points}});
  }
  out["curves"] = curves;
  out["warnings"] = r.warnings;
  return dump(out) + "\n";
}

}  // namespace relpos::oracle
