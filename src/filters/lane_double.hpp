// W doubles operated on lane by lane, one pair of quadrics per lane: the number type of the
// many-pairs filter (static_filter_lanes.hpp, math.md §11).
//
// The generic formulas (the pencil's f and s, 27 Disc(f), the smallness and gap quantities) are
// templates over their number type using ring operations only; instantiated on LaneDouble<W> they
// evaluate W pairs at once with the template's operations in the template's order. Each lane rounds
// exactly as the scalar double operation (IEEE lane by lane, and no contraction: -ffp-contract=off),
// so every lane holds bit for bit the double of the scalar instantiation, and the error bounds the
// static filter derives on that template hold lane by lane. GCC/Clang vector extension: with AVX2 a
// LaneDouble<4> is one ymm register, in the baseline x86-64 ISA two xmm registers; with AVX-512 a
// LaneDouble<8> is one zmm register.
//
// Only ring operations and bit casts here: GCC expands a comparison of vectors wider than the ISA of
// the function it is written in piecewise before that function is inlined into an AVX copy, so the
// comparisons live with the code compiled for each ISA (static_filter_lanes_route.inc).
#pragma once

#include <cstddef>

namespace relpos::detail {

/// The vector types of W lanes: doubles, a comparison's result (all ones or zero per lane: GCC gives
/// `long` lanes) and the bits of a double as unsigned lanes. Spelt out per width: GCC does not apply
/// a vector_size that depends on a template parameter.
template <int W>
struct LaneVectors;
template <>
struct LaneVectors<4> {
  typedef double Vec __attribute__((vector_size(32)));
  typedef long Mask __attribute__((vector_size(32)));
  typedef unsigned long Bits __attribute__((vector_size(32)));
};
template <>
struct LaneVectors<8> {
  typedef double Vec __attribute__((vector_size(64)));
  typedef long Mask __attribute__((vector_size(64)));
  typedef unsigned long Bits __attribute__((vector_size(64)));
};

template <int W>
struct LaneDouble {
  using Vec = typename LaneVectors<W>::Vec;
  using Mask = typename LaneVectors<W>::Mask;
  using Bits = typename LaneVectors<W>::Bits;

  Vec v;

  LaneDouble() = default;
  /// Every lane x (implicit: the templates write NT(2) and mix constants into their formulas).
  [[gnu::always_inline]] LaneDouble(double x) {  // NOLINT(google-explicit-constructor)
    for (int i = 0; i < W; ++i) v[i] = x;
  }
  [[gnu::always_inline]] explicit LaneDouble(const Vec& x) : v(x) {}

  [[gnu::always_inline]] friend LaneDouble operator+(const LaneDouble& a, const LaneDouble& b) {
    return LaneDouble(a.v + b.v);
  }
  [[gnu::always_inline]] friend LaneDouble operator-(const LaneDouble& a, const LaneDouble& b) {
    return LaneDouble(a.v - b.v);
  }
  [[gnu::always_inline]] friend LaneDouble operator*(const LaneDouble& a, const LaneDouble& b) {
    return LaneDouble(a.v * b.v);
  }
  /// The sign flipped (exact, as the scalar -x).
  [[gnu::always_inline]] friend LaneDouble operator-(const LaneDouble& a) { return LaneDouble(-a.v); }
};

/// A LaneDouble that may be known, for the whole block, to be zero in every lane: the number type
/// of the pencil when every paraboloid of a block has the same zero entries (an axis-aligned one has
/// seven, math.md §11). `zero` is known when the code is compiled (it comes from the entries'
/// positions, constants once the formula is unrolled), so a product with a known zero, and adding
/// or subtracting one, are left out of the compiled code. Every value that is not zero is then the
/// double the full formula computes, bit for bit: a product with an exact zero is a zero (the other
/// factor is finite), and adding a zero to x gives x exactly. Only the sign of a zero result may
/// differ, and no later operation of the route reads it (a certified sign needs |v| above a positive
/// bound, and zeros have no exponent).
template <int W>
struct MaybeZero {
  LaneDouble<W> x;
  bool zero;

  MaybeZero() = default;
  [[gnu::always_inline]] MaybeZero(double c) : x(c), zero(c == 0) {}  // NOLINT(google-explicit-constructor)
  [[gnu::always_inline]] MaybeZero(const LaneDouble<W>& v, bool z) : x(v), zero(z) {}

  [[gnu::always_inline]] friend MaybeZero operator*(const MaybeZero& a, const MaybeZero& b) {
    if (a.zero || b.zero) return MaybeZero(0.0);
    return {a.x * b.x, false};
  }
  [[gnu::always_inline]] friend MaybeZero operator+(const MaybeZero& a, const MaybeZero& b) {
    if (b.zero) return a;
    if (a.zero) return b;
    return {a.x + b.x, false};
  }
  [[gnu::always_inline]] friend MaybeZero operator-(const MaybeZero& a, const MaybeZero& b) {
    if (b.zero) return a;
    if (a.zero) return -b;
    return {a.x - b.x, false};
  }
  [[gnu::always_inline]] friend MaybeZero operator-(const MaybeZero& a) { return {-a.x, a.zero}; }
};

/// A LaneMatrix read as MaybeZero entries, the entries whose bit is set in `zero` (bit 4 i + j for
/// entry (i, j)) known to be zero (a constant where the formulas are inlined).
template <int W>
struct KnownZeros {
  const LaneDouble<W>* a;
  unsigned zero;
  [[gnu::always_inline]] MaybeZero<W> operator()(int i, int j) const {
    return {a[4 * i + j], ((zero >> (4 * i + j)) & 1) != 0};
  }
};

/// A matrix of W pairs' entries in structure-of-arrays form: entry (i, j) of every lane in one
/// LaneDouble, read by the generic formulas through m(i, j) as a row-major matrix.
template <int W>
struct LaneMatrix {
  LaneDouble<W> a[16];
  [[gnu::always_inline]] const LaneDouble<W>& operator()(int i, int j) const { return a[4 * i + j]; }
};

}  // namespace relpos::detail
