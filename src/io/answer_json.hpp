// The one writer of an answer's JSON text, for every evidence level: the frame ({"id":<id>, or {
// alone), then the members of the level -- minimal (the verdict), full (the classification with its
// evidence and certificate) or contact only -- each preceded by a comma, then the closing brace;
// a batch line's last members (append_trailer: the number mode and the line's "meta") after them.
// `relpos batch`, `relpos classify --json`, the Python module and the public text functions of
// io.hpp all write through it; a new answer member goes into the level's append_members, a new
// level is one more overload (doc/architecture.md, "One batch line, from text to verdict").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "io/json_write.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/general_classify.hpp"
#include "relpos/io.hpp"
#include "relpos/margin.hpp"

namespace relpos::detail::io {

/// The minimal answer: position, small, contact, rule, stage.
void append_members(const Verdict& v, JsonWriter& w);
/// The full answer (classification_json_text's members): position, small, contact, rho_vs_one,
/// rho, rho_approx, rule, stage, disc_sign, disc_ftilde_sign, roots, and with full evidence
/// degree_ftilde (before roots), f, s, multiple_roots and certificate.
void append_members(const Classification& c, const relpos::io::RenderOptions& options, JsonWriter& w);
/// The contact-only answer (doc/contact.md): contact, position, rule, decided_by.
void append_members(const ContactAnswer& a, JsonWriter& w);
/// A general pair's answer (doc/cli.md, "General quadrics"): position, contact, quadric_type, rule,
/// stage (the minimal answer, and the one of --contact-only).
void append_members(const QuadricVerdict& v, JsonWriter& w);
/// A general pair's full answer: the minimal members, then the exact f and d, the real roots
/// (decimals with `digits` digits, intervals, multiplicities) and the certificate.
void append_members(const QuadricClassification& c, int digits, JsonWriter& w);

/// The margin (`--margin`; doc/certificates.md, "Margins") as the answer's last member, ,"margin":{...},
/// written over the closing brace of the level's members just appended to `out`: any level may end
/// with it.
void append_margin_member(const Margin& m, int digits, std::string& out);

/// Room in `out` for a long id and what follows it at once: growing past the id would copy it.
void reserve_for_id(std::string& out, std::string_view id);

/// The answer line {"id":<id>,...} of a report into `out` (replacing its text, keeping its
/// capacity; the id is written first, byte for byte).
template <class... Report>
void write_answer(std::string_view id, std::string& out, const Report&... report) {
  reserve_for_id(out, id);
  out.assign("{\"id\":").append(id);
  JsonWriter w(out);
  append_members(report..., w);
}

/// The answer without an id, {...}, with room for `reserve` bytes.
template <class... Report>
std::string answer_text(std::size_t reserve, const Report&... report) {
  std::string out;
  out.reserve(reserve);
  JsonWriter w(out);
  append_members(report..., w);
  out[0] = '{';  // the members start with a comma (a batch line writes the id before them)
  return out;
}

/// {"id":<id>,"error":<message>} into `out` (its capacity kept); false when out of memory.
bool write_error(std::string_view id, std::string_view message, std::string& out) noexcept;

/// The members every answer line of a batch or a scene ends with, answer or error (doc/cli.md,
/// "relpos batch"): "numbers":"double" when the line was read with --numbers double, then
/// "meta":<meta> when the input line had a "meta" member (its text, echoed byte for byte), written
/// before the closing brace of the answer in `out`. Room first: out of memory (std::bad_alloc)
/// leaves `out` as it was, a whole JSON object.
void append_trailer(std::string_view meta, bool numbers_as_doubles, std::string& out);

/// The minimal report of `relpos batch --evidence minimal` (without "id") as one line of JSON
/// text: position, small, contact, rule, stage (the Python package's classify(evidence="minimal")).
std::string minimal_json_text(const Verdict& v);

}  // namespace relpos::detail::io
