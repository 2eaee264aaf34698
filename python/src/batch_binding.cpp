// relpos._relpos._batch_block: the lines of `relpos batch` for a block of a JSON Lines file, answered
// by the library's relpos::detail::io::answer_batch_line (the one batch-line function of the CLI), for
// relpos.distributed (doc/python.md, "Dask").
//
// A block is whole lines of a file: it is cut into lines as `relpos batch` reads a file (at each
// '\n'; a last line without '\n' is a line, nothing after a final '\n' is), and every answer is
// followed by '\n'. The BOM, a trailing '\r', blank lines, NUL bytes and over-long lines are the
// library's business (relpos::detail::io::normalize_line), so a block answered here gives the bytes the CLI
// writes for the same lines with the same numbers.
#include <algorithm>
#include <cstddef>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "base/worker_pool.hpp"
#include "io/batch.hpp"
#include "module.hpp"

namespace relpos_python {

using namespace pybind11::literals;

namespace {

/// The options of `relpos batch`, spelled as its command-line values; the CLI's ranges.
relpos::detail::io::BatchOptions batch_options(const std::string& evidence, const std::string& numbers,
                                               bool contact_only, int digits, long long max_line_bytes,
                                               long long max_bits) {
  relpos::detail::io::BatchOptions options;
  if (evidence != "full" && evidence != "minimal")
    throw relpos::InputError("evidence: expected 'full' or 'minimal', got '" + evidence + "'");
  if (numbers != "exact" && numbers != "double")
    throw relpos::InputError("numbers: expected 'exact' or 'double', got '" + numbers + "'");
  if (digits < 1 || digits > 1000)
    throw relpos::InputError("digits: expected 1 to 1000, got " + std::to_string(digits));
  if (max_line_bytes < 1 || max_line_bytes > (1LL << 40))
    throw relpos::InputError("max_line_bytes: expected 1 to 2^40, got " + std::to_string(max_line_bytes));
  options.evidence = evidence == "full" ? relpos::Evidence::Full : relpos::Evidence::Minimal;
  options.numbers_as_doubles = numbers == "double";
  options.contact_only = contact_only;
  options.render.digits = digits;
  options.max_line_bytes = static_cast<std::size_t>(max_line_bytes);
  if (max_bits < static_cast<long long>(relpos::kMaxNormalizedBits) || max_bits > (1LL << 32))
    throw relpos::InputError("max_bits: expected " + std::to_string(relpos::kMaxNormalizedBits) + " to 2^32, got " +
                             std::to_string(max_bits));
  options.size_limit.max_bits = static_cast<std::size_t>(max_bits);
  return options;
}

/// The lines of a block, as `relpos batch` reads them.
std::vector<std::string_view> split_lines(std::string_view block) {
  std::vector<std::string_view> lines;
  for (std::size_t begin = 0; begin < block.size();) {
    const std::size_t nl = block.find('\n', begin);
    const std::size_t end = nl == std::string_view::npos ? block.size() : nl;
    lines.push_back(block.substr(begin, end - begin));
    begin = end + 1;
  }
  return lines;
}

std::string answer_block(std::string_view block, long first_line, const relpos::detail::io::BatchOptions& options,
                         unsigned threads) {
  const std::vector<std::string_view> lines = split_lines(block);
  std::string out, answer;
  if (threads <= 1 || lines.size() < 2) {
    for (std::size_t i = 0; i < lines.size(); ++i) {
      relpos::detail::io::answer_batch_line(lines[i], first_line + static_cast<long>(i), options, answer);
      out.append(answer).push_back('\n');
    }
    return out;
  }
  std::vector<std::string> answers(lines.size());
  relpos::detail::WorkerPool pool(static_cast<unsigned>(std::min<std::size_t>(threads, lines.size())));
  pool.run(lines.size(), [&](std::size_t i) {
    relpos::detail::io::answer_batch_line(lines[i], first_line + static_cast<long>(i), options, answers[i]);
  });
  for (const std::string& a : answers) out.append(a).push_back('\n');
  return out;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def(
      "_batch_block",
      [](const py::bytes& data, long first_line, const std::string& evidence, const std::string& numbers,
         bool contact_only, int digits, long long max_line_bytes, int threads, long long max_bits) {
        const relpos::detail::io::BatchOptions options =
            batch_options(evidence, numbers, contact_only, digits, max_line_bytes, max_bits);
        if (first_line < 1) throw relpos::InputError("first_line: expected >= 1, got " + std::to_string(first_line));
        if (threads < 1) throw relpos::InputError("threads: expected >= 1, got " + std::to_string(threads));
        const std::string_view block = data;  // `data` is held by the caller while the GIL is released
        std::string out;
        {
          py::gil_scoped_release release;
          out = answer_block(block, first_line, options, static_cast<unsigned>(threads));
        }
        return py::bytes(out);
      },
      "data"_a, "first_line"_a = 1, "evidence"_a = "full", "numbers"_a = "exact", "contact_only"_a = false,
      "digits"_a = 12, "max_line_bytes"_a = static_cast<long long>(relpos::detail::io::kDefaultMaxLineBytes),
      "threads"_a = 1, "max_bits"_a = static_cast<long long>(relpos::kMaxNormalizedBits),
      "The output of `relpos batch` for the lines of `data` (whole lines of a JSON Lines file, the first of them "
      "line number `first_line`), as bytes: one answer and '\\n' per line. The options are those of `relpos batch` "
      "(--evidence, --numbers, --contact-only, --digits, --max-line-bytes, --max-bits); `threads` threads of one "
      "worker pool answer "
      "the lines.");
}

}  // namespace relpos_python
