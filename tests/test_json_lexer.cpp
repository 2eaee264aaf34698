// json_lexer.hpp, the one JSON lexer of src/io, against the grammar and against the general parser:
// numbers against RFC 8259's number grammar (a regular expression), with the digits a sink is
// handed; strings: valid_string only says yes to what nlohmann parses as a string, and says yes to
// every string nlohmann writes; value_end finds the end of every value nlohmann writes, whatever
// follows it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <string>

#include "io/json_lexer.hpp"

namespace {

using relpos::detail::io::scan_number;

/// Counts what scan_number hands to a sink: the digits of the integer and fraction parts (blocks
/// of eight counted as eight) and of the exponent.
struct Counting {
  int integer = 0, fraction = 0, exponent = 0;
  bool minus = false, exponent_minus = false;
  void negative() { minus = true; }
  bool wants_eight() const { return true; }
  bool eight(std::uint64_t, bool f) {
    (f ? fraction : integer) += 8;
    return true;
  }
  bool digit(unsigned, bool f) {
    ++(f ? fraction : integer);
    return true;
  }
  bool exponent_digit(unsigned) {
    ++exponent;
    return true;
  }
  void exponent_sign(bool m) { exponent_minus = m; }
};

std::string random_text(std::mt19937_64& rng, const std::string& alphabet, std::size_t most) {
  std::string s(rng() % (most + 1), ' ');
  for (char& c : s) c = alphabet[rng() % alphabet.size()];
  return s;
}

}  // namespace

TEST_CASE("scan_number: RFC 8259's number grammar, and every digit handed to the sink", "[json_lexer]") {
  const std::regex grammar("-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?");
  std::mt19937_64 rng(3);
  int numbers = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    // Mostly digits, so that long runs (blocks of eight) and valid numbers are frequent.
    const std::string s = random_text(rng, trial % 2 ? "0123456789.eE+-" : "01234567890123456789.e-", 30);
    const bool valid = std::regex_match(s, grammar);
    CAPTURE(s);
    REQUIRE(relpos::detail::io::is_number(s) == valid);
    Counting c;
    const char* end = scan_number(s.data(), s.data() + s.size(), c);
    if (end) REQUIRE(std::regex_match(std::string(s.data(), end), grammar));  // a number as far as it goes
    if (!valid) continue;
    ++numbers;
    // The digits handed over are the text's, but the integer part's lone 0.
    const std::size_t dot = s.find('.'), e = s.find_first_of("eE");
    const std::size_t int_begin = s[0] == '-' ? 1 : 0, int_end = std::min({dot, e, s.size()});
    const int int_digits = static_cast<int>(int_end - int_begin);
    REQUIRE(c.integer == (s[int_begin] == '0' ? 0 : int_digits));
    REQUIRE(c.fraction == (dot == std::string::npos ? 0 : static_cast<int>(std::min(e, s.size()) - dot - 1)));
    const std::size_t exp_digits = e == std::string::npos ? 0 : s.size() - e - 1 - (s[e + 1] == '+' || s[e + 1] == '-');
    REQUIRE(c.exponent == static_cast<int>(exp_digits));
    REQUIRE(c.minus == (s[0] == '-'));
    REQUIRE(c.exponent_minus == (e != std::string::npos && s[e + 1] == '-'));
  }
  CHECK(numbers > 1000);
}

TEST_CASE("valid_string: only strings the parser reads, and every string the writer writes", "[json_lexer]") {
  std::mt19937_64 rng(5);
  const std::string alphabet = std::string("ab\\\"u0D8dcF/nrt") + '\x01' + "\xC3\xA9\xED\xA0\x80\xF0\x9F\x98\x80\xFF";
  int accepted = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const std::string token = "\"" + random_text(rng, alphabet, 12) + "\"";
    CAPTURE(token);
    if (!relpos::detail::io::valid_string(token)) continue;
    ++accepted;
    nlohmann::json parsed;
    REQUIRE_NOTHROW(parsed = nlohmann::json::parse(token));
    REQUIRE(parsed.is_string());
  }
  CHECK(accepted > 1000);
  for (int trial = 0; trial < 20000; ++trial) {  // the writer's strings: any bytes, invalid UTF-8 replaced
    const std::string raw = random_text(rng, alphabet + '\n' + '\x7f', 16);
    const std::string dumped =
        nlohmann::json(raw).dump(-1, ' ', trial % 2 == 0, nlohmann::json::error_handler_t::replace);
    CAPTURE(dumped);
    REQUIRE(relpos::detail::io::valid_string(dumped));
    REQUIRE(relpos::detail::io::string_end(dumped + ",1", 0) == dumped.size());
  }
}

