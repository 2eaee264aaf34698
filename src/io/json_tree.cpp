#include "io/json_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/json_lexer.hpp"
#include "relpos/io.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail::io {
namespace {

/// "[json.exception.parse_error.101] parse error at ..." -> "parse error at ...".
std::string strip_exception_prefix(const std::string& what) {
  if (!what.empty() && what[0] == '[') {
    auto close = what.find("] ");
    if (close != std::string::npos) return what.substr(close + 2);
  }
  return what;
}

/// The nesting depth of a parse, limited to kMaxJsonDepth: copying and printing a JSON value recurse,
/// so a line of 100000 '[' would otherwise overflow the stack when its "id" is echoed.
class DepthLimit {
 protected:
  explicit DepthLimit(std::size_t start_depth) : depth_(start_depth) {}
  bool enter() {
    if (++depth_ > kMaxJsonDepth)
      throw InputError("invalid JSON: nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  }
  bool leave() {
    --depth_;
    return true;
  }

 private:
  std::size_t depth_;
};

/// The DOM builder of nlohmann::json, except that a floating-point number is stored as a string
/// holding its original text (the lexer hands the text to the SAX callback), so that no number is
/// ever rounded to a double; with `doubles`, every number becomes the exact value of the IEEE double
/// nearest its text instead. Duplicate keys are rejected; with max_elements, so are arrays and
/// objects of more entries (a quadric needs at most 16), which bounds the DOM of a batch line.
class ExactSax : public nlohmann::detail::json_sax_dom_parser<Json>, DepthLimit {
 public:
  using Base = nlohmann::detail::json_sax_dom_parser<Json>;
  ExactSax(Json& document, const JsonReadOptions& options)
      : Base(document, /*allow_exceptions=*/true), DepthLimit(options.start_depth), options_(options) {}
  bool number_float(Json::number_float_t rounded, const Json::string_t& text) {
    if (!counted()) return false;
    Json::string_t copy = options_.doubles ? double_text(rounded) : text;
    return Base::string(copy);
  }
  bool number_integer(Json::number_integer_t v) {
    if (!counted()) return false;
    if (options_.doubles && (v > (std::int64_t(1) << 53) || v < -(std::int64_t(1) << 53))) {
      Json::string_t copy = double_text(static_cast<double>(v));
      return Base::string(copy);
    }
    return Base::number_integer(v);
  }
  bool number_unsigned(Json::number_unsigned_t v) {
    if (!counted()) return false;
    if (options_.doubles && v > (std::uint64_t(1) << 53)) {
      Json::string_t copy = double_text(static_cast<double>(v));
      return Base::string(copy);
    }
    return Base::number_unsigned(v);
  }
  bool null() { return counted() && Base::null(); }
  bool boolean(bool v) { return counted() && Base::boolean(v); }
  bool string(Json::string_t& v) { return counted() && Base::string(v); }
  bool key(Json::string_t& k) {
    auto& keys = keys_.back();
    if (std::find(keys.begin(), keys.end(), k) != keys.end())
      throw InputError("invalid JSON: duplicate key \"" + (k.size() > 40 ? k.substr(0, 40) + "..." : k) + "\"");
    keys.push_back(k);
    return Base::key(k);
  }
  // Nesting is limited (DepthLimit).
  bool start_object(std::size_t n) { return open() && Base::start_object(n); }
  bool end_object() { return close() && Base::end_object(); }
  bool start_array(std::size_t n) { return open() && Base::start_array(n); }
  bool end_array() { return close() && Base::end_array(); }

 private:
  static Json::string_t double_text(double d) {
    if (!std::isfinite(d)) return "inf";  // parse_rational rejects it with the field's path
    return to_string(exact_rational(d));
  }
  /// One more entry in the innermost array or object.
  bool counted() {
    if (!counts_.empty() && options_.max_elements != 0 && ++counts_.back() > options_.max_elements)
      throw InputError("an array or object of more than " + std::to_string(options_.max_elements) +
                       " entries (a quadric needs at most 16: a 4x4 matrix)");
    return true;
  }
  /// A new array or object: counted in its parent, one level deeper, with its own keys and count.
  bool open() {
    if (!counted() || !enter()) return false;
    keys_.emplace_back();
    counts_.push_back(0);
    return true;
  }
  bool close() {
    keys_.pop_back();
    counts_.pop_back();
    return leave();
  }
  JsonReadOptions options_;
  std::vector<std::vector<std::string>> keys_;
  std::vector<std::size_t> counts_;
};

/// Validates JSON without storing anything (memory independent of the text's size): ignored content.
class ValidatingSax : public nlohmann::json_sax<Json>, DepthLimit {
 public:
  explicit ValidatingSax(std::size_t start_depth) : DepthLimit(start_depth) {}
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return enter(); }
  bool key(string_t&) override { return true; }
  bool end_object() override { return leave(); }
  bool start_array(std::size_t) override { return enter(); }
  bool end_array() override { return leave(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    if (e.id == 406) {  // a number beyond double range: nlohmann stops here
      overflow = true;
      return false;
    }
    throw JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()));
  }
  bool overflow = false;  ///< a number beyond double range stopped the parse (valid JSON so far)
};

/// Length of a JSON number token at the start of s (the lexer's grammar) that no further number
/// character follows, or 0 if there is none.
std::size_t json_number_length(std::string_view s) {
  NumberGrammar grammar;
  const char* const end = scan_number(s.data(), s.data() + s.size(), grammar);
  if (!end) return 0;
  const std::size_t i = static_cast<std::size_t>(end - s.data());
  if (i < s.size() && std::string_view("0123456789.eE+-").find(s[i]) != std::string_view::npos) return 0;
  return i;
}

/// The text with every well-formed JSON number outside strings turned into a string holding it.
/// Malformed tokens are left alone for the parser to report.
std::string quote_numbers(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 16);
  bool in_string = false;
  for (std::size_t i = 0; i < text.size();) {
    const char ch = text[i];
    if (in_string) {
      out += ch;
      if (ch == '\\' && i + 1 < text.size()) {
        out += text[i + 1];
        i += 2;
        continue;
      }
      if (ch == '"') in_string = false;
      ++i;
      continue;
    }
    if (ch == '"') {
      in_string = true;
      out += ch;
      ++i;
      continue;
    }
    if (ch == '-' || (ch >= '0' && ch <= '9')) {
      const std::string_view token = text.substr(i, json_number_length(text.substr(i)));
      if (!token.empty()) {
        // Floats and integers too long for 64 bits become strings; other integers stay as they are.
        const bool quote = token.find_first_of(".eE") != std::string_view::npos || token.size() > 18;
        if (quote) out += '"';
        out += token;
        if (quote) out += '"';
        i += token.size();
        continue;
      }
    }
    out += ch;
    ++i;
  }
  return out;
}

}  // namespace

