#include "relpos/numbers.hpp"

#include <gmp.h>

#include <cctype>
#include <cmath>
#include <sstream>

#include "algebra/number_limits.hpp"
#include "relpos/error.hpp"

namespace relpos {
namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

Integer parse_integer_digits(std::string_view digits) {
  Integer z;
  mpz_set_str(z.mpz(), std::string(digits).c_str(), 10);  // digits already validated
  return z;
}

Integer power_of_ten(unsigned long e) {
  Integer z;
  mpz_ui_pow_ui(z.mpz(), 10, e);
  return z;
}

/// "nan", "inf", "infinity" in any case (the sign is already removed): what printf and other
/// languages write for non-finite doubles.
bool is_non_finite(std::string_view s) {
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

[[noreturn]] void bad(std::string_view text, const char* why) {
  std::string shown(text.substr(0, 60));
  if (text.size() > 60) shown += "...";
  throw InputError("not an exact number: \"" + shown + "\" (" + why + ")");
}

/// A fraction p/q (text[slash] = '/'): an optionally signed integer over a positive integer written
/// without sign.
Rational parse_fraction(std::string_view text, std::size_t slash) {
  std::string_view num = text.substr(0, slash), den = text.substr(slash + 1);
  bool neg = false;
  if (!num.empty() && (num[0] == '+' || num[0] == '-')) {
    neg = num[0] == '-';
    num.remove_prefix(1);
  }
  if (!den.empty() && (den[0] == '+' || den[0] == '-')) bad(text, "the denominator takes no sign");
  if (!all_digits(num) || !all_digits(den)) bad(text, "a fraction needs integers on both sides of '/'");
  Integer d = parse_integer_digits(den);
  if (d == 0) bad(text, "zero denominator");
  Rational q(parse_integer_digits(num), d);  // Gmpq canonicalizes
  return neg ? -q : q;
}

/// The exponent of a decimal's (e|E) part, [sign] digits (at most six).
long parse_exponent(std::string_view text, std::string_view expo) {
  bool eneg = false;
  if (expo[0] == '+' || expo[0] == '-') {
    eneg = expo[0] == '-';
    expo.remove_prefix(1);
  }
  if (!all_digits(expo)) bad(text, "exponent is not an integer");
  if (expo.size() > 6) bad(text, "exponent out of range");
  const long e10 = std::stol(std::string(expo));
  return eneg ? -e10 : e10;
}

/// A decimal: [sign] digits [. digits] [(e|E) [sign] digits], at least one mantissa digit.
Rational parse_decimal(std::string_view text) {
  std::string_view s = text;
  bool neg = false;
  if (s[0] == '+' || s[0] == '-') {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  std::string_view mant = s, expo;
  if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
    mant = s.substr(0, e);
    expo = s.substr(e + 1);
    if (expo.empty()) bad(text, "missing exponent digits");
  }
  std::string_view ip = mant, fp;
  if (auto dot = mant.find('.'); dot != std::string_view::npos) {
    ip = mant.substr(0, dot);
    fp = mant.substr(dot + 1);
  }
  if (ip.empty() && fp.empty()) bad(text, "no digits");
  if ((!ip.empty() && !all_digits(ip)) || (!fp.empty() && !all_digits(fp))) {
    if (is_non_finite(s)) bad(text, "not finite");
    bad(text, "unexpected character");
  }
  long e10 = expo.empty() ? 0 : parse_exponent(text, expo);
  e10 -= static_cast<long>(fp.size());
  if (e10 > detail::kMaxDecimalExponent ||
      e10 < -detail::kMaxDecimalExponent - static_cast<long>(detail::kMaxNumberChars))
    bad(text, "decimal exponent beyond the supported range: the exponent of the last digit must lie in [-14000, 4000]");
  std::string digits = std::string(ip) + std::string(fp);
  Integer m = parse_integer_digits(digits.empty() ? "0" : digits);
  if (neg) m = -m;
  if (e10 >= 0) return Rational(m * power_of_ten(static_cast<unsigned long>(e10)));
  return Rational(m, power_of_ten(static_cast<unsigned long>(-e10)));
}

}  // namespace

Rational parse_rational(std::string_view text) {
  // Every character is part of the number: a blank around it is an error, as in a JSON number.
  if (text.empty()) bad(text, "empty");
  if (std::isspace(static_cast<unsigned char>(text.front())) || std::isspace(static_cast<unsigned char>(text.back())))
    bad(text, "blank before or after the number");
  if (text.size() > detail::kMaxNumberChars) bad(text, "longer than the 10000-character limit");
  if (auto slash = text.find('/'); slash != std::string_view::npos) return parse_fraction(text, slash);
  return parse_decimal(text);
}

Rational exact_rational(double value) {
  if (!std::isfinite(value)) {
    std::ostringstream os;
    os << "not a finite number: " << value;
    throw InputError(os.str());
  }
  return Rational(value);  // mpq_set_d is exact for finite doubles
}

std::string to_string(const Integer& z) {
  std::string s(mpz_sizeinbase(z.mpz(), 10) + 2, '\0');
  mpz_get_str(s.data(), 10, z.mpz());
  s.resize(std::char_traits<char>::length(s.c_str()));
  return s;
}

std::string to_string(const Rational& q) {
  if (q.denominator() == 1) return to_string(q.numerator());
  return to_string(q.numerator()) + "/" + to_string(q.denominator());
}

std::string to_decimal(const Rational& q, int digits) {
  if (digits < 1) digits = 1;
  if (q == 0) return "0";
  // Exact: find e with 10^(digits-1) <= |q| * 10^-e < 10^digits, then round the scaled value.
  Rational a = q < 0 ? -q : q;
  long e = static_cast<long>(mpz_sizeinbase(a.numerator().mpz(), 10)) -
           static_cast<long>(mpz_sizeinbase(a.denominator().mpz(), 10)) - digits + 1;
  auto scaled = [&](long ex) {
    Rational t = a;
    if (ex >= 0)
      t /= Rational(power_of_ten(static_cast<unsigned long>(ex)));
    else
      t *= Rational(power_of_ten(static_cast<unsigned long>(-ex)));
    return t;
  };
  Integer lo = power_of_ten(static_cast<unsigned long>(digits - 1));
  Integer hi = power_of_ten(static_cast<unsigned long>(digits));
  Rational t = scaled(e);
  while (t >= Rational(hi)) t = scaled(++e);
  while (t < Rational(lo)) t = scaled(--e);
  // round half up: floor(t + 1/2)
  Rational half = t + Rational(1, 2);
  Integer r;
  mpz_fdiv_q(r.mpz(), half.numerator().mpz(), half.denominator().mpz());
  if (r == hi) {
    r = lo;
    ++e;
  }
  std::string ds = to_string(r);  // exactly `digits` digits
  std::string out = q < 0 ? "-" : "";
  long point = static_cast<long>(ds.size()) + e;  // position of decimal point in ds
  if (e >= 0 && point <= 21) {
    out += ds + std::string(static_cast<std::size_t>(e), '0');
  } else if (point > 0 && point <= 21) {
    out += ds.substr(0, static_cast<std::size_t>(point)) + "." + ds.substr(static_cast<std::size_t>(point));
  } else if (point <= 0 && point > -7) {
    out += "0." + std::string(static_cast<std::size_t>(-point), '0') + ds;
  } else {
    out += ds.substr(0, 1);
    if (ds.size() > 1) out += "." + ds.substr(1);
    out += "e" + std::to_string(point - 1);
  }
  // strip trailing zeros after a decimal point (but keep mantissa/exponent form intact)
  auto epos = out.find('e');
  std::string mantissa = out.substr(0, epos), rest = epos == std::string::npos ? "" : out.substr(epos);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  return mantissa + rest;
}

}  // namespace relpos
