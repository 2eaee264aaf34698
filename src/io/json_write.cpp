#include "io/json_write.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/json_tree.hpp"

namespace relpos::detail::io {

void JsonWriter::key(std::string_view name) {
  char text[64];  // "name": in one append (the reports' names are short)
  if (name.size() + 3 > sizeof text) {
    out_.append(1, '"').append(name).append("\":");
    return;
  }
  text[0] = '"';
  std::memcpy(text + 1, name.data(), name.size());
  std::memcpy(text + 1 + name.size(), "\":", 2);
  out_.append(text, name.size() + 3);
}

void JsonWriter::string(std::string_view s) {
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c >= 0x80 || c == '"' || c == '\\') {  // escapes or UTF-8: the general writer
      out_ += dump_json(Json(std::string(s)));
      return;
    }
  }
  out_ += '"';
  out_.append(s);
  out_ += '"';
}

void JsonWriter::integer(long n) {
  char text[24];
  out_.append(text, static_cast<std::size_t>(std::to_chars(text, text + sizeof text, n).ptr - text));
}

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

__extension__ typedef unsigned __int128 Word;  // __extension__: a GCC/Clang builtin type under -Wpedantic

constexpr std::uint64_t kChunk = 10000000000000000000ULL;  // 10^19 < 2^64 <= 10^20, top bit set
/// floor((2^128 - 1) / 10^19) - 2^64: the reciprocal of the division below.
constexpr std::uint64_t kChunkInverse = static_cast<std::uint64_t>(~Word(0) / kChunk);

/// The quotient of r 2^64 + x by 10^19 (r < 10^19), r set to the remainder: the 2-by-1 division
/// by a normalized invariant divisor of Möller and Granlund ("Improved division by invariant
/// integers", 2011, Algorithm 4), which mpn_divrem_1 does after computing the reciprocal anew on
/// each call.
std::uint64_t divide_step(std::uint64_t& r, std::uint64_t x) {
  const Word p = Word(r) * kChunkInverse + ((Word(r) + 1) << 64 | x);
  auto q = static_cast<std::uint64_t>(p >> 64);
  r = x - q * kChunk;
  if (r > static_cast<std::uint64_t>(p)) {
    --q;
    r += kChunk;
  }
  if (r >= kChunk) {
    ++q;
    r -= kChunk;
  }
  return q;
}

/// q = a / 10^(19 K) for the n limbs of a (q may be a), and the K chunks of 19 digits divided
/// out, the lowest first: K divisions by 10^19 in one pass, each taking the previous one's
/// quotient limb by limb, so that their chains of dependent multiplications overlap.
template <int K>
void divide_by_chunks(mp_limb_t* q, const mp_limb_t* a, std::size_t n, std::uint64_t* chunks) {
  std::uint64_t r[K] = {};  // < 10^19
  for (std::size_t i = n; i-- > 0;) {
    std::uint64_t x = a[i];
    for (int k = 0; k < K; ++k) x = divide_step(r[k], x);
    q[i] = x;
  }
  std::copy(r, r + K, chunks);
}

/// The 8 decimal digits of x < 10^8 with leading zeros, as the bytes of one word (the first digit
/// first in memory): the four digit pairs, then the eight digits, split in parallel lanes.
std::uint64_t eight_digits(std::uint32_t x) {
  std::uint64_t v = x / 10000 | std::uint64_t(x % 10000) << 32;              // 2 lanes of 32 bits, < 10^4
  const std::uint64_t hundreds = (v * 10486 >> 20) & 0x0000007F0000007FULL;  // lane / 100, exact below 10^4
  v = hundreds | (v - 100 * hundreds) << 16;                                 // 4 lanes of 16 bits, < 100
  const std::uint64_t tens = (v * 103 >> 10) & 0x000F000F000F000FULL;        // lane / 10, exact below 179
  v = tens | (v - 10 * tens) << 8;                                           // 8 bytes, < 10
  v += 0x3030303030303030ULL;
#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  v = __builtin_bswap64(v);  // the first digit in the first byte in memory
#endif
  return v;
}

/// The 19 decimal digits of v < 10^19 with leading zeros, at p[0..19).
void put_19_digits(char* p, std::uint64_t v) {
  constexpr std::uint64_t kTen8 = 100000000, kTen16 = kTen8 * kTen8;
  const auto head = static_cast<unsigned>(v / kTen16);  // < 1000
  v %= kTen16;
  const std::uint64_t high = eight_digits(static_cast<std::uint32_t>(v / kTen8));
  const std::uint64_t low = eight_digits(static_cast<std::uint32_t>(v % kTen8));
  static_assert(sizeof high == 8, "a word of eight digits");
  p[0] = static_cast<char>('0' + head / 100);
  std::memcpy(p + 1, kDigitPairs + 2 * (head % 100), 2);
  std::memcpy(p + 3, &high, 8);  // the first digit first (eight_digits' byte order)
  std::memcpy(p + 11, &low, 8);
}

