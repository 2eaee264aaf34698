// The fast reader's view of a JSON value (fast_quadric.hpp): a bounded tree (at most 32 nodes,
// depth 3) of arrays, objects with plain keys, and numbers, each number kept as the decimal it spells
// (its exact identity, detail::Decimal) and enclosed by at most three exactly-rounded operations.
// Tokens come from the one lexer (json_lexer.hpp); anything else makes parse() fail, and the caller
// takes the general reader.
#pragma once

#include <CGAL/Interval_nt.h>

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>

#include "algebra/decimal_recipe.hpp"

namespace relpos::detail::io {

using FastInterval = CGAL::Interval_nt<false>;

/// A number as read: its identity and its enclosure.
struct FastNumber {
  relpos::detail::Decimal d;
  FastInterval x;
};

enum class FastKind : unsigned char { Number, Array, Object };

struct FastNode {
  FastKind kind = FastKind::Number;
  std::string_view key;  ///< the member name, inside an object
  int child = -1;        ///< first child (arrays and objects)
  int next = -1;         ///< next sibling
  int count = 0;         ///< children
  FastNumber number;
};

class FastValue {
 public:
  static constexpr int kMaxNodes = 32;
  static constexpr int kMaxDepth = 3;
  static constexpr int kMaxDigits = 19;  ///< significant digits: m < 10^19 < 2^64
  static constexpr int kMaxExponent =
      30;  ///< |e| of a short number, trailing zeros removed (fast_quadric.hpp's size bound)
  /// |e| of any number read: beyond kMaxExponent a number is "wide", taken only in a matrix whose
  /// exponents span at most 2 kMaxExponent (a matrix scaled by a power of ten; fast_quadric.hpp).
  static constexpr int kMaxWideExponent = 340;  ///< beyond, m 10^e leaves the double range

  /// Whether any number read is wide: a decimal with |e| > kMaxExponent (a double, --numbers
  /// double, never is). Known once enclose_decimals() has run.
  bool any_wide() const { return wide_; }

  /// `doubles`: each number is the double nearest its text (--numbers double).
  FastValue(std::string_view text, bool doubles) : s_(text), doubles_(doubles) {}

  /// The root node, or -1 when the text is not entirely one value of the accepted kinds.
  int parse();
  /// The root node of the value at the start of the text, or -1; the value ends at end().
  int parse_prefix();
  std::size_t end() const { return i_; }
  const FastNode& node(int k) const { return nodes_[k].node; }

  /// The enclosures of the decimal numbers: m exactly (a sum of two exact doubles when m > 2^53),
  /// then one exactly-rounded operation with 10^|e| (two when |e| > 22; for a wide number, with an
  /// enclosure of 10^|e| made once), and whether any is wide (any_wide). Call with the rounding
  /// mode towards +inf.
  void enclose_decimals();

  /// The child of an object named `name`, or -1.
  int member(int object, std::string_view name) const {
    for (int k = node(object).child; k >= 0; k = node(k).next)
      if (node(k).key == name) return k;
    return -1;
  }
  /// The numbers of an array of exactly N numbers, or false.
  template <std::size_t N>
  bool numbers(int array, std::array<FastNumber, N>& out) const {
    if (array < 0 || node(array).kind != FastKind::Array || node(array).count != static_cast<int>(N)) return false;
    std::size_t i = 0;
    for (int k = node(array).child; k >= 0; k = node(k).next) {
      if (node(k).kind != FastKind::Number) return false;
      out[i++] = node(k).number;
    }
    return true;
  }

 private:
  int new_node(FastKind kind);
  [[gnu::always_inline]] inline int value(int depth);
  int container(int depth, bool object);
  [[gnu::always_inline]] inline bool member_key(int self, std::string_view& name);
  /// A number, `quoted` when its text starts with '"' (a decimal written as a JSON string).
  template <bool quoted>
  int number();

  std::string_view s_;
  bool doubles_;
  std::size_t i_ = 0;
  int n_ = 0;
  bool decimals_ = false;
  bool wide_ = false;
  union Slot {  // storage: a node is made when it is read (most of the kMaxNodes are never used)
    Slot() {}
    FastNode node;
  };
  static_assert(std::is_trivially_destructible<FastNode>::value, "a Slot does not destroy its node");
  Slot nodes_[kMaxNodes];
};

}  // namespace relpos::detail::io
