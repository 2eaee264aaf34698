// The fast reader of fast_quadric.hpp: a bounded recursive descent over the text (at most 32 nodes,
// depth 3), each number turned into an interval by at most three exactly-rounded operations, then
// the entries of the form in interval arithmetic (one rounding-mode switch per quadric).
//
// Written by hand rather than with simdjson: the forms need the number *text* (exactness, exact
// symmetry), the nodes are few and the general reader stays the reference for every error; a full
// parser would add a second document model without removing the per-number work.
#include "io/fast_quadric.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#include "algebra/forms.hpp"
#include "algebra/shape_filter.hpp"
#include "algebra/word_arithmetic.hpp"

namespace relpos::io::detail {
namespace {

using I = CGAL::Interval_nt<false>;
using Entries = std::array<I, 16>;

constexpr int kMaxNodes = 32;
constexpr int kMaxDepth = 3;
constexpr int kMaxDigits = 19;    ///< significant digits: m < 10^19 < 2^64
constexpr int kMaxExponent = 30;  ///< |e| after trailing zeros are removed (the size bound in the header)

constexpr std::uint64_t kNotDigits = ~std::uint64_t(0);

/// The value of the eight decimal digits at p, or kNotDigits when one of the bytes is not a digit
/// (eight digits at once: the long numbers of printed doubles are most of a line's bytes).
std::uint64_t eight_digits(const char* p) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(p[k]);  // little-endian: one load
  // Each byte is 0x30..0x39: its high nibble is 3 and adding 6 does not carry out of the low nibble.
  if (((v & 0xF0F0F0F0F0F0F0F0) | (((v + 0x0606060606060606) & 0xF0F0F0F0F0F0F0F0) >> 4)) != 0x3333333333333333)
    return kNotDigits;
  v = (v & 0x0F0F0F0F0F0F0F0F) * 2561 >> 8;                // pairs: 10 a + b in each 16-bit lane
  v = (v & 0x00FF00FF00FF00FF) * 6553601 >> 16;            // quadruples in each 32-bit lane
  return (v & 0x0000FFFF0000FFFF) * 42949672960001 >> 32;  // the eight digits
}

/// Powers of ten that are exact doubles.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/// The exact identity of a number as read, for the symmetry test, exact zeros and the exact matrix:
/// (-1)^neg m 10^e with m free of trailing zeros, or with --numbers double the double
/// (-1)^neg m 2^(e-53) (m < 2^53).
struct Exact {
  std::uint64_t m = 0;
  int e = 0;
  bool neg = false;
  bool is_zero() const { return m == 0; }
  bool same(const Exact& o) const { return neg == o.neg && m == o.m && e == o.e; }
};

/// A number as read: its identity and its enclosure.
struct Number : Exact {
  I x;
};

enum class Kind : unsigned char { Number, Array, Object };

struct Node {
  Kind kind = Kind::Number;
  std::string_view key;  ///< the member name, inside an object
  int child = -1;        ///< first child (arrays and objects)
  int next = -1;         ///< next sibling
  int count = 0;         ///< children
  Number number;
};

class Reader {
 public:
  Reader(std::string_view text, bool doubles) : s_(text), doubles_(doubles) {}

  /// The root node, or -1 when the text is not entirely one value of the accepted kinds.
  int parse() {
    skip_ws();
    const int root = value(0);
    skip_ws();
    return root >= 0 && i_ == s_.size() ? root : -1;
  }
  /// The root node of the value at the start of the text, or -1; the value ends at end().
  int parse_prefix() { return value(0); }
  std::size_t end() const { return i_; }
  const Node& node(int k) const { return nodes_[k].node; }

 private:
  bool at_end() const { return i_ >= s_.size(); }
  char peek() const { return s_[i_]; }
  void skip_ws() {
    while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) ++i_;
  }
  bool digit() const { return !at_end() && peek() >= '0' && peek() <= '9'; }

  int new_node(Kind kind) {
    if (n_ == kMaxNodes) return -1;
    new (&nodes_[n_].node) Node;  // its members' initializers; no zeroing of the whole node
    nodes_[n_].node.kind = kind;
    return n_++;
  }

  int value(int depth) {
    if (at_end()) return -1;
    const char c = peek();
    if (c == '[' || c == '{') return container(depth, c == '{');
    return number();
  }

  /// A key: plain ASCII without escapes or control characters (anything else: the general reader).
  bool key(std::string_view& out) {
    if (at_end() || peek() != '"') return false;
    const std::size_t start = ++i_;
    while (!at_end() && peek() != '"') {
      const auto c = static_cast<unsigned char>(peek());
      if (c < 0x20 || c >= 0x80 || c == '\\') return false;
      ++i_;
    }
    if (at_end()) return false;
    out = s_.substr(start, i_ - start);
    ++i_;
    return true;
  }

