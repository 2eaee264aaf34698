// The one writer of an answer's JSON text, for every evidence level: the frame ({"id":<id>, or {
// alone), then the members of the level -- minimal (the verdict), full (the classification with its
// evidence and certificate) or contact only -- each preceded by a comma, then the closing brace.
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
#include "relpos/io.hpp"

namespace relpos::io::detail {

/// The minimal answer: position, small, contact, rule, stage.
void append_members(const Verdict& v, JsonWriter& w);
/// The full answer (classification_json_text's members): position, small, contact, rho_vs_one,
/// rho, rho_approx, rule, stage, disc_sign, disc_ftilde_sign, roots, and with full evidence
/// degree_ftilde (before roots), f, s, multiple_roots and certificate.
void append_members(const Classification& c, const RenderOptions& options, JsonWriter& w);
/// The contact-only answer (doc/contact.md): contact, position, rule, decided_by.
void append_members(const ContactAnswer& a, JsonWriter& w);

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

}  // namespace relpos::io::detail
