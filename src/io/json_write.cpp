#include "io/json_write.hpp"

#include <gmp.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

namespace relpos::io::detail {

void JsonWriter::key(std::string_view name) {
  out_ += '"';
  out_.append(name);
  out_ += "\":";
}

void JsonWriter::string(std::string_view s) {
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c >= 0x80 || c == '"' || c == '\\') {  // escapes or UTF-8: the general writer
      out_ += dump_json(nlohmann::ordered_json(std::string(s)));
      return;
    }
  }
  out_ += '"';
  out_.append(s);
  out_ += '"';
}

void JsonWriter::integer(long n) { out_ += std::to_string(n); }

void JsonWriter::number(double x) {
  // What dump_json writes for a double (nlohmann's serializer: null when not finite, else its
  // shortest round-trip digits), without a json value and a string per number.
  if (!std::isfinite(x)) {
    out_ += "null";
    return;
  }
  std::array<char, 64> digits;  // the serializer's buffer size
  const char* end = nlohmann::detail::to_chars(digits.data(), digits.data() + digits.size(), x);
  out_.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

void JsonWriter::rational(const Rational& q) {
  // mpz_get_str straight into the output from the mpq's own integers: no temporary strings for the
  // longest values of a report, and no copies of the numerator and denominator.
  auto put = [this](mpz_srcptr z) {
    const std::size_t at = out_.size();
    out_.resize(at + mpz_sizeinbase(z, 10) + 2);
    mpz_get_str(&out_[at], 10, z);
    out_.resize(at + std::char_traits<char>::length(&out_[at]));
  };
  const mpq_srcptr x = q.mpq();
  out_ += '"';
  put(mpq_numref(x));
  if (mpz_cmp_ui(mpq_denref(x), 1) != 0) {
    out_ += '/';
    put(mpq_denref(x));
  }
  out_ += '"';
}

void JsonWriter::rationals(const Rational* q, std::size_t n) {
  out_ += '[';
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out_ += ',';
    rational(q[i]);
  }
  out_ += ']';
}

}  // namespace relpos::io::detail
