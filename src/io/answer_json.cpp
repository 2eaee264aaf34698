#include "io/answer_json.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "decide/decision.hpp"
#include "io/certificate_json.hpp"
#include "io/general_io.hpp"
#include "io/margin_json.hpp"
#include "io/report_text.hpp"
#include "io/root_decimals.hpp"

namespace relpos::detail::io {
namespace {

/// The members of a report that depend on the verdict alone, written once: a batch line copies them.
struct VerdictTexts {
  std::array<std::array<std::string, 2>, kAllPositions.size()> head;  // by position and smallness
  std::array<std::string, relpos::detail::kRuleCount> rule;
  std::array<std::string, kAllStages.size()> stage;
};

const VerdictTexts& verdict_texts() {
  static const VerdictTexts texts = [] {
    VerdictTexts t;
    for (const Position p : kAllPositions)
      for (const bool small : {false, true}) {
        JsonWriter w(t.head[static_cast<std::size_t>(p)][small]);
        w.member("position");
        w.string(to_string(p));
        w.member("small");
        w.boolean(small);
        w.member("contact");
        w.boolean(contact_of(p) != Contact::None);
      }
    for (std::size_t k = 0; k < relpos::detail::kRuleCount; ++k) {
      JsonWriter w(t.rule[k]);
      w.member("rule");
      w.string(describe(static_cast<Rule>(k)));
    }
    for (const Stage st : kAllStages) {
      JsonWriter w(t.stage[static_cast<std::size_t>(st)]);
      w.member("stage");
      w.string(to_string(st));
    }
    return t;
  }();
  return texts;
}

/// "position", "small" and "contact": the first members of the full and the minimal answer.
void append_verdict_head(const Verdict& v, JsonWriter& w) {
  w.raw(verdict_texts().head.at(static_cast<std::size_t>(v.position))[v.small]);
}

/// ,"rule":"<describe(r)>" and ,"stage":"<to_string(st)>", each text made once.
const std::string& rule_member(Rule r) { return verdict_texts().rule.at(static_cast<std::size_t>(r)); }
const std::string& stage_member(Stage st) { return verdict_texts().stage.at(static_cast<std::size_t>(st)); }

/// The full answer's multiple roots: value, interval, approx, multiplicities, tangency.
void append_multiple_roots(const Classification& c, const relpos::io::RenderOptions& options, JsonWriter& w) {
  w.raw('[');
  const auto approx_roots = root_decimals(c, options.digits, /*only_multiple=*/true);
  bool first = true;
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const auto& r = c.roots[i];
    if (r.multiplicity_f < 2) continue;
    w.raw(first ? "{" : ",{");
    first = false;
    w.key("value");
    w.or_null(r.exact, [&](const Rational& x) { w.rational(x); });
    w.member("interval");
    const Rational ends[2] = {r.lower, r.upper};
    w.rationals(ends, 2);
    w.member("approx");
    w.string(approx_roots[i]);
    w.member("multiplicity_f");
    w.integer(r.multiplicity_f);
    w.member("multiplicity_s");
    w.integer(r.multiplicity_s);
    w.member("tangency");
    w.boolean(r.tangency());
    w.raw('}');
  }
  w.raw(']');
}

/// The counts of f's roots: real, negative, positive, nonreal.
void append_root_counts(const Verdict& v, JsonWriter& w) {
  const std::pair<const char*, int> counts[] = {{"real", v.real_roots},
                                                {"negative", v.negative_roots},
                                                {"positive", v.positive_roots},
                                                {"nonreal", v.nonreal_roots}};
  for (std::size_t k = 0; k < 4; ++k) {
    w.raw(k == 0 ? "{" : ",");
    w.key(counts[k].first);
    w.integer(counts[k].second);
  }
  w.raw('}');
}

}  // namespace

void append_members(const Verdict& v, JsonWriter& w) {
  append_verdict_head(v, w);
  w.raw(rule_member(v.rule));
  w.raw(stage_member(v.stage));
  w.raw('}');
}

void append_members(const Classification& c, const relpos::io::RenderOptions& options, JsonWriter& w) {
  const Verdict& v = c.verdict;
  append_verdict_head(v, w);
  w.member("rho_vs_one");
  w.string(rho_vs_one_text(v.rho_vs_one));
  w.member("rho");
  w.or_null(c.rho, [&](const Rational& rho) { w.rational(rho); });
  w.member("rho_approx");  // the double nearest the exact rho when there is one
  const bool approx = c.has_full_evidence && std::isfinite(c.rho_approx);
  w.or_null(approx ? std::optional<double>(c.rho_approx) : std::nullopt, [&](double x) { w.number(x); });
  w.raw(rule_member(v.rule));
  w.raw(stage_member(v.stage));
  w.member("disc_sign");
  w.integer(v.sign_disc_f);
  w.member("disc_ftilde_sign");
  w.integer(v.sign_disc_ftilde);
  if (c.has_full_evidence) {
    w.member("degree_ftilde");
    w.integer(c.degree_ftilde);
  }
  w.member("roots");
  append_root_counts(v, w);
  if (!c.has_full_evidence) {
    w.raw('}');
    return;
  }
  w.member("f");
  w.rationals(c.f.data(), c.f.size());
  w.member("s");
  w.rationals(c.s.data(), c.s.size());
  w.member("multiple_roots");
  append_multiple_roots(c, options, w);
  w.member("certificate");
  append_certificate(c.certificate, options.digits, w);
  w.raw('}');
}

