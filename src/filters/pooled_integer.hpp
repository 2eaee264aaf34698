// PooledInteger: an exact integer (GMP mpz) for the exact-sign stage whose temporaries cost no heap
// allocation once the thread is warm.
//
// The generic formulas (pencil.hpp, sturm.hpp, smallness.hpp) create a few hundred temporaries per
// pair; with CGAL::Gmpz each one allocates a reference-counted handle and its limbs and frees them
// again, and on the 100- to 3000-bit numbers of the exact stage that traffic, not the arithmetic,
// was most of the time. Here every PooledInteger takes an initialised mpz_t, limbs included, from
// the thread's free list (algebra/recycled.hpp, the one strategy: doc/performance.md, "Memory: one
// strategy") and gives it back on destruction.
//
// Value semantics, ring operations and sign only: what the generic formulas need. Objects must be
// destroyed on the thread that created them (the exact stage uses them inside one call).
#pragma once

#include <gmp.h>

#include <memory>
#include <type_traits>
#include <utility>

#include "algebra/recycled.hpp"
#include "algebra/sturm.hpp"
#include "relpos/numbers.hpp"

namespace relpos {

class PooledInteger {
 public:
  PooledInteger() : z_(take()) { mpz_set_ui(z_, 0); }
  PooledInteger(long v) : z_(take()) { mpz_set_si(z_, v); }      // NOLINT: integer constants of the formulas
  PooledInteger(int v) : PooledInteger(static_cast<long>(v)) {}  // NOLINT
  explicit PooledInteger(const Integer& v) : z_(take()) { mpz_set(z_, v.mpz()); }
  PooledInteger(const PooledInteger& o) : z_(take()) { mpz_set(z_, o.z_); }
  PooledInteger(PooledInteger&& o) noexcept : z_(std::exchange(o.z_, nullptr)) {}
  PooledInteger& operator=(const PooledInteger& o) {
    if (this == &o) return *this;
    if (!z_) z_ = take();  // assigning to a moved-from object
    mpz_set(z_, o.z_);
    return *this;
  }
  PooledInteger& operator=(PooledInteger&& o) noexcept {
    std::swap(z_, o.z_);  // o gives back our old mpz when it dies
    return *this;
  }
  ~PooledInteger() {
    if (z_) give(z_);
  }

  Integer to_integer() const {
    Integer r;
    mpz_set(r.mpz(), z_);
    return r;
  }
  int sign() const { return mpz_sgn(z_); }
  /// The value, to be written in place (e.g. by forms::to_compact_integers).
  mpz_ptr mpz() { return z_; }
  mpz_srcptr mpz() const { return z_; }

  friend PooledInteger operator+(const PooledInteger& a, const PooledInteger& b) {
    PooledInteger r(Raw{});
    mpz_add(r.z_, a.z_, b.z_);
    return r;
  }
  friend PooledInteger operator-(const PooledInteger& a, const PooledInteger& b) {
    PooledInteger r(Raw{});
    mpz_sub(r.z_, a.z_, b.z_);
    return r;
  }
  friend PooledInteger operator*(const PooledInteger& a, const PooledInteger& b) {
    PooledInteger r(Raw{});
    if (mpz_sgn(a.z_) != 0 && mpz_sgn(b.z_) != 0)
      mpz_mul(r.z_, a.z_, b.z_);
    else
      r.z_->_mp_size = 0;  // 0, as mpz_set_ui(r, 0) writes it
    return r;
  }
  friend PooledInteger operator-(const PooledInteger& a) {
    PooledInteger r(Raw{});
    mpz_neg(r.z_, a.z_);
    return r;
  }
  // Rvalue overloads reuse a dying operand's mpz as the result (most temporaries are rvalues).
  friend PooledInteger operator+(PooledInteger&& a, const PooledInteger& b) {
    mpz_add(a.z_, a.z_, b.z_);
    return std::move(a);
  }
  friend PooledInteger operator-(PooledInteger&& a, const PooledInteger& b) {
    mpz_sub(a.z_, a.z_, b.z_);
    return std::move(a);
  }
  friend PooledInteger operator*(PooledInteger&& a, const PooledInteger& b) {
    mpz_mul(a.z_, a.z_, b.z_);
    return std::move(a);
  }
  friend PooledInteger operator+(const PooledInteger& a, PooledInteger&& b) {
    mpz_add(b.z_, a.z_, b.z_);
    return std::move(b);
  }
  friend PooledInteger operator-(const PooledInteger& a, PooledInteger&& b) {
    mpz_sub(b.z_, a.z_, b.z_);
    return std::move(b);
  }
  friend PooledInteger operator*(const PooledInteger& a, PooledInteger&& b) {
    mpz_mul(b.z_, a.z_, b.z_);
    return std::move(b);
  }
  friend PooledInteger operator+(PooledInteger&& a, PooledInteger&& b) { return std::move(a) + std::as_const(b); }
  friend PooledInteger operator-(PooledInteger&& a, PooledInteger&& b) { return std::move(a) - std::as_const(b); }
  friend PooledInteger operator*(PooledInteger&& a, PooledInteger&& b) { return std::move(a) * std::as_const(b); }
  friend PooledInteger operator-(PooledInteger&& a) {
    mpz_neg(a.z_, a.z_);
    return std::move(a);
  }
  // The fused forms of the generic formulas' acc +/- x y (pencil.hpp): no temporary at all, and no
  // call for a zero factor (most entries of an axis-aligned quadric's matrix are 0).
  friend void add_product(PooledInteger& acc, const PooledInteger& x, const PooledInteger& y) {
    if (mpz_sgn(x.z_) != 0 && mpz_sgn(y.z_) != 0) mpz_addmul(acc.z_, x.z_, y.z_);
  }
  friend void sub_product(PooledInteger& acc, const PooledInteger& x, const PooledInteger& y) {
    if (mpz_sgn(x.z_) != 0 && mpz_sgn(y.z_) != 0) mpz_submul(acc.z_, x.z_, y.z_);
  }

 private:
  struct Raw {};
  explicit PooledInteger(Raw) : z_(take()) {}  // value unspecified: the caller overwrites it

  /// An initialised mpz_t, its limbs kept while it waits on the free list.
  struct Mpz {
    __mpz_struct z;  // first member: &z and the Mpz share their address
    Mpz() { mpz_init(&z); }
    ~Mpz() { mpz_clear(&z); }
    Mpz(const Mpz&) = delete;
    Mpz& operator=(const Mpz&) = delete;
  };
  static_assert(std::is_standard_layout_v<Mpz>, "an Mpz pointer and its z pointer are interconvertible");
  static mpz_ptr take() { return &detail::Recycled<Mpz>::take().release()->z; }
  static void give(mpz_ptr z) { detail::Recycled<Mpz>::give(std::unique_ptr<Mpz>(reinterpret_cast<Mpz*>(z))); }

  mpz_ptr z_;
};

inline USign sign_of(const PooledInteger& x) {
  const int s = x.sign();
  return USign(s > 0 ? CGAL::POSITIVE : s < 0 ? CGAL::NEGATIVE : CGAL::ZERO);
}

}  // namespace relpos