  int container(int depth, bool object) {
    if (depth == kMaxDepth) return -1;
    const int self = new_node(object ? Kind::Object : Kind::Array);
    if (self < 0) return -1;
    ++i_;
    skip_ws();
    const char close = object ? '}' : ']';
    if (!at_end() && peek() == close) {
      ++i_;
      return self;
    }
    int last = -1;
    for (;;) {
      std::string_view name;
      if (object) {
        if (!key(name)) return -1;
        skip_ws();
        if (at_end() || peek() != ':') return -1;
        ++i_;
        skip_ws();
        for (int k = nodes_[self].node.child; k >= 0; k = nodes_[k].node.next)
          if (nodes_[k].node.key == name) return -1;  // a duplicate key: the general reader's error
      }
      const int child = value(depth + 1);
      if (child < 0) return -1;
      nodes_[child].node.key = name;
      (last < 0 ? nodes_[self].node.child : nodes_[last].node.next) = child;
      last = child;
      ++nodes_[self].node.count;
      skip_ws();
      if (at_end()) return -1;
      if (peek() == ',') {
        ++i_;
        skip_ws();
        continue;
      }
      if (peek() != close) return -1;
      ++i_;
      return self;
    }
  }

  /// A JSON number (RFC 8259 grammar, checked here), read as its decimal or its nearest double.
  int number() {
    const char* const first = s_.data() + i_;
    const char* const last = s_.data() + s_.size();
    const char* p = first;
    const int self = new_node(Kind::Number);
    if (self < 0) return -1;
    Number& x = nodes_[self].node.number;  // read in place (a copy of a Number stalls on its parts)
    if (p < last && *p == '-') {
      x.neg = true;
      ++p;
    }
    // The significant digits go into m (at most kMaxDigits of them; zeros after those only move the
    // exponent), `scale` counts the fraction's digits and `zeros` the zeros dropped from m's end.
    int significant = 0, scale = 0, zeros = 0;
    const auto digits = [&](bool fraction) {
      for (;;) {
        if (x.m != 0 && significant + 8 <= kMaxDigits && last - p >= 8) {
          if (const std::uint64_t block = eight_digits(p); block != kNotDigits) {
            x.m = x.m * 100000000 + block;
            significant += 8;
            p += 8;
            if (fraction) scale -= 8;
            continue;
          }
        }
        if (p == last || static_cast<unsigned>(*p - '0') > 9) return true;
        const auto d = static_cast<unsigned>(*p++ - '0');
        if (fraction) --scale;
        if (x.m == 0 && d == 0) continue;  // a leading zero
        if (significant == kMaxDigits) {
          if (d != 0) return false;  // more than kMaxDigits significant digits
          ++zeros;
          continue;
        }
        x.m = x.m * 10 + d;
        ++significant;
      }
    };
    if (p == last || static_cast<unsigned>(*p - '0') > 9) return -1;
    if (*p == '0')
      ++p;
    else if (!digits(false))
      return -1;
    if (p < last && *p == '.') {
      ++p;
      if (p == last || static_cast<unsigned>(*p - '0') > 9 || !digits(true)) return -1;
    }
    int exponent = 0;
    if (p < last && (*p == 'e' || *p == 'E')) {
      ++p;
      bool negative = false;
      if (p < last && (*p == '+' || *p == '-')) negative = *p++ == '-';
      if (p == last || static_cast<unsigned>(*p - '0') > 9) return -1;
      for (int length = 0; p < last && static_cast<unsigned>(*p - '0') <= 9; ++p) {
        if (++length > 5) return -1;
        exponent = exponent * 10 + (*p - '0');
      }
      if (negative) exponent = -exponent;
    }
    if (p < last && *p != ',' && *p != ']' && *p != '}' && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r')
      return -1;
    i_ += static_cast<std::size_t>(p - first);
    while (x.m != 0 && x.m % 10 == 0) x.m /= 10, ++zeros;  // m without trailing zeros: one identity a value
    if (doubles_) {  // round to nearest here: the caller's guard starts after parse()
      double d = 0;
      const auto r = std::from_chars(first, p, d);
      if (r.ec != std::errc() || r.ptr != p) return -1;
      if (d != 0 && !(std::fabs(d) >= 0x1p-100 && std::fabs(d) <= 0x1p100)) return -1;
      // The identity of a double: its bits, read through the same fields (exact symmetry, zeros).
      x.x = I(d);
      x.neg = d < 0;
      x.e = 0;
      x.m = d == 0 ? 0 : static_cast<std::uint64_t>(std::fabs(std::frexp(d, &x.e)) * 0x1p53);
    } else if (x.m == 0) {
      x.x = I(0);
      x.neg = false;
      x.e = 0;
    } else {
      x.e = exponent + scale + zeros;
      if (x.e > kMaxExponent || x.e < -kMaxExponent) return -1;
      decimals_ = true;  // enclosed by enclose_decimals()
    }
    return self;
  }

 public:
  /// The enclosures of the decimal numbers: m exactly (a sum of two exact doubles when m > 2^53),
  /// then one exactly-rounded operation with 10^|e| (two when |e| > 22). Call with the rounding mode
  /// towards +inf.
  void enclose_decimals() {
    if (!decimals_) return;
    for (int k = 0; k < n_; ++k) {
      Number& x = nodes_[k].node.number;
      if (nodes_[k].node.kind != Kind::Number || x.m == 0) continue;
      const I m = x.m <= (std::uint64_t(1) << 53)
                      ? I(static_cast<double>(x.m))
                      : I(static_cast<double>(x.m >> 11)) * I(2048.0) + I(static_cast<double>(x.m & 2047));
      const int p10 = x.e < 0 ? -x.e : x.e;
      const I p = p10 <= 22 ? I(kPow10[p10]) : I(kPow10[22]) * I(kPow10[p10 - 22]);
      x.x = x.e >= 0 ? m * p : m / p;
      if (x.neg) x.x = -x.x;
    }
  }

 private:
  std::string_view s_;
  bool doubles_;
  std::size_t i_ = 0;
  int n_ = 0;
  bool decimals_ = false;
  union Slot {  // storage: a node is made when it is read (most of the kMaxNodes are never used)
    Slot() {}
    Node node;
  };
  static_assert(std::is_trivially_destructible<Node>::value, "a Slot does not destroy its node");
  Slot nodes_[kMaxNodes];
};

/// The child of an object named `name`, or -1.
int member(const Reader& r, int object, std::string_view name) {
  for (int k = r.node(object).child; k >= 0; k = r.node(k).next)
    if (r.node(k).key == name) return k;
  return -1;
}

/// The numbers of an array of exactly n numbers, or false.
template <std::size_t N>
bool numbers(const Reader& r, int array, std::array<Number, N>& out) {
  if (array < 0 || r.node(array).kind != Kind::Array || r.node(array).count != static_cast<int>(N)) return false;
  std::size_t i = 0;
  for (int k = r.node(array).child; k >= 0; k = r.node(k).next) {
    if (r.node(k).kind != Kind::Number) return false;
    out[i++] = r.node(k).number;
  }
  return true;
}

/// A 4x4 array of numbers that is exactly symmetric.
bool symmetric_matrix(const Reader& r, int array, std::array<Number, 16>& out) {
  if (array < 0 || r.node(array).kind != Kind::Array || r.node(array).count != 4) return false;
  std::size_t row = 0;
  for (int k = r.node(array).child; k >= 0; k = r.node(k).next, ++row) {
    std::array<Number, 4> x;
    if (!numbers(r, k, x)) return false;
    for (std::size_t j = 0; j < 4; ++j) out[4 * row + j] = x[j];
  }
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      if (!out[4 * i + j].same(out[4 * j + i])) return false;
  return true;
}

bool positive(const Exact& x) { return !x.neg && !x.is_zero(); }

/// What a quadric was read from: the form and its numbers (a matrix: 16; a sphere: centre, radius;
/// a standard paraboloid: vertex, a, b), and the orientation the shape test certified.
struct Recipe {
  enum class Form : unsigned char { Matrix, Sphere, Standard } form = Form::Matrix;
  int orientation = 1;
  std::array<Exact, 16> n;  // the identities only: the exact source keeps a copy
};

static_assert(sizeof(unsigned long) >= sizeof(std::uint64_t), "GMP's _ui functions take the 19-digit m");

/// r = n 2^t2 5^t5 in canonical form, n the integer in r's numerator (not zero). The factors 2 and 5
/// of n cancel against negative powers and the denominator has no other prime: no gcd is needed.
void times_powers_of_2_and_5(mpq_ptr r, long t2, long t5) {
  const mpz_ptr num = mpq_numref(r), den = mpq_denref(r);
  if (t2 < 0) {
    const long v = std::min<long>(static_cast<long>(mpz_scan1(num, 0)), -t2);
    mpz_tdiv_q_2exp(num, num, static_cast<unsigned long>(v));
    t2 += v;
  }
  for (; t5 < 0 && mpz_divisible_ui_p(num, 5); ++t5) mpz_divexact_ui(num, num, 5);
  if (t5 > 0) forms::times_power_of_five(num, num, static_cast<unsigned long>(t5));
  forms::set_power_of_five(den, static_cast<unsigned long>(t5 < 0 ? -t5 : 0));
  if (t2 > 0) mpz_mul_2exp(num, num, static_cast<unsigned long>(t2));
  if (t2 < 0) mpz_mul_2exp(den, den, static_cast<unsigned long>(-t2));
}

/// The value m 10^e of a decimal number x != 0, negated when `minus`, written into r in canonical form.
void decimal_value(const Exact& x, bool minus, mpq_ptr r) {
  mpz_set_ui(mpq_numref(r), x.m);
  if (x.neg != minus) mpz_neg(mpq_numref(r), mpq_numref(r));
  times_powers_of_2_and_5(r, x.e, x.e);
}

/// The exact value of a number as read: m 10^e, or the double itself (a point enclosure).
Rational exact(const Exact& x, bool doubles) {
  if (doubles) return Rational(std::ldexp(x.neg ? -double(x.m) : double(x.m), x.e - 53));
  if (x.m == 0) return Rational(0);
  Rational q;  // fresh: its mpq is not shared
  decimal_value(x, false, q.mpq());
  return q;
}

/// c0^2 + c1^2 + c2^2 - r^2 for decimal numbers as an integer sum over the smallest power of ten:
/// the sum into `sum`, and `low` with the entry = sum 10^(2 low).
int sphere_sum(const std::array<Exact, 16>& n, mpz_ptr sum) {
  int low = 0;
  bool any = false;
  for (std::size_t i = 0; i < 4; ++i)
    if (n[i].m != 0) low = any ? std::min(low, n[i].e) : n[i].e, any = true;
  struct Term {  // one per thread: its limbs are kept
    mpz_t z;
    Term() { mpz_init(z); }
    ~Term() { mpz_clear(z); }
    Term(const Term&) = delete;
    Term& operator=(const Term&) = delete;
  };
  thread_local Term scratch;
  const mpz_ptr term = scratch.z;
  mpz_set_ui(sum, 0);
  for (std::size_t i = 0; i < 4; ++i) {
    if (n[i].m == 0) continue;
    mpz_set_ui(term, n[i].m);
    mpz_mul(term, term, term);
    if (n[i].e != low) {  // times 10^(2 (e - low))
      const auto k = static_cast<unsigned long>(2 * (n[i].e - low));
      forms::times_power_of_five(term, term, k);
      mpz_mul_2exp(term, term, k);
    }
    (i < 3 ? mpz_add : mpz_sub)(sum, sum, term);  // the radius is n[3]
  }
  return low;
}

/// The entry c0^2 + c1^2 + c2^2 - r^2 of Ellipsoid::sphere for decimal numbers, written into r: the
/// integer sum over the smallest power of ten, then reduced by its factors 2 and 5 alone (no rational
/// additions). False (r unspecified) when the entry is zero.
bool sphere_constant_value(const std::array<Exact, 16>& n, mpq_ptr r) {
  const int low = sphere_sum(n, mpq_numref(r));
  if (mpz_sgn(mpq_numref(r)) == 0) return false;
  times_powers_of_2_and_5(r, 2 * low, 2 * low);
  return true;
}

/// sphere_constant_value() as a Rational.
Rational sphere_constant(const std::array<Exact, 16>& n) {
  Rational q;  // fresh: its mpq is not shared
  return sphere_constant_value(n, q.mpq()) ? q : Rational(0);
}

/// 5^k for k < 28 (< 2^64): the powers of five of decimal text, multiplied in one word.
constexpr unsigned long kMaxWordPower5 = 28;
constexpr auto kPower5 = [] {
  std::array<unsigned long, kMaxWordPower5> p{};
  p[0] = 1;
  for (std::size_t k = 1; k < kMaxWordPower5; ++k) p[k] = p[k - 1] * 5;
  return p;
}();

/// The integer form of an exact matrix of decimal text (forms::integer_form_of) from the numbers read:
/// each entry of the upper triangle (row by row, as in symmetric()) is (-1)^neg n 2^t2 5^t5 / R^2
/// with R one of two integers prime to 10 and to n (the rests of the mantissas of a and b of a
/// standard paraboloid; 1 for every other entry). The lcm of the denominators is 2^u2 5^u5 rest with
/// u2, u5 the largest negative exponents once n's own 2s and 5s are counted and rest = lcm(R_a^2,
/// R_b^2): no rationals and no gcd but one of two words.
class DecimalForm {
 public:
  DecimalForm() {
    for (auto& x : n_) mpz_init(x);
    for (auto& x : cof_) mpz_init(x);
  }
  ~DecimalForm() {
    for (auto& x : n_) mpz_clear(x);
    for (auto& x : cof_) mpz_clear(x);
  }
  DecimalForm(const DecimalForm&) = delete;
  DecimalForm& operator=(const DecimalForm&) = delete;

