// One batch line (io.hpp): the reader shared by `relpos batch`, `relpos scene` and the fuzzer.
//
// The top-level object of a line is scanned by hand, once: each member's value is located as a span
// of the text, so that the id is echoed byte for byte, duplicate keys are seen, and "comment" is
// validated by a SAX pass that stores nothing. The two quadrics are read by the fast reader
// (fast_quadric.hpp: common forms, short numbers, straight to double enclosures) or else parsed
// into (small, bounded) DOMs by the general reader, which words every error.
#include "io/batch.hpp"

#include <cctype>
#include <charconv>
#include <new>
#include <string>
#include <string_view>

#include "io/fast_quadric.hpp"
#include "io/json_read.hpp"
#include "io/json_write.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::io {
namespace {

using Json = nlohmann::ordered_json;

/// Entries allowed per array or object inside a quadric (a 4x4 matrix has 4 rows of 4).
constexpr std::size_t kMaxQuadricEntries = 16;

bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::size_t skip_ws(std::string_view s, std::size_t i) {
  while (i < s.size() && is_ws(s[i])) ++i;
  return i;
}

/// End of the string starting at s[i] == '"', or npos.
std::size_t string_end(std::string_view s, std::size_t i) {
  for (++i; i < s.size(); ++i) {
    if (s[i] == '\\')
      ++i;
    else if (s[i] == '"')
      return i + 1;
  }
  return std::string_view::npos;
}

/// End of the JSON value starting at s[i] (structure only: the span is validated later), or npos.
std::size_t value_end(std::string_view s, std::size_t i) {
  if (i >= s.size()) return std::string_view::npos;
  if (s[i] == '"') return string_end(s, i);
  if (s[i] == '{' || s[i] == '[') {
    std::size_t depth = 0;
    while (i < s.size()) {
      const char c = s[i];
      if (c == '"') {
        i = string_end(s, i);
        if (i == std::string_view::npos) return i;
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      if ((c == '}' || c == ']') && --depth == 0) return i + 1;
      ++i;
    }
    return std::string_view::npos;
  }
  const std::size_t start = i;
  while (i < s.size() && !is_ws(s[i]) && s[i] != ',' && s[i] != '}' && s[i] != ']') ++i;
  return i == start ? std::string_view::npos : i;
}

/// The message of a line that is not JSON, from the parser (columns count from the line's start).
[[noreturn]] void invalid_json(std::string_view line) {
  detail::validate_json(line);
  throw InputError("invalid JSON: expected one JSON object");
}

struct Member {
  std::string_view key;  ///< one of the known keys
  std::string_view value;
  bool fast = false;  ///< a quadric the fast reader took (into the line's quadric of that key)
};

bool valid_utf8(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : 9;
    if (n == 9 || i + n >= s.size()) return false;
    for (std::size_t k = 1; k <= n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return false;
    i += n + 1;
  }
  return true;
}

/// The name of a key given as its JSON text "...": the text between the quotes when it has no
/// escape, control character or non-ASCII byte (what every key of a well-formed line is), else the
/// general parser's reading, kept in `storage`.
std::string_view key_name(std::string_view key_text, std::string& storage) {
  bool plain = true;
  for (std::size_t k = 1; k + 1 < key_text.size() && plain; ++k) {
    const auto c = static_cast<unsigned char>(key_text[k]);
    plain = c >= 0x20 && c < 0x80 && c != '\\';
  }
  if (plain) return key_text.substr(1, key_text.size() - 2);
  storage = Json::parse(key_text).get<std::string>();
  return storage;
}

/// Length of the valid UTF-8 sequence at s[i] (1 to 4), or 0 (what the JSON parser refuses:
/// overlong forms, surrogates, code points beyond U+10FFFF).
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto at = [&](std::size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
  const unsigned c = at(0);
  const auto tail = [&](std::size_t k) { return (at(k) >> 6) == 2; };
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return tail(1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return at(1) >= lo && at(1) <= hi && tail(2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return at(1) >= lo && at(1) <= hi && tail(2) && tail(3) ? 4 : 0;
  }
  return 0;
}

bool hex4(std::string_view s, std::size_t i) {
  if (i + 4 > s.size()) return false;
  for (std::size_t k = i; k < i + 4; ++k)
    if (!std::isxdigit(static_cast<unsigned char>(s[k]))) return false;
  return true;
}

/// A JSON string that is certainly valid: escapes well formed, no control character, valid UTF-8,
/// \u escapes of surrogates only as pairs (else the parser decides and words the error).
bool plain_string(std::string_view v) {
  if (v.size() < 2 || v.front() != '"' || v.back() != '"') return false;
  const std::string_view s = v.substr(1, v.size() - 2);
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c < 0x20) return false;
    if (c != '\\') {
      const std::size_t n = utf8_length(s, i);
      if (n == 0) return false;
      i += n;
      continue;
    }
    if (i + 1 >= s.size()) return false;
    const char e = s[i + 1];
    if (e != 'u') {
      if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) return false;
      i += 2;
      continue;
    }
    if (!hex4(s, i + 2)) return false;
    const unsigned long u = std::stoul(std::string(s.substr(i + 2, 4)), nullptr, 16);
    if (u >= 0xDC00 && u <= 0xDFFF) return false;
    if (u >= 0xD800 && u <= 0xDBFF) {
      if (i + 7 >= s.size() || s[i + 6] != '\\' || s[i + 7] != 'u' || !hex4(s, i + 8)) return false;
      const unsigned long w = std::stoul(std::string(s.substr(i + 8, 4)), nullptr, 16);
      if (w < 0xDC00 || w > 0xDFFF) return false;
      i += 6;
    }
    i += 6;
  }
  return true;
}

