// answer_batch_line (io.hpp): one line of `relpos batch`, read (batch.hpp), decided at the evidence
// level asked, and answered by the one answer writer (answer_json.hpp); any failure is that line's
// error, out of memory included (doc/cli.md, "Out of memory").
#include <charconv>
#include <new>
#include <string>
#include <string_view>

#include "io/answer_json.hpp"
#include "io/batch.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::io {
namespace {

/// The answer of a line read, at the evidence level of the options.
void answer(const BatchLine& in, std::string_view id, const BatchOptions& options, std::string& out) {
  if (options.contact_only) {
    detail::write_answer(id, out, contact(*in.ellipsoid, *in.paraboloid));
  } else if (options.evidence == Evidence::Minimal) {  // the verdict alone: classify's, without its evidence
    detail::write_answer(id, out, decide_position(*in.ellipsoid, *in.paraboloid));
  } else {
    const Classification c = classify(*in.ellipsoid, *in.paraboloid, Evidence::Full);
    detail::write_answer(id, out, c, options.render);
  }
}

/// Out of memory: that line's error, with its id when it can be echoed (the partial answer's
/// capacity is reused), else with the line number (doc/cli.md, "Out of memory").
void out_of_memory(std::string_view id, long line_number, std::string& out) noexcept {
  if (detail::write_error(id, kOutOfMemoryMessage, out)) return;
  char number[24];
  const auto end = std::to_chars(number, number + sizeof number, line_number).ptr;
  if (detail::write_error(std::string_view(number, static_cast<std::size_t>(end - number)), kOutOfMemoryNoIdMessage,
                          out))
    return;
  out.clear();  // not even that: the caller writes its own line (doc/cli.md)
}

}  // namespace

void answer_batch_line(std::string_view line, long line_number, const BatchOptions& options, std::string& out) {
  // The line's memory: the caller's line, the answer, and no copy of the id (a view into the line).
  // The answer is computed before the id is written, so that no long id is held meanwhile.
  BatchLine in;
  std::string_view id;
  std::string internal;
  try {
    read_batch_line(line, line_number, options, nullptr, in, &id);
    answer(in, id, options, out);
    return;
  } catch (const InputError& err) {
    if (detail::write_error(id, err.what(), out)) return;
  } catch (const std::bad_alloc&) {
  } catch (const std::exception& err) {
    try {
      internal = std::string("internal error: ") + err.what();
    } catch (...) {
    }
    if (!internal.empty() && detail::write_error(id, internal, out)) return;
  } catch (...) {
    if (detail::write_error(id, "internal error: unknown exception", out)) return;
  }
  out_of_memory(id, line_number, out);
}

std::string answer_batch_line(std::string_view line, long line_number, const BatchOptions& options) {
  std::string out;
  answer_batch_line(line, line_number, options, out);
  return out;
}

}  // namespace relpos::io
