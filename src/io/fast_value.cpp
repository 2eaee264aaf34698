#include "io/fast_value.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <new>

#include "io/json_lexer.hpp"

namespace relpos::detail::io {
namespace {

using relpos::detail::Decimal;

/// Powers of ten that are exact doubles.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/// The largest power of ten below the double range.
constexpr int kMaxPower = 308;

/// An enclosure of 10^k, 0 <= k <= kMaxPower: 10^(k - 22) 10^22 rounded outwards (for k <= 44 the
/// product of the two exact doubles, as enclose_decimals writes it), made once, under the first
/// caller's rounding towards +inf.
FastInterval power_of_ten(int k) {
  static const std::array<FastInterval, kMaxPower + 1> table = [] {
    std::array<FastInterval, kMaxPower + 1> t;
    for (int j = 0; j <= 22; ++j) t[static_cast<std::size_t>(j)] = FastInterval(kPow10[j]);
    for (std::size_t j = 23; j <= kMaxPower; ++j) t[j] = t[j - 22] * t[22];
    return t;
  }();
  return table[static_cast<std::size_t>(k)];
}

/// The lexer's sink of a number read as a decimal: the significant digits go into m (at most
/// kMaxDigits of them; zeros after those only move the exponent), `scale` counts the fraction's
/// digits and `zeros` the zeros dropped from m's end; the exponent has at most five digits. m is
/// the sink's own, not the node's: the digits are loads of chars, which may alias any store, so a
/// node's m would go back to memory after every digit.
struct DecimalDigits {
  std::uint64_t m = 0;
  bool neg = false;
  int significant = 0, scale = 0, zeros = 0, exponent = 0, exponent_length = 0;
  void negative() { neg = true; }
  bool wants_eight() const { return m != 0 && significant + 8 <= FastValue::kMaxDigits; }
  bool eight(std::uint64_t block, bool fraction) {
    m = m * 100000000 + block;
    significant += 8;
    if (fraction) scale -= 8;
    return true;
  }
  bool digit(unsigned d, bool fraction) {
    if (fraction) --scale;
    if (m == 0 && d == 0) return true;  // a leading zero
    if (significant == FastValue::kMaxDigits) {
      ++zeros;
      return d == 0;  // more than kMaxDigits significant digits: refused
    }
    m = m * 10 + d;
    ++significant;
    return true;
  }
  bool exponent_digit(unsigned d) {
    if (++exponent_length > 5) return false;
    exponent = exponent * 10 + static_cast<int>(d);
    return true;
  }
  void exponent_sign(bool negative) {
    if (negative) exponent = -exponent;
  }
};

}  // namespace

inline int FastValue::value(int depth) {
  if (i_ >= s_.size()) return -1;
  const char c = s_[i_];
  if (c == '[' || c == '{') return container(depth, c == '{');
  return c == '"' ? number<true>() : number<false>();
}

int FastValue::parse() {
  i_ = skip_space(s_, i_);
  const int root = value(0);
  i_ = skip_space(s_, i_);
  return root >= 0 && i_ == s_.size() ? root : -1;
}

int FastValue::parse_prefix() { return value(0); }

int FastValue::new_node(FastKind kind) {
  if (n_ == kMaxNodes) return -1;
  new (&nodes_[n_].node) FastNode;  // its members' initializers; no zeroing of the whole node
  nodes_[n_].node.kind = kind;
  return n_++;
}

inline bool FastValue::member_key(int self, std::string_view& name) {
  // A key: plain ASCII without escapes or control characters (anything else: the general reader).
  if (i_ >= s_.size() || s_[i_] != '"') return false;
  const std::size_t end = plain_string_end(s_, i_);
  if (end == std::string_view::npos) return false;
  name = s_.substr(i_ + 1, end - i_ - 2);
  i_ = skip_space(s_, end);
  if (i_ >= s_.size() || s_[i_] != ':') return false;
  i_ = skip_space(s_, i_ + 1);
  for (int k = nodes_[self].node.child; k >= 0; k = nodes_[k].node.next)
    if (nodes_[k].node.key == name) return false;  // a duplicate key: the general reader's error
  return true;
}

int FastValue::container(int depth, bool object) {
  if (depth == kMaxDepth) return -1;
  const int self = new_node(object ? FastKind::Object : FastKind::Array);
  if (self < 0) return -1;
  i_ = skip_space(s_, i_ + 1);
  const char close = object ? '}' : ']';
  if (i_ < s_.size() && s_[i_] == close) {
    ++i_;
    return self;
  }
  int last = -1;
  for (;;) {
    std::string_view name;
    if (object && !member_key(self, name)) return -1;
    const int child = value(depth + 1);
    if (child < 0) return -1;
    nodes_[child].node.key = name;
    (last < 0 ? nodes_[self].node.child : nodes_[last].node.next) = child;
    last = child;
    ++nodes_[self].node.count;
    i_ = skip_space(s_, i_);
    if (i_ >= s_.size()) return -1;
    if (s_[i_] == ',') {
      i_ = skip_space(s_, i_ + 1);
      continue;
    }
    if (s_[i_] != close) return -1;
    ++i_;
    return self;
  }
}

template <bool quoted>
int FastValue::number() {
  // A decimal written as a JSON string ("0.1") is the number 0.1 to the general reader: read here
  // too, so that both spellings give the quadric the same storage and the same stages run (with
  // --numbers doubles only JSON numbers are rounded: a string stays with the general reader).
  const char* first = s_.data() + i_;
  const char* const last = s_.data() + s_.size();
  if (quoted && doubles_) return -1;
  first += quoted;
  const int self = new_node(FastKind::Number);
  if (self < 0) return -1;
  DecimalDigits digits;
  const char* const p = scan_number(first, last, digits);
  if (!p) return -1;
  const char* after = p;
  if (quoted) {
    if (after == last || *after != '"') return -1;
    ++after;
  }
  if (after < last && *after != ',' && *after != ']' && *after != '}' && !is_json_space(*after)) return -1;
  i_ = static_cast<std::size_t>(after - s_.data());
  FastNumber& n = nodes_[self].node.number;  // written in place (a copy of a number stalls on its parts)
  Decimal& x = n.d;
  std::uint64_t m = digits.m;
  int zeros = digits.zeros;
  while (m != 0 && m % 10 == 0) m /= 10, ++zeros;  // m without trailing zeros: one identity a value
  if (doubles_) {                                  // round to nearest here: the caller's guard starts after parse()
    double d = 0;
    const auto r = std::from_chars(first, p, d);
    if (r.ec != std::errc() || r.ptr != p) return -1;
    if (d != 0 && !(std::fabs(d) >= 0x1p-100 && std::fabs(d) <= 0x1p100)) return -1;
    // The identity of a double: its bits, read through the same fields (exact symmetry, zeros).
    n.x = FastInterval(d);
    x.neg = d < 0;
    x.e = 0;
    x.m = d == 0 ? 0 : static_cast<std::uint64_t>(std::fabs(std::frexp(d, &x.e)) * 0x1p53);
  } else if (m == 0) {
    n.x = FastInterval(0);
  } else {
    const int e = digits.exponent + digits.scale + zeros;
    if (e > kMaxWideExponent || e < -kMaxWideExponent) return -1;
    x.m = m;
    x.e = e;
    x.neg = digits.neg;
    decimals_ = true;  // enclosed by enclose_decimals()
  }
  return self;
}

void FastValue::enclose_decimals() {
  if (!decimals_) return;
  int widest = 0;  // the largest |e|: one test after the loop, not one a number as it is read
  for (int k = 0; k < n_; ++k) {
    FastNumber& n = nodes_[k].node.number;
    const Decimal& x = n.d;
    if (nodes_[k].node.kind != FastKind::Number || x.m == 0) continue;
    const FastInterval m = x.m <= (std::uint64_t(1) << 53)
                               ? FastInterval(static_cast<double>(x.m))
                               : FastInterval(static_cast<double>(x.m >> 11)) * FastInterval(2048.0) +
                                     FastInterval(static_cast<double>(x.m & 2047));
    const int p10 = x.e < 0 ? -x.e : x.e;
    widest = std::max(widest, p10);
    if (p10 <= 44) {
      const FastInterval p =
          p10 <= 22 ? FastInterval(kPow10[p10]) : FastInterval(kPow10[22]) * FastInterval(kPow10[p10 - 22]);
      n.x = x.e >= 0 ? m * p : m / p;
    } else if (p10 <= kMaxPower) {  // a wide number
      n.x = x.e >= 0 ? m * power_of_ten(p10) : m / power_of_ten(p10);
    } else {  // 10^|e| beyond the double range, the number perhaps not: 10^(|e| - kMaxPower) first
      // (|e| <= kMaxWideExponent, so both powers are in the table)
      static_assert(kMaxWideExponent - kMaxPower <= kMaxPower, "10^|e| in two steps of the table");
      const FastInterval p = power_of_ten(p10 - kMaxPower);
      n.x = x.e >= 0 ? m * p * power_of_ten(kMaxPower) : m / p / power_of_ten(kMaxPower);
    }
    if (x.neg) n.x = -n.x;
  }
  wide_ = widest > kMaxExponent;
}

}  // namespace relpos::detail::io