/// A JSON number (RFC 8259 grammar), of any length.
bool plain_number(std::string_view v) {
  std::size_t k = 0;
  const auto digits = [&] {
    const std::size_t from = k;
    while (k < v.size() && v[k] >= '0' && v[k] <= '9') ++k;
    return k > from;
  };
  if (k < v.size() && v[k] == '-') ++k;
  if (k < v.size() && v[k] == '0')
    ++k;
  else if (!digits())
    return false;
  if (k < v.size() && v[k] == '.' && (++k, !digits())) return false;
  if (k < v.size() && (v[k] == 'e' || v[k] == 'E')) {
    ++k;
    if (k < v.size() && (v[k] == '+' || v[k] == '-')) ++k;
    if (!digits()) return false;
  }
  return k == v.size();
}

/// An id, comment or unknown member's value that is certainly one valid JSON value, checked in
/// place: a string or a number of any length (the parser's lexer would hold a copy of a long token,
/// twice). Anything else goes through the validating parser, which stores one token at a time.
bool plainly_valid(std::string_view v) { return !v.empty() && (v.front() == '"' ? plain_string(v) : plain_number(v)); }

/// The minimal report's members after the id, in the order of the full report's first members.
void append_minimal(const Verdict& v, std::string& out) {
  detail::JsonWriter w(out);
  detail::append_verdict_head(v, w);
  out += detail::rule_member(v.rule);
  out += detail::stage_member(v.stage);
  out += '}';
}

}  // namespace

std::string minimal_json_text(const Verdict& v) {
  std::string out;
  append_minimal(v, out);
  out[0] = '{';  // the members start with a comma (batch writes the id before them)
  return out;
}

namespace {

/// Room in `out` for a long id and what follows it at once: growing past the id would copy it.
void reserve_for_id(std::string& out, std::string_view id) {
  constexpr std::size_t kLong = std::size_t(1) << 16, kReport = std::size_t(1) << 20;  // a report is smaller
  if (id.size() > kLong) out.reserve(id.size() + kReport);
}

/// Writes {"id":<id>,"error":<message>} into out (its capacity kept); false when out of memory.
bool write_error(std::string& out, std::string_view id, std::string_view message) noexcept {
  try {
    out.clear();
    if (out.capacity() < id.size() + message.size() + 32) reserve_for_id(out, id);
    out.append("{\"id\":").append(id).append(",\"error\":");
    detail::JsonWriter(out).string(message);
    out += '}';
    return true;
  } catch (...) {
    return false;
  }
}

}  // namespace

Json contact_to_json(const ContactAnswer& a) {
  Json j;
  j["contact"] = to_string(a.contact);
  j["position"] = to_string(a.position);
  j["rule"] = describe(a.rule);
  j["decided_by"] = decided_by(a.stage);
  return j;
}