void append_members(const ContactAnswer& a, JsonWriter& w) {
  w.member("contact");
  w.string(to_string(a.contact));
  w.member("position");
  w.string(to_string(a.position));
  w.member("rule");
  w.string(describe(a.rule));
  w.member("decided_by");
  w.string(decided_by(a.stage));
  w.raw('}');
}

void append_margin_member(const Margin& m, int digits, std::string& out) {
  out.pop_back();  // the members' closing brace
  JsonWriter w(out);
  w.member("margin");
  append_margin(m, digits, w);
  w.raw('}');
}

namespace {

/// The members of a general answer before its closing brace (the minimal answer is these alone).
void append_general_head(const QuadricVerdict& v, JsonWriter& w) {
  w.member("position");
  w.string(to_string(v.position));
  w.member("contact");
  w.string(to_string(contact_of(v.position)));
  w.member("quadric_type");
  w.string(to_string(v.type));
  w.member("rule");
  w.string(describe(v.rule));
  w.member("stage");
  w.string(to_string(v.stage));
}

}  // namespace

void append_members(const QuadricVerdict& v, JsonWriter& w) {
  append_general_head(v, w);
  w.raw('}');
}

void append_members(const QuadricClassification& c, int digits, JsonWriter& w) {
  append_general_head(c.verdict, w);
  w.member("f");
  w.rationals(c.f.data(), c.f.size());
  w.member("d");
  w.rationals(c.d.data(), c.d.size());
  w.member("roots");
  w.raw('[');
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const PencilRoot& r = c.roots[i];
    w.raw(i == 0 ? "{" : ",{");
    w.key("approx");
    w.string(to_decimal((r.lower + r.upper) / 2, digits));
    w.member("interval");
    const Rational ends[2] = {r.lower, r.upper};
    w.rationals(ends, 2);
    w.member("multiplicity_f");
    w.integer(r.multiplicity_f);
    w.member("multiplicity_d");
    w.integer(r.multiplicity_d);
    if (r.exact) {
      w.member("exact");
      w.rational(*r.exact);
    }
    w.raw('}');
  }
  w.raw(']');
  w.member("certificate");  // its tree, shared with the text report and read back by relpos verify
  w.raw(dump_json(quadric_certificate_to_json(c.certificate, digits)));
  w.raw('}');
}

void reserve_for_id(std::string& out, std::string_view id) {
  constexpr std::size_t kLong = std::size_t(1) << 16, kReport = std::size_t(1) << 20;  // a report is smaller
  if (id.size() > kLong) out.reserve(id.size() + kReport);
}

bool write_error(std::string_view id, std::string_view message, std::string& out) noexcept {
  try {
    out.clear();
    if (out.capacity() < id.size() + message.size() + 32) reserve_for_id(out, id);
    out.append("{\"id\":").append(id).append(",\"error\":");
    JsonWriter(out).string(message);
    out += '}';
    return true;
  } catch (...) {
    return false;
  }
}

void append_trailer(std::string_view meta, bool numbers_as_doubles, std::string& out) {
  if ((!numbers_as_doubles && meta.empty()) || out.empty() || out.back() != '}') return;
  constexpr std::string_view kNumbers = ",\"numbers\":\"double\"", kMeta = ",\"meta\":";
  out.reserve(out.size() + (numbers_as_doubles ? kNumbers.size() : 0) +
              (meta.empty() ? 0 : kMeta.size() + meta.size()));
  out.pop_back();
  if (numbers_as_doubles) out.append(kNumbers);
  if (!meta.empty()) out.append(kMeta).append(meta);
  out.push_back('}');
}

std::string minimal_json_text(const Verdict& v) { return answer_text(128, v); }

}  // namespace relpos::detail::io

namespace relpos::io {

std::string classification_json_text(const Classification& c, const RenderOptions& options) {
  // The reports of ordinary pairs fit: no reallocation.
  return detail::io::answer_text(c.has_full_evidence ? 2048 : 512, c, options);
}

std::string contact_json_text(const ContactAnswer& a) { return detail::io::answer_text(128, a); }

}  // namespace relpos::io
