// The pair's size limit (kMaxNormalizedBits, doc/cli.md, Limits): the bits of a matrix's primitive
// integer form, bounded first from the lcm of its denominators alone.
#include "algebra/pair_size.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <string>

#include "algebra/forms.hpp"
#include "relpos/error.hpp"
#include "relpos/quadric.hpp"

namespace relpos {
namespace {

/// An upper bound on normalized_bits(m) from the lcm of the denominators alone: each entry of the
/// integer form, num * (l / den), has at most bits(num) + bits(l) - bits(den) + 1 bits.
std::size_t normalized_bits_bound(const Matrix4& m) {
  Integer l(1);
  detail::forms::lcm_of_denominators(m.a.begin(), m.a.end(), l);
  const std::size_t lb = mpz_sizeinbase(l.mpz(), 2);
  std::size_t bound = 0;
  for (const Rational& q : m.a)
    bound = std::max(bound, mpz_sizeinbase(mpq_numref(q.mpq()), 2) + lb + 1 - mpz_sizeinbase(mpq_denref(q.mpq()), 2));
  return bound;
}

}  // namespace

std::size_t detail::normalized_bits(const Matrix4& m) {
  Integer l(1), g(0);
  forms::lcm_of_denominators(m.a.begin(), m.a.end(), l);
  std::array<Integer, 16> z;
  for (std::size_t i = 0; i < 16; ++i) {
    forms::scaled_numerator(m.a[i], l, z[i].mpz());
    mpz_gcd(g.mpz(), g.mpz(), z[i].mpz());
  }
  if (g == 0) return 0;
  std::size_t bits = 0;
  for (auto& x : z) {
    if (x == 0) continue;
    mpz_divexact(x.mpz(), x.mpz(), g.mpz());
    bits = std::max<std::size_t>(bits, mpz_sizeinbase(x.mpz(), 2));
  }
  return bits;
}

std::size_t detail::normalized_pair_bits(const Ellipsoid& e, const Paraboloid& p) {
  return std::max(normalized_bits(e.matrix()), normalized_bits(p.matrix()));
}

namespace detail {
namespace {

/// The limit itself: raised, never lowered.
void check_limit(const SizeLimit& limit) {
  if (limit.max_bits < kMaxNormalizedBits)
    throw InputError("the size limit is at least " + std::to_string(kMaxNormalizedBits) + " bits, got " +
                     std::to_string(limit.max_bits) + " (it can be raised, not lowered: doc/cli.md, Limits)");
}

/// A bound on normalized_bits of m's matrix, exact when it exceeds kMaxNormalizedBits. A matrix of
/// doubles is within the limit whatever its entries: its primitive form has at most 2098 bits (every
/// double is a multiple of 2^-1074 below 2^1024), so it costs nothing then and never builds the
/// exact matrix of a quadric made from doubles. The bound from the lcm alone settles ordinary inputs
/// (decimals with their powers of ten) without the gcd and the products.
std::size_t bits_of(const QuadricMatrix& m) {
  static_assert(kMaxNormalizedBits >= 2098, "every matrix of doubles must pass");
  if (m.within_size_limit()) return 0;
  const std::size_t bound = normalized_bits_bound(m.matrix());
  return bound <= kMaxNormalizedBits ? bound : normalized_bits(m.matrix());
}

std::size_t checked(std::size_t bits, const SizeLimit& limit) {
  if (bits > limit.max_bits)
    throw InputError(
        "numbers too large: a matrix of the pair, divided by its own content (its primitive integer "
        "form), has " +
        std::to_string(bits) + "-bit entries, beyond the limit of " + std::to_string(limit.max_bits) +
        (limit.max_bits == kMaxNormalizedBits ? " bits (kMaxNormalizedBits, doc/cli.md, Limits)"
                                              : " bits (the limit given, doc/cli.md, Limits)"));
  return bits;
}

}  // namespace

std::size_t check_normalized_size(const QuadricMatrix& a, const QuadricMatrix& b, const SizeLimit& limit) {
  check_limit(limit);
  return checked(std::max(bits_of(a), bits_of(b)), limit);
}

std::size_t check_normalized_size(const QuadricMatrix& a, const SizeLimit& limit) {
  check_limit(limit);
  return checked(bits_of(a), limit);
}

std::size_t check_normalized_pair_size(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit) {
  return check_normalized_size(storage_of(e), storage_of(p), limit);
}

}  // namespace detail
}  // namespace relpos