Json parse_json(std::string_view text, const JsonReadOptions& options) {
  Json root;
  try {
    ExactSax sax(root, options);
    Json::sax_parse(text.begin(), text.end(), &sax);
    return root;
  } catch (const nlohmann::json::out_of_range& e) {
    // "number overflow" (406): a number beyond the range of a double, which nlohmann checks before
    // handing us the text. Quote the number tokens and parse again; they are exact all the same.
    if (e.id != 406) throw JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()));
    if (options.doubles) throw InputError("invalid JSON: a number beyond the range of a double (--numbers double)");
  } catch (const nlohmann::json::exception& e) {
    throw JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()));
  }
  const std::string quoted = quote_numbers(text);
  root = Json();
  try {
    ExactSax sax(root, options);
    Json::sax_parse(quoted.begin(), quoted.end(), &sax);
  } catch (const nlohmann::json::exception& e) {
    throw JsonSyntaxError("invalid JSON: " + strip_exception_prefix(e.what()) +
                          " (columns counted after quoting the numbers beyond double range)");
  }
  return root;
}

void validate_json(std::string_view text, std::size_t start_depth) {
  ValidatingSax sax(start_depth);
  Json::sax_parse(text.begin(), text.end(), &sax);
  if (!sax.overflow) return;
  const std::string quoted = quote_numbers(text);  // rare: numbers beyond double range
  ValidatingSax again(start_depth);
  Json::sax_parse(quoted.begin(), quoted.end(), &again);
}

std::string dump_json(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace relpos::detail::io