  /// Every entry zero, ready for a new matrix; the integers keep their limbs (a form reused by a
  /// thread writes quadric after quadric without malloc).
  void reset() {
    for (auto& x : n_) mpz_set_ui(x, 0);
    std::fill(std::begin(t2_), std::end(t2_), 0L);
    std::fill(std::begin(t5_), std::end(t5_), 0L);
    std::fill(std::begin(which_), std::end(which_), 0);
    std::fill(std::begin(rest_), std::end(rest_), std::uint64_t{1});
  }

  /// Entry k is (-1)^neg m 10^e (zero for m = 0).
  void decimal(std::size_t k, std::uint64_t m, int e, bool neg) {
    mpz_set_ui(n_[k], m);
    if (neg) mpz_neg(n_[k], n_[k]);
    t2_[k] = t5_[k] = e;
  }
  /// Entry k is n 10^e, n already in place (n_ref(k)).
  mpz_ptr n_ref(std::size_t k) { return n_[k]; }
  void exponents(std::size_t k, long t2, long t5) {
    t2_[k] = t2;
    t5_[k] = t5;
  }
  /// Entry k's denominator has the factor rests_[r]^2 (r = 1, 2).
  void over_square(std::size_t k, int r, std::uint64_t rest) {
    which_[k] = r;
    rest_[r] = rest;
  }