std::string dump_json(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

std::string error_line(const std::string& id_text, const std::string& message) {
  std::string out;
  if (!write_error(out, id_text, message)) throw std::bad_alloc();
  return out;
}

std::string too_long_message(std::size_t max_line_bytes) {
  return "line too long: more than " + std::to_string(max_line_bytes) + " bytes (--max-line-bytes)";
}

std::string_view normalize_line(std::string_view line, long line_number, std::size_t max_line_bytes) {
  if (line.size() > max_line_bytes) throw InputError(too_long_message(max_line_bytes));
  if (line.substr(0, 3) == "\xEF\xBB\xBF") {
    if (line_number != 1) throw InputError("a UTF-8 byte order mark is accepted only at the start of the input");
    line.remove_prefix(3);
  }
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::size_t nul = line.find('\0');
  if (nul != std::string_view::npos) throw InputError("NUL byte at column " + std::to_string(nul + 1));
  return line;
}

namespace {

/// read_batch_line; with `id`, the id is not copied into out.id: *id is set to its text instead (a
/// view into `raw`, or of out.id when it is the line number or re-encoded), before anything is thrown.
void read_line(std::string_view raw, long line_number, const BatchOptions& options, const Paraboloid* fixed,
               BatchLine& out, std::string_view* id) {
  out.id = std::to_string(line_number);
  if (id) *id = out.id;
  out.ellipsoid.reset();  // the fast reader makes the quadrics here as the line is scanned
  out.paraboloid.reset();
  const std::string_view line = normalize_line(raw, line_number, options.max_line_bytes);
  std::size_t i = skip_ws(line, 0);
  if (i == line.size()) throw InputError("empty line");
  const char* const expected = fixed ? "expected a JSON object {\"id\": ..., \"ellipsoid\": ...}"
                                     : "expected a JSON object {\"id\": ..., \"ellipsoid\": ..., \"paraboloid\": ...}";
  if (line[i] != '{') {
    detail::validate_json(line);  // not JSON, or JSON that is not an object
    throw InputError(expected);
  }
  // Scan the members; all structural errors are reported by the parser's message on the whole line.
  Member members[4];
  std::size_t count = 0;
  std::string unknown, duplicate, key_storage;
  i = skip_ws(line, i + 1);
  if (i < line.size() && line[i] == '}') {
    i = skip_ws(line, i + 1);
  } else {
    for (;;) {
      if (i >= line.size() || line[i] != '"') invalid_json(line);
      const std::size_t key_end = string_end(line, i);
      if (key_end == std::string_view::npos) invalid_json(line);
      const std::string_view key_text = line.substr(i, key_end - i);
      i = skip_ws(line, key_end);
      if (i >= line.size() || line[i] != ':') invalid_json(line);
      i = skip_ws(line, i + 1);
      std::string_view key;
      try {
        key = key_name(key_text, key_storage);
      } catch (const nlohmann::json::exception&) {
        invalid_json(line);
      }
      // A quadric is read by the fast reader as the line is scanned: its end comes with it.
      std::size_t end = std::string_view::npos;
      bool taken = false;
      if (key == "ellipsoid")
        taken = detail::fast_ellipsoid_at(line.substr(i), options.numbers_as_doubles, end, out.ellipsoid);
      else if (key == "paraboloid" && !fixed)
        taken = detail::fast_paraboloid_at(line.substr(i), options.numbers_as_doubles, end, out.paraboloid);
      end = end == std::string_view::npos ? value_end(line, i) : i + end;
      if (end == std::string_view::npos) invalid_json(line);
      const std::string_view value = line.substr(i, end - i);
      // nlohmann skips a byte order mark at the start of what it parses; inside a line it is not JSON.
      if (value.substr(0, 3) == "\xEF\xBB\xBF") invalid_json(line);
      static constexpr std::string_view kKeys[] = {"id", "ellipsoid", "paraboloid", "comment"};
      bool known = false;
      for (const std::string_view k : kKeys) {
        if (key != k || (fixed && key == "paraboloid")) continue;
        known = true;
        for (std::size_t m = 0; m < count; ++m)
          if (members[m].key == k && duplicate.empty()) duplicate = key;
        if (count < 4) members[count++] = Member{k, value, taken};
      }
      if (!known) {
        if (unknown.empty()) unknown = key.substr(0, 40);
        try {
          if (!plainly_valid(value)) detail::validate_json(value, 1);  // not stored; still JSON within the limits
        } catch (const detail::JsonSyntaxError&) {
          invalid_json(line);
        }
      }
      i = skip_ws(line, end);
      if (i < line.size() && line[i] == ',') {
        i = skip_ws(line, i + 1);
        continue;
      }
      if (i < line.size() && line[i] == '}') {
        i = skip_ws(line, i + 1);
        break;
      }
      invalid_json(line);
    }
  }
  if (i != line.size()) invalid_json(line);

  // The id and the comment: valid JSON, not stored (the id is kept as its text).
  for (std::size_t m = 0; m < count; ++m) {
    if (members[m].key == "ellipsoid" || members[m].key == "paraboloid") continue;
    if (plainly_valid(members[m].value)) continue;
    try {
      detail::validate_json(members[m].value, 1);
    } catch (const detail::JsonSyntaxError&) {
      invalid_json(line);  // reported on the whole line, with its columns
    }
  }
  for (std::size_t m = count; m-- > 0;)  // the first "id" when there are two (an error below)
    if (members[m].key == "id") {
      const std::string_view value = members[m].value;
      if (!valid_utf8(value)) {
        out.id = dump_json(detail::parse_json(value, detail::JsonReadOptions{}));
        if (id) *id = out.id;
      } else if (id) {
        *id = value;  // byte for byte, not copied
      } else {
        out.id.assign(value.data(), value.size());  // byte for byte
      }
    }
  // The quadrics: small bounded trees, numbers exact (or the nearest doubles).
  detail::JsonReadOptions read;
  read.doubles = options.numbers_as_doubles;
  read.max_elements = kMaxQuadricEntries;
  read.start_depth = 1;
  Json ellipsoid, paraboloid;
  for (std::size_t m = 0; m < count; ++m) {
    const Member& x = members[m];
    if ((x.key != "ellipsoid" && x.key != "paraboloid") || x.fast) continue;
    try {
      (x.key == "ellipsoid" ? ellipsoid : paraboloid) = detail::parse_json(x.value, read);
    } catch (const detail::JsonSyntaxError&) {
      out.id = std::to_string(line_number);  // as for any line that is not JSON
      if (id) *id = out.id;
      invalid_json(line);
    } catch (const InputError& e) {
      throw InputError(std::string(x.key) + ": " + e.what());  // a limit: nesting, entries, duplicate key
    }
  }
  if (!duplicate.empty()) throw InputError("duplicate key \"" + duplicate + "\"");
  if (!unknown.empty())
    throw InputError("unknown key \"" + unknown + "\"" +
                     (fixed ? " (a scene line takes \"id\", \"ellipsoid\" and \"comment\")"
                            : " (a line takes \"id\", \"ellipsoid\", \"paraboloid\" and \"comment\")"));
  if (!out.ellipsoid && ellipsoid.is_null()) throw InputError("ellipsoid: missing");
  if (!fixed && !out.paraboloid && paraboloid.is_null()) throw InputError("paraboloid: missing");
  if (!out.ellipsoid) out.ellipsoid = ellipsoid_from_json(ellipsoid, "ellipsoid");
  if (!fixed && !out.paraboloid) out.paraboloid = paraboloid_from_json(paraboloid, "paraboloid");
  check_normalized_pair_size(*out.ellipsoid, fixed ? *fixed : *out.paraboloid,
                             options.size_limit);  // doc/cli.md, Limits
}

}  // namespace

void read_batch_line(std::string_view line, long line_number, const BatchOptions& options, const Paraboloid* fixed,
                     BatchLine& out) {
  read_line(line, line_number, options, fixed, out, nullptr);
}

void answer_batch_line(std::string_view line, long line_number, const BatchOptions& options, std::string& out) {
  // The line's memory: the caller's line, the answer, and no copy of the id (a view into the line).
  // The answer is computed before the id is written, so that no long id is held meanwhile.
  BatchLine in;
  std::string_view id;
  std::string internal;
  try {
    read_line(line, line_number, options, nullptr, in, &id);
    if (options.contact_only) {
      const std::string report = dump_json(contact_to_json(contact(*in.ellipsoid, *in.paraboloid, options.size_limit)));
      reserve_for_id(out, id);
      out.assign("{\"id\":").append(id).append(",").append(report, 1, std::string::npos);
      return;
    }
    if (options.evidence == Evidence::Minimal) {  // the verdict alone: classify's, without its evidence
      const Verdict v = decide_position(*in.ellipsoid, *in.paraboloid, options.size_limit);
      reserve_for_id(out, id);
      out.assign("{\"id\":").append(id);  // the id goes first
      append_minimal(v, out);
      return;
    }
    const Classification c = classify(*in.ellipsoid, *in.paraboloid, Evidence::Full, options.size_limit);
    reserve_for_id(out, id);
    out.assign("{\"id\":").append(id);
    detail::JsonWriter w(out);
    detail::append_classification(c, options.render, w);
    return;
  } catch (const InputError& err) {
    if (write_error(out, id, err.what())) return;
  } catch (const std::bad_alloc&) {
  } catch (const std::exception& err) {
    try {
      internal = std::string("internal error: ") + err.what();
    } catch (...) {
    }
    if (!internal.empty() && write_error(out, id, internal)) return;
  } catch (...) {
    if (write_error(out, id, "internal error: unknown exception")) return;
  }
  // Out of memory: that line's error, with its id when it can be echoed (the partial answer's
  // capacity is reused), else with the line number (doc/cli.md, "Out of memory").
  if (write_error(out, id, kOutOfMemoryMessage)) return;
  char number[24];
  const auto end = std::to_chars(number, number + sizeof number, line_number).ptr;
  if (write_error(out, std::string_view(number, static_cast<std::size_t>(end - number)), kOutOfMemoryNoIdMessage))
    return;
  out.clear();  // not even that: the caller writes its own line (doc/cli.md)
}

std::string answer_batch_line(std::string_view line, long line_number, const BatchOptions& options) {
  std::string out;
  answer_batch_line(line, line_number, options, out);
  return out;
}

}  // namespace relpos::io
