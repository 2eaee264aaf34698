// A 128-bit machine integer that knows when it has overflowed: the exact number type of the
// machine-integer stages (multiple_roots.hpp).
//
// Why not GMP: an exact tangency given as doubles needs only a few dozen exact operations on
// numbers of well under 128 bits, but every Gmpz temporary is a heap allocation; profiling the
// exact stages showed ~70% of their time in malloc/free. CheckedInt is a plain value (no
// allocation). Overflow is not an error: it makes the value *invalid*, invalid values propagate
// through every operation like NaN, and sign_of() of an invalid value is uncertain -- exactly the
// failure mode of an interval filter, so callers fall back to GMP by the same rule.
//
// It models the ring operations the generic pencil code uses (NT(0), +, -, *, unary -), so
// characteristic_polynomial<CheckedInt> and special_polynomial<CheckedInt> are exact or invalid.
#pragma once

#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

namespace relpos {

__extension__ typedef __int128 Int128;  // __extension__: GCC/Clang builtin type under -Wpedantic

class CheckedInt {
 public:
  using Int = Int128;

  constexpr CheckedInt() = default;
  constexpr CheckedInt(int x) : v_(x) {}  // NOLINT: implicit like the other number types
  explicit constexpr CheckedInt(long long x) : v_(x) {}
  static constexpr CheckedInt from(Int x) { return CheckedInt(x, true); }
  static constexpr CheckedInt invalid() { return CheckedInt(0, false); }

  constexpr bool valid() const { return ok_; }
  /// The value; meaningful only when valid().
  constexpr Int value() const { return v_; }

  friend CheckedInt operator+(const CheckedInt& a, const CheckedInt& b) {
    Int r;
    const bool of = __builtin_add_overflow(a.v_, b.v_, &r);
    return CheckedInt(r, a.ok_ && b.ok_ && !of);
  }
  friend CheckedInt operator-(const CheckedInt& a, const CheckedInt& b) {
    Int r;
    const bool of = __builtin_sub_overflow(a.v_, b.v_, &r);
    return CheckedInt(r, a.ok_ && b.ok_ && !of);
  }
  friend CheckedInt operator*(const CheckedInt& a, const CheckedInt& b) {
    // Fast path: a product of two 64-bit values always fits in 127 bits (one multiply instruction;
    // the checked 128-bit multiply is several times slower).
    if (fits64(a.v_) && fits64(b.v_)) return CheckedInt(a.v_ * b.v_, a.ok_ && b.ok_);
    Int r;
    const bool of = __builtin_mul_overflow(a.v_, b.v_, &r);
    return CheckedInt(r, a.ok_ && b.ok_ && !of);
  }
  CheckedInt operator-() const { return CheckedInt(0) - *this; }
  CheckedInt& operator+=(const CheckedInt& b) { return *this = *this + b; }
  CheckedInt& operator-=(const CheckedInt& b) { return *this = *this - b; }
  CheckedInt& operator*=(const CheckedInt& b) { return *this = *this * b; }

  /// a / b when b divides a exactly; invalid otherwise (or when b = 0).
  friend CheckedInt exact_quotient(const CheckedInt& a, const CheckedInt& b) {
    if (!a.ok_ || !b.ok_ || b.v_ == 0) return invalid();
    if (b.v_ == -1) return -a;           // avoids the overflowing MIN / -1
    if (fits64(a.v_) && fits64(b.v_)) {  // hardware division instead of the libgcc 128-bit routine
      const auto x = static_cast<long long>(a.v_), y = static_cast<long long>(b.v_);
      if (x % y != 0) return invalid();
      return from(x / y);
    }
    if (a.v_ % b.v_ != 0) return invalid();
    return from(a.v_ / b.v_);
  }

  /// -1, 0, +1; only for valid values.
  constexpr int sign() const { return v_ > 0 ? 1 : (v_ < 0 ? -1 : 0); }

 private:
  constexpr CheckedInt(Int v, bool ok) : v_(v), ok_(ok) {}
  static constexpr bool fits64(Int x) { return x == static_cast<long long>(x); }
  Int v_ = 0;
  bool ok_ = true;
};

/// Certain sign for a valid value, uncertain after an overflow (the caller falls back to GMP).
inline CGAL::Uncertain<CGAL::Sign> sign_of(const CheckedInt& x) {
  if (!x.valid()) return CGAL::Uncertain<CGAL::Sign>::indeterminate();
  return CGAL::Uncertain<CGAL::Sign>(static_cast<CGAL::Sign>(x.sign()));
}

}  // namespace relpos