/// The decimal text of v < 10^19 without leading zeros ("0" for 0) at p; returns its end. The
/// digits are made as a chunk's (a word of eight when they fit) and the leading zeros skipped:
/// their count from the bit length of v (log10 2 ~ 1233 / 2^12) and one comparison.
char* put_lead(char* p, std::uint64_t v) {
  static constexpr std::array<std::uint64_t, 20> kPowers = [] {  // 10^0 .. 10^19
    std::array<std::uint64_t, 20> t{1};
    for (std::size_t k = 1; k < t.size(); ++k) t[k] = 10 * t[k - 1];
    return t;
  }();
  const auto below = static_cast<std::size_t>((64 - __builtin_clzll(v | 1)) * 1233 >> 12);  // v's length or one less
  const std::size_t length = below + ((v | 1) >= kPowers[below]);                           // v | 1: "0" has one digit
  char digits[19];
  if (length <= 8) {
    const std::uint64_t word = eight_digits(static_cast<std::uint32_t>(v));
    std::memcpy(digits + 11, &word, 8);
  } else {
    put_19_digits(digits, v);
  }
  std::memcpy(p, digits + 19 - length, length);
  return p + length;
}

constexpr std::size_t kMaxLimbs = 64;  ///< longer numbers: mpz_get_str
/// The longest text of put_decimal: a sign, a lead of up to 20 digits, and chunks of 19.
constexpr std::size_t kMaxDecimal = 1 + 20 + 19 * (kMaxLimbs + 1);

/// The decimal text of z (at most kMaxLimbs limbs), as mpz_get_str(.., 10, z) writes it, at p;
/// returns its end. The limbs are divided by 10^19 as GMP's basecase does (with the reciprocal
/// computed once, and up to four divisions a pass) and each chunk written eight digits at a time
/// (several times as fast as mpz_get_str on the few-hundred-bit numbers of a report).
char* put_decimal(char* p, mpz_srcptr z) {
  static_assert(sizeof(mp_limb_t) == sizeof(std::uint64_t) && GMP_NAIL_BITS == 0, "64-bit limbs");
  std::size_t n = mpz_size(z);
  mp_limb_t quotient[kMaxLimbs];
  std::uint64_t chunk[kMaxLimbs + 1];  // 10^19 > 2^63: at most one chunk a limb, and one more
  std::size_t chunks = 0;
  const mp_limb_t* a = mpz_limbs_read(z);
  while (n > 1) {
    // At most n - 1 divisions: the quotient stays at least 2^(64 (n - 1)) / 10^(19 (n - 1)) >= 1, so
    // every chunk is one of z's and the lead is non-zero.
    const std::size_t k = std::min<std::size_t>(n - 1, 4);
    switch (k) {
      case 1:
        divide_by_chunks<1>(quotient, a, n, chunk + chunks);
        break;
      case 2:
        divide_by_chunks<2>(quotient, a, n, chunk + chunks);
        break;
      case 3:
        divide_by_chunks<3>(quotient, a, n, chunk + chunks);
        break;
      default:
        divide_by_chunks<4>(quotient, a, n, chunk + chunks);
    }
    chunks += k;
    a = quotient;
    while (quotient[n - 1] == 0) --n;
  }
  std::uint64_t lead = n == 1 ? a[0] : 0;  // the quotient left: non-zero unless z is
  if (lead >= kChunk) {
    chunk[chunks++] = lead % kChunk;
    lead /= kChunk;
  }
  if (mpz_sgn(z) < 0) *p++ = '-';
  p = put_lead(p, lead);
  for (std::size_t i = chunks; i-- > 0; p += 19) put_19_digits(p, chunk[i]);
  return p;
}

/// The decimal text of z appended to out (mpz_get_str's beyond kMaxLimbs limbs).
void append_decimal(std::string& out, mpz_srcptr z) {
  if (mpz_size(z) > kMaxLimbs) {
    const std::size_t at = out.size();
    out.resize(at + mpz_sizeinbase(z, 10) + 2);
    mpz_get_str(&out[at], 10, z);
    out.resize(at + std::char_traits<char>::length(&out[at]));
    return;
  }
  char text[kMaxDecimal];
  out.append(text, static_cast<std::size_t>(put_decimal(text, z) - text));
}

}  // namespace

void JsonWriter::rational(const Rational& q) {
  // Digits straight into the output from the mpq's own integers: no temporary strings for the
  // longest values of a report, no copies of the numerator and denominator, and one append.
  const mpq_srcptr x = q.mpq();
  const mpz_srcptr num = mpq_numref(x), den = mpq_denref(x);
  const bool integer = mpz_size(den) == 1 && mpz_getlimbn(den, 0) == 1;  // written without "/1"
  if (mpz_size(num) <= kMaxLimbs && mpz_size(den) <= kMaxLimbs) {
    char text[2 * kMaxDecimal + 3];
    char* p = text;
    *p++ = '"';
    p = put_decimal(p, num);
    if (!integer) {
      *p++ = '/';
      p = put_decimal(p, den);
    }
    *p++ = '"';
    out_.append(text, static_cast<std::size_t>(p - text));
    return;
  }
  out_ += '"';
  append_decimal(out_, num);
  if (!integer) {
    out_ += '/';
    append_decimal(out_, den);
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

}  // namespace relpos::detail::io