  void write(const forms::IntegerFormOut& out) {
    long u2 = 0, u5 = 0;
    for (std::size_t k = 0; k < 10; ++k) {
      if (mpz_sgn(n_[k]) == 0) continue;
      const mp_bitcnt_t twos = mpz_scan1(n_[k], 0);  // n's own 2s and 5s count in the exponents
      if (twos > 0) mpz_tdiv_q_2exp(n_[k], n_[k], twos);
      t2_[k] += static_cast<long>(twos);
      for (; mpz_divisible_ui_p(n_[k], 5); ++t5_[k]) mpz_divexact_ui(n_[k], n_[k], 5);
      u2 = std::max(u2, -t2_[k]);
      u5 = std::max(u5, -t5_[k]);
    }
    if (!out.scale) {  // the exponents alone: no rest, no lcm
      out.split.twos = static_cast<unsigned long>(u2);
      out.split.fives = static_cast<unsigned long>(u5);
      return;
    }
    // rest = lcm(R_a^2, R_b^2) = (R_a R_b / g)^2 multiplies the entries without R; the others
    // rest / R_a^2 = (R_b / g)^2 and rest / R_b^2 = (R_a / g)^2.
    const std::uint64_t g = relpos::detail::word_gcd(rest_[1], rest_[2]);
    auto& cof = cof_;
    mpz_set_ui(cof[1], rest_[2] / g);
    mpz_set_ui(cof[2], rest_[1] / g);
    for (std::size_t r = 1; r < 3; ++r) mpz_mul(cof[r], cof[r], cof[r]);
    const mpz_ptr rest = cof[0];
    mpz_set_ui(rest, rest_[1]);
    mpz_mul(rest, rest, rest);
    mpz_mul(rest, rest, cof[1]);
    constexpr std::size_t kAt[10][2] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 1}, {1, 2}, {1, 3}, {2, 2}, {2, 3}, {3, 3}};
    for (std::size_t k = 0; k < 10 && out.entries; ++k) {
      const mpz_ptr z = out.form[4 * kAt[k][0] + kAt[k][1]];
      if (mpz_sgn(n_[k]) == 0) {
        mpz_set_ui(z, 0);
      } else {
        const auto fives = static_cast<unsigned long>(t5_[k] + u5);
        if (fives < kMaxWordPower5)
          mpz_mul_ui(z, n_[k], kPower5[fives]);
        else
          forms::times_power_of_five(z, n_[k], fives);
        mpz_mul_2exp(z, z, static_cast<unsigned long>(t2_[k] + u2));
        if (mpz_cmp_ui(cof[which_[k]], 1) != 0) mpz_mul(z, z, cof[which_[k]]);
      }
      if (kAt[k][0] != kAt[k][1]) mpz_set(out.form[4 * kAt[k][1] + kAt[k][0]], z);
    }
    const mpz_ptr l = out.l.mpz();  // fresh: written in place
    forms::set_power_of_five(l, static_cast<unsigned long>(u5));
    mpz_mul_2exp(l, l, static_cast<unsigned long>(u2));
    mpz_mul(l, l, rest);
    if (!out.factors) {
      out.split.twos = static_cast<unsigned long>(u2);
      out.split.fives = static_cast<unsigned long>(u5);
      out.split.rest = Integer(rest);
      return;
    }
    std::vector<forms::SplitScale::Factor> rests;
    for (std::size_t r = 1; r < 3; ++r)
      if (rest_[r] > 1 && (r == 1 || rest_[2] != rest_[1])) rests.push_back({Integer(rest_[r]), 2});
    out.split =
        forms::split_scale(static_cast<unsigned long>(u2), static_cast<unsigned long>(u5), Integer(rest), rests);
  }

 private:
  mpz_t n_[10];
  mpz_t cof_[3];  // the rest (cof_[0]) and the cofactors of R_a^2 and R_b^2 in it
  long t2_[10] = {}, t5_[10] = {};
  int which_[10] = {};
  std::uint64_t rest_[3] = {1, 1, 1};
};

