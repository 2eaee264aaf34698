// The one JSON lexer of src/io (RFC 8259 tokens): white space, strings, numbers and the extent of a
// value, read in place from the text. The batch line's scan (batch_line.cpp), the fast reader
// (fast_quadric.cpp) and the quoting of numbers beyond double range (json_read.cpp) all read their
// tokens here; the general parser (nlohmann) then words every error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace relpos::detail::io {

inline bool is_json_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
inline bool is_digit(char c) { return static_cast<unsigned>(c - '0') <= 9; }

/// The first index at or after i that is not white space.
inline std::size_t skip_space(std::string_view s, std::size_t i) {
  while (i < s.size() && is_json_space(s[i])) ++i;
  return i;
}

/// End of the string token starting at s[i] == '"' (structure only: escapes skipped), or npos.
inline std::size_t string_end(std::string_view s, std::size_t i) {
  for (++i; i < s.size(); ++i) {
    if (s[i] == '\\')
      ++i;
    else if (s[i] == '"')
      return i + 1;
  }
  return std::string_view::npos;
}

/// End of the string token starting at s[i] == '"' when it is plain -- no escape, control character
/// or non-ASCII byte, what every key of a well-formed line is --, else npos.
inline std::size_t plain_string_end(std::string_view s, std::size_t i) {
  for (++i; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"') return i + 1;
    if (c < 0x20 || c >= 0x80 || c == '\\') return std::string_view::npos;
  }
  return std::string_view::npos;
}

/// A string token (quotes included) that is certainly valid JSON: escapes well formed, no control
/// character, valid UTF-8, \u escapes of surrogates only as pairs.
bool valid_string(std::string_view token);

/// Whether the bytes are UTF-8 in its loose form (lead and continuation bytes only).
bool valid_utf8(std::string_view s);

/// End of the JSON value starting at s[i] (structure only: brackets matched outside strings; the
/// span is validated by whoever reads it), or npos.
inline std::size_t value_end(std::string_view s, std::size_t i) {
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
  while (i < s.size() && !is_json_space(s[i]) && s[i] != ',' && s[i] != '}' && s[i] != ']') ++i;
  return i == start ? std::string_view::npos : i;
}

constexpr std::uint64_t kNotDigits = ~std::uint64_t(0);

/// The value of the eight decimal digits at p, or kNotDigits when one of the bytes is not a digit
/// (eight digits at once: the long numbers of printed doubles are most of a line's bytes).
inline std::uint64_t eight_digits(const char* p) {
  std::uint64_t v = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  std::memcpy(&v, p, 8);  // one load (the loop below is not always folded into one)
#else
  for (int k = 7; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(p[k]);  // p[0] in the low byte
#endif
  // Each byte is 0x30..0x39: its high nibble is 3 and adding 6 does not carry out of the low nibble.
  if (((v & 0xF0F0F0F0F0F0F0F0) | (((v + 0x0606060606060606) & 0xF0F0F0F0F0F0F0F0) >> 4)) != 0x3333333333333333)
    return kNotDigits;
  v = (v & 0x0F0F0F0F0F0F0F0F) * 2561 >> 8;                // pairs: 10 a + b in each 16-bit lane
  v = (v & 0x00FF00FF00FF00FF) * 6553601 >> 16;            // quadruples in each 32-bit lane
  return (v & 0x0000FFFF0000FFFF) * 42949672960001 >> 32;  // the eight digits
}

/// What scan_number tells about a number's parts. A sink that keeps nothing (NumberGrammar) checks
/// the grammar alone; one that returns false from a digit stops the scan (the number is refused).
///   void negative();                                   a leading minus
///   bool wants_eight() const;                          eight digits at once welcome now
///   bool eight(std::uint64_t value, bool fraction);    eight digits of the integer or fraction part
///   bool digit(unsigned d, bool fraction);             one digit (not the integer part's lone 0)
///   bool exponent_digit(unsigned d);                   one digit of the exponent
///   void exponent_sign(bool negative);                 after the exponent's digits
struct NumberGrammar {
  void negative() {}
  bool wants_eight() const { return true; }
  bool eight(std::uint64_t, bool) { return true; }
  bool digit(unsigned, bool) { return true; }
  bool exponent_digit(unsigned) { return true; }
  void exponent_sign(bool) {}
};

/// The digits from p on (the first one a digit), to the sink; the end, or nullptr if it refused.
/// Inlined into its caller (as scan_number): the sink's counters then stay in registers, where a
/// call would keep them in memory (the fast reader's numbers are most of a batch line's bytes).
template <class Sink>
[[gnu::always_inline]] inline const char* scan_digits(const char* p, const char* last, Sink& sink, bool fraction) {
  for (;;) {
    if (sink.wants_eight() && last - p >= 8) {
      if (const std::uint64_t block = eight_digits(p); block != kNotDigits) {
        if (!sink.eight(block, fraction)) return nullptr;
        p += 8;
        continue;
      }
    }
    if (p == last || !is_digit(*p)) return p;
    if (!sink.digit(static_cast<unsigned>(*p++ - '0'), fraction)) return nullptr;
  }
}

/// The JSON number at p: -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?, its parts handed
/// to `sink`. Returns the end of the token (what follows is the caller's to check), or nullptr when
/// the text at p is not a number or the sink refused it.
template <class Sink>
[[gnu::always_inline]] inline const char* scan_number(const char* p, const char* last, Sink& sink) {
  if (p < last && *p == '-') {
    sink.negative();
    ++p;
  }
  if (p == last || !is_digit(*p)) return nullptr;
  if (*p == '0')
    ++p;
  else if (!(p = scan_digits(p, last, sink, false)))
    return nullptr;
  if (p < last && *p == '.') {
    ++p;
    if (p == last || !is_digit(*p) || !(p = scan_digits(p, last, sink, true))) return nullptr;
  }
  if (p < last && (*p == 'e' || *p == 'E')) {
    ++p;
    bool negative = false;
    if (p < last && (*p == '+' || *p == '-')) negative = *p++ == '-';
    if (p == last || !is_digit(*p)) return nullptr;
    for (; p < last && is_digit(*p); ++p)
      if (!sink.exponent_digit(static_cast<unsigned>(*p - '0'))) return nullptr;
    sink.exponent_sign(negative);
  }
  return p;
}

/// Whether the text is exactly one JSON number, of any length.
inline bool is_number(std::string_view v) {
  NumberGrammar grammar;
  return scan_number(v.data(), v.data() + v.size(), grammar) == v.data() + v.size();
}

/// An id, comment or unknown member's value that is certainly one valid JSON value, checked in
/// place: a string or a number of any length (the parser's lexer would hold a copy of a long token,
/// twice). Anything else goes through the validating parser, which stores one token at a time.
inline bool plainly_valid(std::string_view v) {
  return !v.empty() && (v.front() == '"' ? valid_string(v) : is_number(v));
}

}  // namespace relpos::detail::io
