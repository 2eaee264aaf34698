#include "io/json_lexer.hpp"

#include <cctype>
#include <string>

namespace relpos::detail::io {
namespace {

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

/// The length of the escape at s[i] == '\\' when it is well formed (a \u escape of a high surrogate
/// only with its low one), else 0.
std::size_t escape_length(std::string_view s, std::size_t i) {
  if (i + 1 >= s.size()) return 0;
  const char e = s[i + 1];
  if (e != 'u') return std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos ? 0 : 2;
  if (!hex4(s, i + 2)) return 0;
  const unsigned long u = std::stoul(std::string(s.substr(i + 2, 4)), nullptr, 16);
  if (u >= 0xDC00 && u <= 0xDFFF) return 0;
  if (u < 0xD800 || u > 0xDBFF) return 6;
  if (i + 7 >= s.size() || s[i + 6] != '\\' || s[i + 7] != 'u' || !hex4(s, i + 8)) return 0;
  const unsigned long w = std::stoul(std::string(s.substr(i + 8, 4)), nullptr, 16);
  return w < 0xDC00 || w > 0xDFFF ? 0 : 12;
}

}  // namespace

bool valid_string(std::string_view v) {
  if (v.size() < 2 || v.front() != '"' || v.back() != '"') return false;
  const std::string_view s = v.substr(1, v.size() - 2);
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c < 0x20) return false;
    const std::size_t n = c == '\\' ? escape_length(s, i) : utf8_length(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

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

}  // namespace relpos::detail::io
