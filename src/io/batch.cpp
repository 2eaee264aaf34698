// One batch line (batch.hpp): the reader shared by `relpos batch`, `relpos scene`, `relpos verify`
// and the fuzzer.
//
// The top-level object of a line is scanned once with the lexer (json_lexer.hpp): each member's
// value is located as a span of the text, so that the id is echoed byte for byte, duplicate keys are
// seen, and "comment" is validated by a pass that stores nothing. The two quadrics are read by the
// fast reader (fast_quadric.hpp: common forms, short numbers, straight to double enclosures; for a
// "quadric", an ellipsoid's or an elliptic paraboloid's matrix) during the scan, or else parsed into (small, bounded)
// trees by the general reader (quadric_json.hpp), which words every error.
#include "io/batch.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include "algebra/pair_size.hpp"
#include "io/fast_quadric.hpp"
#include "io/general_io.hpp"
#include "io/json_lexer.hpp"
#include "io/json_tree.hpp"
#include "io/quadric_json.hpp"
#include "relpos/error.hpp"

namespace relpos::detail::io {
namespace {

/// Entries allowed per array or object inside a quadric (a 4x4 matrix has 4 rows of 4).
constexpr std::size_t kMaxQuadricEntries = 16;

/// The message of a line that is not JSON, from the parser (columns count from the line's start).
[[noreturn]] void invalid_json(std::string_view line) {
  validate_json(line);
  throw InputError("invalid JSON: expected one JSON object");
}

struct Member {
  std::string_view key;  ///< one of the known keys
  std::string_view value;
  bool fast = false;  ///< a quadric the fast reader took (into the line's quadric of that key)
};

/// The name of a key given as its JSON text "...": the text between the quotes when it is plain
/// (what every key of a well-formed line is), else the general parser's reading, kept in `storage`.
std::string_view key_name(std::string_view key_text, std::string& storage) {
  if (plain_string_end(key_text, 0) == key_text.size()) return key_text.substr(1, key_text.size() - 2);
  storage = Json::parse(key_text).get<std::string>();
  return storage;
}

/// read_batch_line, step by step. With `id`, the id is not copied into out.id: *id is set to its
/// text instead (a view into the line, or of out.id when it is the line number or re-encoded),
/// before anything is thrown. The same for `meta` and out.meta (empty until the members are scanned).
class LineReader {
 public:
  LineReader(std::string_view line, long number, const BatchOptions& options, const Paraboloid* fixed,
             const GeneralPairSize* fixed_quadric, BatchLine& out, std::string_view* id, std::string_view* meta)
      : line_(line),
        number_(number),
        options_(options),
        fixed_(fixed),
        fixed_quadric_(fixed_quadric),
        scene_(fixed || fixed_quadric),
        out_(out),
        id_(id),
        meta_(meta) {}

  void read() {
    scan();
    validate_members();
    take_text("id", out_.id, id_);
    take_text("meta", out_.meta, meta_);
    // The second body's tree: the paraboloid's, or a general quadric's (read into the same tree).
    Json ellipsoid, paraboloid;
    general_quadrics(ellipsoid, paraboloid);
    if (!duplicate_.empty()) throw InputError("duplicate key \"" + duplicate_ + "\"");
    if (!unknown_.empty())
      throw InputError("unknown key \"" + unknown_ + "\"" +
                       (scene_ ? " (a scene line takes \"id\", \"ellipsoid\", \"meta\" and \"comment\")"
                               : " (a line takes \"id\", \"ellipsoid\", \"paraboloid\" or \"quadric\", \"meta\""
                                 " and \"comment\")"));
    if (!out_.ellipsoid && ellipsoid.is_null()) throw InputError("ellipsoid: missing");
    if (given("quadric")) return read_quadric(ellipsoid, paraboloid);
    if (fixed_quadric_) {  // a scene line against a general quadric (doc/cli.md, "relpos scene")
      if (!out_.ellipsoid) out_.ellipsoid = ellipsoid_from_tree(ellipsoid, "ellipsoid");
      fixed_quadric_->check(*out_.ellipsoid);
      return;
    }
    if (!fixed_ && !out_.paraboloid && paraboloid.is_null()) throw InputError("paraboloid: missing");
    if (!out_.ellipsoid) out_.ellipsoid = ellipsoid_from_tree(ellipsoid, "ellipsoid");
    if (!fixed_ && !out_.paraboloid) out_.paraboloid = paraboloid_from_tree(paraboloid, "paraboloid");
    relpos::detail::check_normalized_pair_size(*out_.ellipsoid, fixed_ ? *fixed_ : *out_.paraboloid,
                                               options_.size_limit);  // doc/cli.md, Limits
  }

