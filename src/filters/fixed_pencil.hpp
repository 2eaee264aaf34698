// The pencil's two polynomials g = det(mu P + E) and h = det(mu A + M) (math.md §2) for integer
// matrices whose entries are all below 2^62 in absolute value, in fixed-size integers: 2x2 minors
// in 128 bits, g and h summed in 320 bits, then written into the pooled integers once.
//
// Why: the integer forms of doubles (forms::integer_form) are 53-bit significands shifted to a
// common power of two, nearly always below 2^62; on them GMP's calls, not the arithmetic, are the
// cost of the determinant. Larger entries take the GMP path (exact_pencil.hpp); both give the same
// integers, the same formulas in the same ring.
//
// Overflow proof (|x| <= 2^62 - 1 for every entry x):
// - a 2x2 minor's coefficient (detail::linear_minor2) is a sum of at most 4 products of two entries,
//   every partial sum below 4 (2^62)^2 = 2^126 < 2^127: exact in a signed 128-bit integer;
// - a coefficient of g is a sum of at most 6 x 3 = 18 products u_a v_b of two such minors, each
//   below 2^252, every partial sum below 18 2^252 < 2^257; a coefficient of h a sum of at most 6
//   products of an entry and a minor, below 6 2^188 < 2^191: both exact in 320-bit two's
//   complement (|value| < 2^319), and each product (magnitude below 2^254) is formed exactly in 256
//   unsigned bits.
#pragma once

#include <gmp.h>

#include <cstdint>

#include "algebra/exact_pencil.hpp"
#include "algebra/forms.hpp"
#include "filters/checked_int.hpp"
#include "filters/pooled_integer.hpp"

namespace relpos {

namespace detail {

__extension__ typedef unsigned __int128 UInt128;  // __extension__: a GCC/Clang builtin type under -Wpedantic

/// A signed 320-bit integer in two's complement (five 64-bit limbs, least significant first):
/// the accumulator of the fixed-size pencil, with the fused acc +/- x y of exact_pencil.hpp.
struct Int320 {
  std::uint64_t limb[5] = {0, 0, 0, 0, 0};
  Int320() = default;
  explicit Int320(int v) {  // the formulas' NT(0): v sign-extended
    for (std::uint64_t& x : limb) x = v < 0 ? ~std::uint64_t{0} : 0;
    limb[0] = static_cast<std::uint64_t>(static_cast<std::int64_t>(v));
  }

  /// acc + x y (negate: acc - x y) for |x|, |y| < 2^127 with |x y| < 2^254 (the proof above).
  /// Without a branch on the signs (they are as good as random: a mispredicted branch per product
  /// would cost more than the arithmetic): |x| |y| in 256 bits, then acc + (P xor m) + (m and 1)
  /// over five limbs with m all ones for a negative term, the two's complement of P in 320 bits.
  /// Out of line: one copy for the some 70 call sites of the two polynomials (inlined at each,
  /// the code grew several times and measured 40 % slower).
  [[gnu::noinline]] void add(Int128 x, Int128 y, bool negate) {
    using U = UInt128;
    const Int128 sx = x >> 127, sy = y >> 127;  // 0 or -1
    const U ax = static_cast<U>((x ^ sx) - sx), ay = static_cast<U>((y ^ sy) - sy);
    const std::uint64_t m = static_cast<std::uint64_t>(sx ^ sy) ^ (0 - static_cast<std::uint64_t>(negate));
    const std::uint64_t xl = static_cast<std::uint64_t>(ax), xh = static_cast<std::uint64_t>(ax >> 64);
    const std::uint64_t yl = static_cast<std::uint64_t>(ay), yh = static_cast<std::uint64_t>(ay >> 64);
    // |x y| = ll + (lh + hl) 2^64 + hh 2^128 in four 64-bit limbs p[0..3].
    const U ll = static_cast<U>(xl) * yl, lh = static_cast<U>(xl) * yh, hl = static_cast<U>(xh) * yl,
            hh = static_cast<U>(xh) * yh;
    const U mid = (ll >> 64) + static_cast<std::uint64_t>(lh) + static_cast<std::uint64_t>(hl);  // < 3 2^64
    const U high = (mid >> 64) + (lh >> 64) + (hl >> 64) + static_cast<std::uint64_t>(hh);
    const std::uint64_t p[4] = {static_cast<std::uint64_t>(ll), static_cast<std::uint64_t>(mid),
                                static_cast<std::uint64_t>(high),
                                static_cast<std::uint64_t>((high >> 64) + static_cast<std::uint64_t>(hh >> 64))};
    U carry = m & 1;  // each sum below 2 2^64: the carry stays 0 or 1
    for (int i = 0; i < 4; ++i) {
      const U t = static_cast<U>(limb[i]) + (p[i] ^ m) + carry;
      limb[i] = static_cast<std::uint64_t>(t);
      carry = t >> 64;
    }
    limb[4] += m + static_cast<std::uint64_t>(carry);
  }