/// The mantissa m without its factors 2 and 5 (R in DecimalForm), and their counts.
std::uint64_t rest_of(std::uint64_t m, long& twos, long& fives) {
  twos = __builtin_ctzll(m);
  m >>= twos;
  for (fives = 0; m % 5 == 0; ++fives) m /= 5;
  return m;
}

/// The symmetric matrix of an upper triangle given row by row (00 01 02 03 11 12 13 22 23 33): each
/// entry made once and shared with its mirror, no default entries made and replaced.
Matrix4 symmetric(const std::array<Rational, 10>& u) {
  return Matrix4{{u[0], u[1], u[2], u[3], u[1], u[4], u[5], u[6], u[2], u[5], u[7], u[8], u[3], u[6], u[8], u[9]}};
}

/// The exact matrix, when first needed: the matrix of the constructor the general reader calls for
/// the form (Ellipsoid::sphere, Paraboloid::standard), or the matrix with the certified sign
/// normalization (what from_matrix returns), from the exact values of the numbers. For decimal
/// numbers the entries of a sphere and of a standard paraboloid with its vertex on the axis are
/// written directly in canonical form (their denominators are powers of 2 and 5, and the squared
/// mantissas of a and b in forms::inverse_square); the rationals are the constructors'
/// (tests/test_fast_reader.cpp).
class NumberSource final : public relpos::detail::ExactSource {
 public:
  NumberSource(const Recipe& recipe, bool doubles) : recipe_(recipe), doubles_(doubles) {
    const auto& n = recipe.n;
    const bool standard = recipe.form == Recipe::Form::Standard && n[0].m == 0 && n[1].m == 0;
    if (doubles || !(recipe.form == Recipe::Form::Sphere || standard)) return;
    shape_.sphere = !standard;
    const std::array<std::size_t, 4> from =
        standard ? std::array<std::size_t, 4>{3, 4, 2, 2} : std::array<std::size_t, 4>{0, 1, 2, 3};
    for (std::size_t i = 0; i < 4; ++i) shape_.n[i] = {n[from[i]].m, n[from[i]].e, n[from[i]].neg};
    has_shape_ = true;
  }
  const forms::DecimalShape* decimal_shape() const override { return has_shape_ ? &shape_ : nullptr; }
  Matrix4 build() const override {
    const auto& n = recipe_.n;
    // The exact value of n[k], negated when `minus`.
    auto q = [&](std::size_t k, bool minus = false) {
      Exact x = n[k];
      x.neg = x.neg != minus;
      return exact(x, doubles_);
    };
    const Rational zero(0);
    switch (recipe_.form) {
      case Recipe::Form::Sphere: {
        if (doubles_) return Ellipsoid::sphere(Vector3{q(0), q(1), q(2)}, q(3)).matrix();
        const Rational one(1);
        return symmetric({one, zero, zero, q(0, true), one, zero, q(1, true), one, q(2, true), sphere_constant(n)});
      }
      case Recipe::Form::Standard:
        if (doubles_ || n[0].m != 0 || n[1].m != 0)
          return Paraboloid::standard(Vector3{q(0), q(1), q(2)}, q(3), q(4)).matrix();
        return symmetric({forms::inverse_square(q(3)), zero, zero, zero, forms::inverse_square(q(4)), zero, zero, zero,
                          Rational(-1, 2), q(2)});
      case Recipe::Form::Matrix:
        break;
    }
    const bool minus = recipe_.orientation < 0;
    return symmetric({q(0, minus), q(1, minus), q(2, minus), q(3, minus), q(5, minus), q(6, minus), q(7, minus),
                      q(10, minus), q(11, minus), q(15, minus)});
  }