TEST_CASE("value_end: the end of every value the writer writes, whatever follows", "[json_lexer]") {
  std::mt19937_64 rng(7);
  // Random trees: nested arrays and objects of numbers, strings with escapes and brackets, literals.
  std::function<nlohmann::ordered_json(int)> tree = [&](int depth) -> nlohmann::ordered_json {
    switch (depth > 3 ? rng() % 4 : rng() % 6) {
      case 0:
        return static_cast<double>(static_cast<std::int64_t>(rng() % 2000000) - 1000000) / 1024;
      case 1:
        return random_text(rng, "ab[]{},:\"\\ \n", 8);
      case 2:
        return nullptr;
      case 3:
        return rng() % 2 == 0;
      case 4: {
        nlohmann::ordered_json a = nlohmann::ordered_json::array();
        for (int k = static_cast<int>(rng() % 4); k > 0; --k) a.push_back(tree(depth + 1));
        return a;
      }
      default: {
        nlohmann::ordered_json o = nlohmann::ordered_json::object();
        for (int k = static_cast<int>(rng() % 4); k > 0; --k) o[random_text(rng, "k]}\"", 3)] = tree(depth + 1);
        return o;
      }
    }
  };
  for (int trial = 0; trial < 20000; ++trial) {
    const std::string value = tree(0).dump(trial % 3 == 0 ? 1 : -1);
    for (const char* tail : {"", ",", "}", "]", " ,\"x\":1}"}) {
      CAPTURE(value, tail);
      const std::string text = "[" + value + tail;
      REQUIRE(relpos::detail::io::value_end(text, 1) == 1 + value.size());
    }
  }
}

TEST_CASE("valid_utf8: lead and continuation bytes", "[json_lexer]") {
  CHECK(relpos::detail::io::valid_utf8("plain ascii"));
  CHECK(relpos::detail::io::valid_utf8("\xC3\xA9t\xC3\xA9 \xF0\x9F\x98\x80"));
  CHECK_FALSE(relpos::detail::io::valid_utf8("\xC3"));
  CHECK_FALSE(relpos::detail::io::valid_utf8("\xC3("));
  CHECK_FALSE(relpos::detail::io::valid_utf8("\xFF"));
  CHECK_FALSE(relpos::detail::io::valid_utf8("\x80"));
}

TEST_CASE("eight_digits: the value of eight digits, or not digits, against the digits one by one", "[json_lexer]") {
  // The bytes next to the digits ('/' and ':'), a byte whose low nibble is a digit's and bytes with
  // the high bit set, so that the test of the whole word is checked byte by byte.
  std::mt19937_64 rng(11);
  const std::string alphabet = std::string("0123456789012345678901234567890123456789/:\x10p") + '\xB5' + '\xF9';
  int numbers = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    std::string eight(8, '0');
    for (char& c : eight) c = alphabet[rng() % alphabet.size()];
    const std::string text = std::string(trial % 8, '-') + eight;  // at every alignment
    std::uint64_t expected = 0;
    bool digits = true;
    for (const char c : eight) {
      digits = digits && c >= '0' && c <= '9';
      expected = expected * 10 + static_cast<std::uint64_t>(c - '0');
    }
    CAPTURE(eight);
    const std::uint64_t got = relpos::detail::io::eight_digits(text.data() + trial % 8);
    if (!digits) {
      REQUIRE(got == relpos::detail::io::kNotDigits);
      continue;
    }
    ++numbers;
    REQUIRE(got == expected);
  }
  CHECK(numbers > 1000);
  // The extremes.
  CHECK(relpos::detail::io::eight_digits("00000000") == 0);
  CHECK(relpos::detail::io::eight_digits("99999999") == 99999999);
  CHECK(relpos::detail::io::eight_digits("12345678") == 12345678);
  CHECK(relpos::detail::io::eight_digits("1234567:") == relpos::detail::io::kNotDigits);
  CHECK(relpos::detail::io::eight_digits("/2345678") == relpos::detail::io::kNotDigits);
}