 private:
  /// Whether the line has a member with this key. The keys, not the trees, say which bodies were
  /// given: a value may be null, and the fast reader leaves no tree.
  bool given(std::string_view key) const {
    for (std::size_t m = 0; m < count_; ++m)
      if (members_[m].key == key) return true;
    return false;
  }

  /// A general quadric in place of the paraboloid (src/io/general_io.hpp; doc/cli.md, "General
  /// quadrics"), its tree in `second`; the size limit as check_normalized_pair_size words it.
  void read_quadric(const Json& ellipsoid, const Json& second) {
    if (given("paraboloid")) throw InputError("a line takes \"paraboloid\" or \"quadric\", not both");
    if (!out_.ellipsoid) out_.ellipsoid = ellipsoid_from_tree(ellipsoid, "ellipsoid");
    if (!out_.quadric) out_.quadric = quadric_from_json(second, "quadric");
    check_general_pair_size(*out_.ellipsoid, *out_.quadric, options_.size_limit);  // doc/cli.md, Limits
  }

  void set_id(std::string_view text) {
    if (id_) *id_ = text;
  }

  /// The top-level object's members; every structural error is reported by the parser's message on
  /// the whole line.
  void scan() {
    std::size_t i = skip_space(line_, 0);
    if (i == line_.size()) throw InputError("empty line");
    if (line_[i] != '{') {
      validate_json(line_);  // not JSON, or JSON that is not an object
      throw InputError(scene_ ? "expected a JSON object {\"id\": ..., \"ellipsoid\": ...}"
                              : "expected a JSON object {\"id\": ..., \"ellipsoid\": ..., \"paraboloid\": ...}");
    }
    i = skip_space(line_, i + 1);
    if (i < line_.size() && line_[i] == '}') {
      i = skip_space(line_, i + 1);
    } else {
      for (;;) {
        i = skip_space(line_, member(i));
        if (i < line_.size() && line_[i] == ',') {
          i = skip_space(line_, i + 1);
          continue;
        }
        if (i < line_.size() && line_[i] == '}') {
          i = skip_space(line_, i + 1);
          break;
        }
        invalid_json(line_);
      }
    }
    if (i != line_.size()) invalid_json(line_);
  }

  /// The member whose key starts at i: returns the end of its value. A quadric is read by the fast
  /// reader as the line is scanned: its end comes with it.
  std::size_t member(std::size_t i) {
    if (i >= line_.size() || line_[i] != '"') invalid_json(line_);
    // A plain key (every key of a well-formed line) is its text between the quotes: one pass.
    std::size_t key_end = plain_string_end(line_, i);
    std::string_view key;
    if (key_end != std::string_view::npos) {
      key = line_.substr(i + 1, key_end - i - 2);
    } else {
      key_end = string_end(line_, i);
      if (key_end == std::string_view::npos) invalid_json(line_);
      try {
        key = key_name(line_.substr(i, key_end - i), key_storage_);
      } catch (const nlohmann::json::exception&) {
        invalid_json(line_);
      }
    }
    i = skip_space(line_, key_end);
    if (i >= line_.size() || line_[i] != ':') invalid_json(line_);
    i = skip_space(line_, i + 1);
    std::size_t end = std::string_view::npos;
    bool taken = false;
    if (key == "ellipsoid")
      taken = fast_ellipsoid_at(line_.substr(i), options_.numbers_as_doubles, end, out_.ellipsoid);
    else if (key == "paraboloid" && !scene_)
      taken = fast_paraboloid_at(line_.substr(i), options_.numbers_as_doubles, end, out_.paraboloid);
    else if (key == "quadric" && !scene_)
      taken = fast_quadric_at(line_.substr(i), options_.numbers_as_doubles, end, out_.quadric);
    end = end == std::string_view::npos ? value_end(line_, i) : i + end;
    if (end == std::string_view::npos) invalid_json(line_);
    const std::string_view value = line_.substr(i, end - i);
    // nlohmann skips a byte order mark at the start of what it parses; inside a line it is not JSON.
    if (value.substr(0, 3) == "\xEF\xBB\xBF") invalid_json(line_);
    keep(key, value, taken);
    return end;
  }

  /// A known member kept (a second one of a key noted), an unknown one noted and validated.
  void keep(std::string_view key, std::string_view value, bool taken) {
    static constexpr std::string_view kKeys[] = {"id", "ellipsoid", "paraboloid", "comment", "meta", "quadric"};
    bool known = false;
    for (const std::string_view k : kKeys) {
      if (key != k) continue;
      if (scene_ && (k == "paraboloid" || k == "quadric")) break;  // not a key of a scene line
      known = true;
      for (std::size_t m = 0; m < count_; ++m)
        if (members_[m].key == k && duplicate_.empty()) duplicate_ = key;
      if (count_ < kMembers) members_[count_++] = Member{k, value, taken};
      general_ = general_ || (!taken && (k == "ellipsoid" || k == "paraboloid" || k == "quadric"));
      break;
    }
    if (known) return;
    if (unknown_.empty()) unknown_ = key.substr(0, 40);
    try {
      if (!plainly_valid(value)) validate_json(value, 1);  // not stored; still JSON within the limits
    } catch (const JsonSyntaxError&) {
      invalid_json(line_);
    }
  }