  bool integer_form(const forms::IntegerFormOut& out) const override {
    const auto& n = recipe_.n;
    if (doubles_) return false;
    thread_local DecimalForm form;
    form.reset();
    switch (recipe_.form) {
      case Recipe::Form::Sphere: {
        for (std::size_t k : {0, 4, 7}) form.decimal(k, 1, 0, false);
        for (std::size_t i = 0; i < 3; ++i) form.decimal(i == 0 ? 3 : i == 1 ? 6 : 8, n[i].m, n[i].e, !n[i].neg);
        const long low = sphere_sum(n, form.n_ref(9));
        form.exponents(9, 2 * low, 2 * low);
        break;
      }
      case Recipe::Form::Standard: {
        if (n[0].m != 0 || n[1].m != 0) return false;  // the general constructor's matrix
        // 1/a^2 for a = m 10^e = R 2^(e + twos) 5^(e + fives): 2^(-2 (e + twos)) 5^(-2 (e + fives)) / R^2.
        for (std::size_t i = 0; i < 2; ++i) {
          long twos = 0, fives = 0;
          const std::uint64_t r = rest_of(n[3 + i].m, twos, fives);
          const std::size_t k = i == 0 ? 0 : 4;
          form.decimal(k, 1, 0, false);
          form.exponents(k, -2 * (n[3 + i].e + twos), -2 * (n[3 + i].e + fives));
          form.over_square(k, static_cast<int>(i) + 1, r);
        }
        form.decimal(8, 1, 0, true);  // -1/2
        form.exponents(8, -1, 0);
        form.decimal(9, n[2].m, n[2].e, n[2].neg);
        break;
      }
      case Recipe::Form::Matrix: {
        const bool minus = recipe_.orientation < 0;
        constexpr std::size_t kUpper[10] = {0, 1, 2, 3, 5, 6, 7, 10, 11, 15};
        for (std::size_t k = 0; k < 10; ++k) {
          const Exact& x = n[kUpper[k]];
          form.decimal(k, x.m, x.e, x.neg != minus);
        }
        break;
      }
    }
    form.write(out);
    return true;
  }

