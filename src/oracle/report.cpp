// The reports of judge.hpp: Markdown tables, CSV and JSON, from one JudgeReport.
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "oracle/json_text.hpp"
#include "oracle/judge.hpp"

namespace relpos::detail::oracle {

namespace {

std::string percent(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100 * x);
  return text;
}

}  // namespace

namespace {

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

}  // namespace relpos::detail::oracle
