// JSON in and out for the general quadrics (doc/cli.md, "General quadrics"; math.md §14–§18): the
// "quadric" of a batch line or of `relpos classify --quadric` (from an exact tree, json_tree.hpp),
// the text report, and the certificates' JSON form, read back by `relpos verify`. The JSON answers
// are written by the one answer writer (answer_json.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include "algebra/large_stack.hpp"
#include "io/json_tree.hpp"
#include "relpos/general_classify.hpp"

namespace relpos::detail::io {

/// A general quadric from a tree of detail::parse_json: a 4x4 array, {"matrix"}, {"coefficients"},
/// or a geometric form {"type": NAME, ...} with NAME one of to_string(QuadricType) or "sphere":
///   sphere {"center", "radius"}; ellipsoid and the hyperboloids {"center", "axes", "rotation"?};
///   "elliptic cone" {"apex", "a", "b", "rotation"?}; the paraboloids {"vertex", "a", "b", "rotation"?};
///   the elliptic and hyperbolic cylinders {"center", "a", "b", "rotation"?}; "parabolic cylinder"
///   {"vertex", "a", "rotation"?}; "half-space" {"normal", "offset"}; "slab" {"normal", "low", "high"}.
/// InputError "<role>: ..." naming the field, or what the matrix is when it is refused.
Quadric quadric_from_json(const Json& value, const std::string& role = "quadric");

/// The pair's size limit (doc/cli.md, Limits): InputError "numbers too large: ..." when a matrix's
/// primitive integer form has entries beyond limit.max_bits bits (--max-bits, max_bits), the
/// message of check_normalized_pair_size. Free for matrices of doubles (always within the limit).
/// Returns the bits as check_normalized_size does (0 or at most kMaxNormalizedBits within the default).
std::size_t check_general_pair_size(const Ellipsoid& e, const Quadric& q, const SizeLimit& limit = {});

/// f() directly, or, for a pair beyond the default size limit (`bits` from check_general_pair_size
/// under a raised limit), on a thread whose stack fits the exact stage's root isolation, whose
/// recursion grows with the numbers (algebra/large_stack.hpp; as decide_position does for a paraboloid).
template <class F>
auto with_stack_for_general(std::size_t bits, F f) -> decltype(f()) {
  if (bits <= kMaxNormalizedBits) return f();
  std::optional<decltype(f())> out;
  relpos::detail::run_on_large_stack(relpos::detail::stack_for_bits(bits), [&] { out.emplace(f()); });
  return std::move(*out);
}

/// check_general_pair_size for many ellipsoids against one quadric (a scene, Python's
/// decide_positions): the quadric's own size computed once, each ellipsoid's as it comes; the same
/// errors with the same messages.
class GeneralPairSize {
 public:
  explicit GeneralPairSize(const Quadric& q, const SizeLimit& limit = {});
  /// The bits as check_general_pair_size returns them (a bound: exact beyond kMaxNormalizedBits).
  std::size_t check(const Ellipsoid& e) const;

 private:
  const Quadric& q_;
  SizeLimit limit_;
  std::size_t q_bits_ = 0;  ///< q's bits as check_normalized_size returns them
  bool within_ = true;      ///< q alone is within the limit
};

/// The same pair as a multi-line report (relpos classify --quadric).
std::string general_answer_text(const QuadricClassification& c, int digits);

/// The JSON form of a general certificate (exact numbers as strings):
///   Definite {"t"}; Tangent {"t", "contact"}; HardTangent {"t": {"a", "b", "d"}, "contact_set":
///   {"center", "directions", "radius2", "decimal"}}; Crossing {"inside", "outside", "beyond"?};
///   Equal {"ratio"}.
Json quadric_certificate_to_json(const QuadricCertificate& c, int digits);
/// The inverse (numbers also as JSON numbers, read exactly); InputError naming the field.
QuadricCertificate quadric_certificate_from_json(const Json& j);

/// "I", "TI", ..., "EQ" back to the position, or nullopt.
std::optional<QuadricPosition> quadric_position_from_text(const std::string& s);

}  // namespace relpos::detail::io
