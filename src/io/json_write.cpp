#include "io/json_write.hpp"

#include <gmp.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

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

namespace {

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// The 19 decimal digits of v < 10^19 with leading zeros, at p[0..19).
void put_19_digits(char* p, std::uint64_t v) {
  for (int i = 17; i >= 1; i -= 2) {
    const std::uint64_t q = v / 100;
    std::memcpy(p + i, kDigitPairs + 2 * (v - 100 * q), 2);
    v = q;
  }
  p[0] = static_cast<char>('0' + v);
}

/// The decimal text of z, as mpz_get_str(.., 10, z) writes it, appended to out: the limbs divided by
/// 10^19 (one mpn_divrem_1 a chunk, as GMP's basecase) and each chunk written two digits at a time,
/// straight into the output (about twice as fast as mpz_get_str on the few-hundred-bit numbers of a
/// report). Longer numbers: mpz_get_str itself.
void append_decimal(std::string& out, mpz_srcptr z) {
  constexpr std::size_t kMaxLimbs = 64;
  constexpr mp_limb_t kChunk = 10000000000000000000UL;  // 10^19 < 2^64
  static_assert(sizeof(mp_limb_t) == sizeof(std::uint64_t), "64-bit limbs");
  const std::size_t size = mpz_size(z);
  if (size > kMaxLimbs) {
    const std::size_t at = out.size();
    out.resize(at + mpz_sizeinbase(z, 10) + 2);
    mpz_get_str(&out[at], 10, z);
    out.resize(at + std::char_traits<char>::length(&out[at]));
    return;
  }
  if (mpz_sgn(z) < 0) out += '-';
  mp_limb_t t[kMaxLimbs];
  std::uint64_t chunk[kMaxLimbs + 1];  // 10^19 > 2^63: at most one chunk a limb, and one more
  std::size_t chunks = 0;
  auto n = static_cast<mp_size_t>(size);
  if (n > 0) std::memcpy(t, mpz_limbs_read(z), size * sizeof(mp_limb_t));
  for (; n > 1; n -= t[n - 1] == 0) chunk[chunks++] = mpn_divrem_1(t, 0, t, n, kChunk);
  std::uint64_t lead = n == 1 ? t[0] : 0;  // the quotient left: non-zero unless z is
  if (lead >= kChunk) {
    chunk[chunks++] = lead % kChunk;
    lead /= kChunk;
  }
  char first[20];
  out.append(first, static_cast<std::size_t>(std::to_chars(first, first + sizeof first, lead).ptr - first));
  const std::size_t at = out.size();
  out.resize(at + 19 * chunks);
  char* p = &out[at];
  for (std::size_t i = chunks; i-- > 0; p += 19) put_19_digits(p, chunk[i]);
}

}  // namespace

void JsonWriter::rational(const Rational& q) {
  // Digits straight into the output from the mpq's own integers: no temporary strings for the
  // longest values of a report, and no copies of the numerator and denominator.
  const mpq_srcptr x = q.mpq();
  out_ += '"';
  append_decimal(out_, mpq_numref(x));
  if (mpz_cmp_ui(mpq_denref(x), 1) != 0) {
    out_ += '/';
    append_decimal(out_, mpq_denref(x));
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