  /// For a sphere and a standard paraboloid with its vertex on the axis read from decimal text: each
  /// entry of build()'s matrix made canonical in one scratch rational (decimal_value() and
  /// sphere_constant_value(), as exact() and sphere_constant() make it) and truncated, with no
  /// matrix of rationals.
  bool truncated_doubles(DoubleMatrix4& out) const override {
    if (!has_shape_) return false;
    thread_local Rational scratch;  // one per thread, never copied (so written in place): its limbs are kept
    const mpq_ptr q = scratch.mpq();
    const mpz_ptr num = mpq_numref(q), den = mpq_denref(q);
    // The entry (-1)^minus x of a decimal x, truncated.
    auto decimal = [&](const Exact& x, bool minus) {
      if (x.m == 0) return 0.0;
      decimal_value(x, minus, q);
      return forms::truncated_double(scratch);
    };
    const auto& n = recipe_.n;
    out.fill(0.0);
    if (shape_.sphere) {
      out[0] = out[5] = out[10] = 1.0;
      for (std::size_t i = 0; i < 3; ++i) out[4 * i + 3] = out[12 + i] = decimal(n[i], true);
      if (sphere_constant_value(n, q)) out[15] = forms::truncated_double(scratch);
      return true;
    }
    for (std::size_t i = 0; i < 2; ++i) {  // 1/a^2, 1/b^2 (forms::inverse_square): a > 0 canonical, inverted, squared
      decimal(n[3 + i], false);
      mpz_swap(num, den);
      mpz_mul(num, num, num);
      mpz_mul(den, den, den);
      out[5 * i] = forms::truncated_double(scratch);
    }
    out[11] = out[14] = -0.5;
    out[15] = decimal(n[2], false);
    return true;
  }

 private:
  Recipe recipe_;
  bool doubles_;
  bool has_shape_ = false;
  forms::DecimalShape shape_;
};

/// The storage of a certified quadric: its doubles when every enclosure is a point (the exact
/// matrix is then those doubles), else the enclosures with the numbers as the exact source.
relpos::detail::QuadricMatrix storage(const Entries& x, const Recipe& recipe, bool doubles) {
  relpos::detail::EnclosureMatrix4 enc;
  bool points = true;
  for (std::size_t k = 0; k < 16; ++k) {
    const I v = recipe.orientation > 0 ? x[k] : -x[k];
    enc.lo[k] = v.inf();
    enc.hi[k] = v.sup();
    points = points && v.inf() == v.sup();
  }
  if (points) return relpos::detail::QuadricMatrix(enc.lo);
  return relpos::detail::QuadricMatrix(enc, std::make_shared<const NumberSource>(recipe, doubles));
}

Entries intervals(const std::array<Number, 16>& n) {
  Entries x;
  for (std::size_t k = 0; k < 16; ++k) x[k] = n[k].x;
  return x;
}

/// The matrix of a 4x4 array or {"matrix": 4x4}, or -1.
int matrix_node(const Reader& r, int root) {
  if (r.node(root).kind == Kind::Array) return root;
  if (r.node(root).kind == Kind::Object && r.node(root).count == 1) return member(r, root, "matrix");
  return -1;
}

/// The entries of the ellipsoid of the text, in interval arithmetic, and its orientation (the sign
/// that makes Q3 positive definite); 0 when this reader does not take the text. Rounding towards
/// +inf (the caller's guard).
int ellipsoid_entries(const Reader& r, int root, Entries& x, Recipe& recipe) {
  if (const int m = matrix_node(r, root); m >= 0) {
    std::array<Number, 16> n;
    if (!symmetric_matrix(r, m, n) || n[0].is_zero()) return 0;
    const int want = n[0].neg ? -1 : 1;
    x = intervals(n);
    std::copy(n.begin(), n.end(), recipe.n.begin());
    return shape_filter::certified_ellipsoid_intervals(x, want) == want ? want : 0;
  }
  // {"sphere": {"center" | "centre": [x, y, z], "radius": r}}: Ellipsoid::sphere, valid when r > 0.
  if (r.node(root).kind != Kind::Object || r.node(root).count != 1) return 0;
  const int sphere = member(r, root, "sphere");
  if (sphere < 0 || r.node(sphere).kind != Kind::Object || r.node(sphere).count != 2) return 0;
  const int centre = member(r, sphere, "center") >= 0 ? member(r, sphere, "center") : member(r, sphere, "centre");
  const int radius = member(r, sphere, "radius");
  std::array<Number, 3> c;
  if (radius < 0 || r.node(radius).kind != Kind::Number || !numbers(r, centre, c)) return 0;
  const Number& rad = r.node(radius).number;
  if (!positive(rad)) return 0;
  recipe.form = Recipe::Form::Sphere;
  recipe.n = {c[0], c[1], c[2], rad};
  x.fill(I(0));
  x[0] = x[5] = x[10] = I(1);
  for (std::size_t i = 0; i < 3; ++i) x[4 * i + 3] = x[12 + i] = -c[i].x;
  x[15] = CGAL::square(c[0].x) + CGAL::square(c[1].x) + CGAL::square(c[2].x) - CGAL::square(rad.x);
  return 1;
}

