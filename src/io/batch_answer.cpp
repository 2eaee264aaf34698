// answer_batch_line (io.hpp): one line of `relpos batch`, read (batch.hpp), decided at the evidence
// level asked, and answered by the one answer writer (answer_json.hpp), the line's last members
// (number mode, "meta") included; any failure is that line's error, out of memory included (doc/cli.md,
// "Out of memory").
#include <charconv>
#include <new>
#include <optional>
#include <string>
#include <string_view>

#include "io/answer_json.hpp"
#include "io/batch.hpp"
#include "io/general_io.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/error.hpp"
#include "relpos/general_classify.hpp"
#include "relpos/io.hpp"
#include "relpos/margin.hpp"

namespace relpos::detail::io {
namespace {

/// The answer of a line read, at the evidence level of the options, ending with its margin when the
/// options ask for it (computed first, like the answer, before the id is written).
void answer(const BatchLine& in, std::string_view id, const BatchOptions& options, std::string& out) {
  if (in.quadric) {  // a general quadric (doc/cli.md, "General quadrics"): --contact-only gets the verdict
    if (options.margin_bits > 0)
      throw InputError("--margin: the margin s* is defined for an ellipsoid and an elliptic paraboloid only");
    // Beyond the default limit (raised by --max-bits; the reader checked the size): a large stack.
    const std::size_t bits = options.size_limit.max_bits > kMaxNormalizedBits
                                 ? check_general_pair_size(*in.ellipsoid, *in.quadric, options.size_limit)
                                 : 0;
    if (options.evidence == Evidence::Full && !options.contact_only)
      write_answer(id, out, with_stack_for_general(bits, [&] { return classify(*in.ellipsoid, *in.quadric); }),
                   options.render.digits);
    else
      write_answer(id, out, with_stack_for_general(bits, [&] { return decide_position(*in.ellipsoid, *in.quadric); }));
    return;
  }
  const std::optional<Margin> m =
      options.margin_bits > 0 ? std::optional<Margin>(margin(*in.ellipsoid, *in.paraboloid, options.margin_bits))
                              : std::nullopt;
  if (options.contact_only) {
    write_answer(id, out, contact(*in.ellipsoid, *in.paraboloid, options.size_limit));
  } else if (options.evidence == Evidence::Minimal) {  // the verdict alone: classify's, without its evidence
    write_answer(id, out, decide_position(*in.ellipsoid, *in.paraboloid, options.size_limit));
  } else {
    const Classification c = classify(*in.ellipsoid, *in.paraboloid, Evidence::Full, options.size_limit);
    write_answer(id, out, c, options.render);
  }
  if (m) append_margin_member(*m, options.render.digits, out);
}

/// The answer's last members (detail::append_trailer); false when out of memory there.
bool finish(std::string_view meta, const BatchOptions& options, std::string& out) noexcept {
  try {
    append_trailer(meta, options.numbers_as_doubles, out);
    return true;
  } catch (...) {
    return false;
  }
}

/// Out of memory: that line's error, with its id when it can be echoed (the partial answer's
/// capacity is reused), else with the line number (doc/cli.md, "Out of memory"); its last members
/// when they fit (the meta only with the id).
void out_of_memory(std::string_view id, std::string_view meta, long line_number, const BatchOptions& options,
                   std::string& out) noexcept {
  if (write_error(id, kOutOfMemoryMessage, out)) {
    finish(meta, options, out);
    return;
  }
  char number[24];
  const auto end = std::to_chars(number, number + sizeof number, line_number).ptr;
  if (write_error(std::string_view(number, static_cast<std::size_t>(end - number)), kOutOfMemoryNoIdMessage, out)) {
    finish(std::string_view(), options, out);
    return;
  }
  out.clear();  // not even that: the caller writes its own line (doc/cli.md)
}

}  // namespace

void answer_batch_line(std::string_view line, long line_number, const BatchOptions& options, std::string& out) {
  // The line's memory: the caller's line, the answer, and no copy of the id (a view into the line).
  // The answer is computed before the id is written, so that no long id is held meanwhile.
  BatchLine in;
  std::string_view id, meta;
  std::string internal;
  try {
    read_batch_line(line, line_number, options, nullptr, in, &id, &meta);
    answer(in, id, options, out);
    append_trailer(meta, options.numbers_as_doubles, out);
    return;
  } catch (const InputError& err) {
    if (write_error(id, err.what(), out) && finish(meta, options, out)) return;
  } catch (const std::bad_alloc&) {
  } catch (const std::exception& err) {
    try {
      internal = std::string("internal error: ") + err.what();
    } catch (...) {
    }
    if (!internal.empty() && write_error(id, internal, out) && finish(meta, options, out)) return;
  } catch (...) {
    if (write_error(id, "internal error: unknown exception", out) && finish(meta, options, out)) return;
  }
  out_of_memory(id, meta, line_number, options, out);
}

std::string answer_batch_line(std::string_view line, long line_number, const BatchOptions& options) {
  std::string out;
  answer_batch_line(line, line_number, options, out);
  return out;
}

}  // namespace relpos::detail::io