  /// The id, the comment and the meta: valid JSON, not stored (the id and the meta are kept as their text).
  void validate_members() {
    for (std::size_t m = 0; m < count_; ++m) {
      if (members_[m].key == "ellipsoid" || members_[m].key == "paraboloid" || members_[m].key == "quadric") continue;
      if (plainly_valid(members_[m].value)) continue;
      try {
        validate_json(members_[m].value, 1);
      } catch (const JsonSyntaxError&) {
        invalid_json(line_);  // reported on the whole line, with its columns
      }
    }
  }

  /// The text of the member `key` (the id or the meta), echoed byte for byte: into `stored`, or with
  /// `view`, *view set to it (not copied; a view of `stored` when it is re-encoded).
  void take_text(std::string_view key, std::string& stored, std::string_view* view) {
    for (std::size_t m = count_; m-- > 0;)  // the first one when there are two (an error below)
      if (members_[m].key == key) {
        const std::string_view value = members_[m].value;
        if (!valid_utf8(value)) {
          stored = dump_json(parse_json_exact(value));
          if (view) *view = stored;
        } else if (view) {
          *view = value;  // byte for byte, not copied
        } else {
          stored.assign(value.data(), value.size());  // byte for byte
        }
      }
  }

  /// The quadrics the fast reader left: small bounded trees, numbers exact (or the nearest doubles).
  void general_quadrics(Json& ellipsoid, Json& paraboloid) {
    if (!general_) return;  // the fast reader took every quadric (most lines)
    JsonReadOptions read;
    read.doubles = options_.numbers_as_doubles;
    read.max_elements = kMaxQuadricEntries;
    read.start_depth = 1;
    for (std::size_t m = 0; m < count_; ++m) {
      const Member& x = members_[m];
      if ((x.key != "ellipsoid" && x.key != "paraboloid" && x.key != "quadric") || x.fast) continue;
      try {
        (x.key == "ellipsoid" ? ellipsoid : paraboloid) = parse_json(x.value, read);
      } catch (const JsonSyntaxError&) {
        out_.id = std::to_string(number_);  // as for any line that is not JSON
        set_id(out_.id);
        invalid_json(line_);
      } catch (const InputError& e) {
        throw InputError(std::string(x.key) + ": " + e.what());  // a limit: nesting, entries, duplicate key
      }
    }
  }

  std::string_view line_;
  long number_;
  const BatchOptions& options_;
  const Paraboloid* fixed_;
  const GeneralPairSize* fixed_quadric_;  ///< a scene's general quadric (then fixed_ is null)
  bool scene_;                            ///< a scene line: the second body is fixed
  BatchLine& out_;
  std::string_view* id_;
  std::string_view* meta_;
  static constexpr std::size_t kMembers = 6;  // one of each known key
  Member members_[kMembers];
  std::size_t count_ = 0;
  bool general_ = false;  ///< a quadric the fast reader left
  std::string unknown_, duplicate_, key_storage_;
};

}  // namespace

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

void read_line(std::string_view line, long line_number, const BatchOptions& options, const Paraboloid* fixed,
               const GeneralPairSize* fixed_quadric, BatchLine& out, std::string_view* id, std::string_view* meta) {
  out.id = std::to_string(line_number);
  if (id) *id = out.id;
  out.meta.clear();
  if (meta) *meta = std::string_view();
  out.ellipsoid.reset();  // the fast reader makes the quadrics here as the line is scanned
  out.paraboloid.reset();
  out.quadric.reset();
  const std::string_view normalized = normalize_line(line, line_number, options.max_line_bytes);
  LineReader(normalized, line_number, options, fixed, fixed_quadric, out, id, meta).read();
}

}  // namespace

void read_batch_line(std::string_view line, long line_number, const BatchOptions& options, const Paraboloid* fixed,
                     BatchLine& out, std::string_view* id, std::string_view* meta) {
  read_line(line, line_number, options, fixed, nullptr, out, id, meta);
}

void read_batch_line(std::string_view line, long line_number, const BatchOptions& options, const GeneralPairSize& fixed,
                     BatchLine& out, std::string_view* id, std::string_view* meta) {
  read_line(line, line_number, options, nullptr, &fixed, out, id, meta);
}

}  // namespace relpos::detail::io