  /// Writes the value into z (mpz_limbs_write: sized once).
  void to_mpz(mpz_ptr z) const {
    static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "64-bit GMP limbs");
    const bool negative = (limb[4] >> 63) != 0;
    std::uint64_t m[5];
    std::uint64_t carry = 1;  // the magnitude of a negative value: its complement plus one
    for (int i = 0; i < 5; ++i) {
      m[i] = negative ? ~limb[i] + carry : limb[i];
      if (negative) carry = carry && m[i] == 0 ? 1 : 0;
    }
    int n = 5;
    while (n > 0 && m[n - 1] == 0) --n;
    if (n == 0) {
      mpz_set_ui(z, 0);
      return;
    }
    mp_limb_t* d = mpz_limbs_write(z, n);
    for (int i = 0; i < n; ++i) d[i] = m[i];
    mpz_limbs_finish(z, negative ? -n : n);
  }
};

// The fused products of exact_pencil.hpp for 128-bit minors summed in Int320 (found by
// argument-dependent lookup). A zero factor is skipped, as PooledInteger's skip it: a paraboloid's
// matrix is mostly zeros (a standard one has four non-zero entries), so most minors' coefficients
// and products are 0, in the same places pair after pair (the branch is predicted).
inline void add_product(Int320& acc, const Int128& x, const Int128& y) {
  if (x != 0 && y != 0) acc.add(x, y, false);
}
inline void sub_product(Int320& acc, const Int128& x, const Int128& y) {
  if (x != 0 && y != 0) acc.add(x, y, true);
}

/// Whether every entry of m is below 2^62 in absolute value, then copied into out.
inline bool small_entries(const forms::MatrixOf<PooledInteger>& m, forms::MatrixOf<std::int64_t>& out) {
  for (std::size_t i = 0; i < 16; ++i) {
    const mpz_srcptr z = m.a[i].mpz();
    const int size = z->_mp_size;
    if (size == 0) {
      out.a[i] = 0;
      continue;
    }
    if ((size != 1 && size != -1) || (z->_mp_d[0] >> 62) != 0) return false;
    const auto magnitude = static_cast<std::int64_t>(z->_mp_d[0]);
    out.a[i] = size < 0 ? -magnitude : magnitude;
  }
  return true;
}

}  // namespace detail

/// g = exact_characteristic_polynomial(p, e) and h = exact_special_polynomial(p, e) in fixed-size
/// integers, written into g and h, for entries all below 2^62 in absolute value (the caller's
/// promise: the proof above rests on it).
inline void small_pencil_polynomials(const detail::forms::MatrixOf<std::int64_t>& p,
                                     const detail::forms::MatrixOf<std::int64_t>& e, Quartic<PooledInteger>& g,
                                     Quadratic<PooledInteger>& h) {
  // The minors in 128 bits: products of two 64-bit words.
  const Quartic<detail::Int320> gs =
      exact_characteristic_polynomial<Int128, detail::forms::MatrixOf<std::int64_t>, detail::Int320>(p, e);
  const Quadratic<detail::Int320> hs =
      exact_special_polynomial<Int128, detail::forms::MatrixOf<std::int64_t>, detail::Int320>(p, e);
  for (std::size_t i = 0; i < 5; ++i) gs[i].to_mpz(g[i].mpz());
  for (std::size_t i = 0; i < 3; ++i) hs[i].to_mpz(h[i].mpz());
}

/// The same for integer matrices in pooled integers when every entry is below 2^62 in absolute
/// value; false (g and h untouched) otherwise.
inline bool small_pencil_polynomials(const detail::forms::MatrixOf<PooledInteger>& p,
                                     const detail::forms::MatrixOf<PooledInteger>& e, Quartic<PooledInteger>& g,
                                     Quadratic<PooledInteger>& h) {
  detail::forms::MatrixOf<std::int64_t> ps, es;
  if (!detail::small_entries(p, ps) || !detail::small_entries(e, es)) return false;
  small_pencil_polynomials(ps, es, g, h);
  return true;
}

}  // namespace relpos