/// The same for an elliptic paraboloid (the orientation makes Q3 positive semidefinite).
int paraboloid_entries(const Reader& r, int root, Entries& x, Recipe& recipe) {
  if (const int m = matrix_node(r, root); m >= 0) {
    std::array<Number, 16> n;
    if (!symmetric_matrix(r, m, n)) return 0;
    std::copy(n.begin(), n.end(), recipe.n.begin());
    // det Q3 = 0 exactly, from entries that are exactly zero (axis-aligned cups); else the general reader.
    if (!shape_filter::impl::zero_by_pattern(n[0].is_zero(), n[1].is_zero(), n[2].is_zero(), n[5].is_zero(),
                                             n[6].is_zero(), n[10].is_zero()))
      return 0;
    x = intervals(n);
    return shape_filter::certified_paraboloid_intervals(x);
  }
  // {"vertex": [x, y, z], "a": a, "b": b}: Paraboloid::standard without rotation, valid when a, b > 0.
  if (r.node(root).kind != Kind::Object || r.node(root).count != 3) return 0;
  const int a = member(r, root, "a"), b = member(r, root, "b");
  std::array<Number, 3> v;
  if (a < 0 || b < 0 || r.node(a).kind != Kind::Number || r.node(b).kind != Kind::Number ||
      !numbers(r, member(r, root, "vertex"), v))
    return 0;
  if (!positive(r.node(a).number) || !positive(r.node(b).number)) return 0;
  recipe.form = Recipe::Form::Standard;
  recipe.n = {v[0], v[1], v[2], r.node(a).number, r.node(b).number};
  const I ia = I(1) / CGAL::square(r.node(a).number.x), ib = I(1) / CGAL::square(r.node(b).number.x);
  x.fill(I(0));
  x[0] = ia;
  x[5] = ib;
  x[3] = x[12] = -ia * v[0].x;
  x[7] = x[13] = -ib * v[1].x;
  x[11] = x[14] = I(-0.5);
  x[15] = ia * CGAL::square(v[0].x) + ib * CGAL::square(v[1].x) + v[2].x;
  return 1;
}

/// The quadric of the text into `out` (made there: a quadric is a few hundred bytes), or false and
/// `out` empty: `entries` is ellipsoid_entries or paraboloid_entries, `make` the matching
/// make_ellipsoid or make_paraboloid. With `end`, the text starts with the value (fast_ellipsoid_at).
template <class Q, class Entries_of, class Make>
bool read_quadric(std::string_view text, bool doubles, std::size_t* end, Entries_of entries, Make make,
                  std::optional<Q>& out) {
  Entries x;
  Recipe recipe;
  recipe.orientation = 0;
  Reader r(text, doubles);
  const int root = end ? r.parse_prefix() : r.parse();
  if (end) *end = root >= 0 ? r.end() : std::string_view::npos;
  if (root >= 0) {
    CGAL::Protect_FPU_rounding<true> guard;  // Interval_nt<false>: rounding towards +inf
    r.enclose_decimals();
    recipe.orientation = entries(r, root, x, recipe);
  }
  if (recipe.orientation == 0) {
    out.reset();
    return false;
  }
  out.emplace(make(storage(x, recipe, doubles)));
  return true;
}

}  // namespace

std::optional<Ellipsoid> fast_ellipsoid(std::string_view text, bool doubles) {
  std::optional<Ellipsoid> e;
  read_quadric(text, doubles, nullptr, ellipsoid_entries, relpos::detail::make_ellipsoid, e);
  return e;
}

std::optional<Paraboloid> fast_paraboloid(std::string_view text, bool doubles) {
  std::optional<Paraboloid> p;
  read_quadric(text, doubles, nullptr, paraboloid_entries, relpos::detail::make_paraboloid, p);
  return p;
}

bool fast_ellipsoid_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Ellipsoid>& out) {
  return read_quadric(text, doubles, &end, ellipsoid_entries, relpos::detail::make_ellipsoid, out);
}

bool fast_paraboloid_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Paraboloid>& out) {
  return read_quadric(text, doubles, &end, paraboloid_entries, relpos::detail::make_paraboloid, out);
}

}  // namespace relpos::io::detail
