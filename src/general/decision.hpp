// The decision of math.md §16, written once: from where the real roots of f lie against the ends
// of the multipliers' intervals to a position and its rule. Both the certified double filter
// (filter.hpp) and the exact stage (exact.hpp) fill the same facts and call decide().
#pragma once

#include <array>

#include "relpos/general_classify.hpp"

namespace relpos::detail::general {

/// The roots of f on one side (math.md §15): in the open interval of multipliers of that side, and
/// at its finite end.
struct SideFacts {
  bool odd = false;       ///< a root of odd multiplicity in the open interval: the optimum is strict
  bool any = false;       ///< any root in the open interval
  bool endpoint = false;  ///< mult_f(end) > mult_D(end): f~ = f / gcd(f, D) vanishes at the end
  /// The optimum is 0 (a tangency) without being strict.
  bool zero() const { return !odd && (any || endpoint); }
};

/// The three sides: min q over E (interval (t_lo, oo)), max q over E ((-oo, t_hi)) and, when Q is an
/// ellipsoid, max e over Q ((r3, 0)).
struct PencilFacts {
  SideFacts min, max, inner;
  bool ellipsoid = false;  ///< Q is an ellipsoid: the inner side counts
};

/// math.md §16: E, TE (min side), then I, TI (max side), then O, TO (inner side), EQ when the max and
/// the inner side are both tangent, C otherwise.
inline QuadricVerdict decide(const PencilFacts& f) {
  QuadricVerdict v;
  auto set = [&v](QuadricPosition p, QuadricRule r) {
    v.position = p;
    v.rule = r;
    return v;
  };
  if (f.min.odd) return set(QuadricPosition::E, QuadricRule::OddRootAboveLo);
  if (f.min.zero()) return set(QuadricPosition::TE, f.min.any ? QuadricRule::EvenRootAboveLo : QuadricRule::EndpointLo);
  if (f.max.odd) return set(QuadricPosition::I, QuadricRule::OddRootBelowHi);
  if (f.max.zero()) {
    if (f.ellipsoid && f.inner.zero()) return set(QuadricPosition::EQ, QuadricRule::Equal);
    return set(QuadricPosition::TI, f.max.any ? QuadricRule::EvenRootBelowHi : QuadricRule::EndpointHi);
  }
  if (f.ellipsoid) {
    if (f.inner.odd) return set(QuadricPosition::O, QuadricRule::OddRootInner);
    if (f.inner.zero())
      return set(QuadricPosition::TO, f.inner.any ? QuadricRule::EvenRootInner : QuadricRule::EndpointInner);
  }
  return set(QuadricPosition::C, QuadricRule::NoRoot);
}

/// Every position of a general pair, in enum order (the JSON reader names them from here).
inline constexpr std::array kAllQuadricPositions{QuadricPosition::I,  QuadricPosition::TI, QuadricPosition::C,
                                                 QuadricPosition::TE, QuadricPosition::E,  QuadricPosition::O,
                                                 QuadricPosition::TO, QuadricPosition::EQ};
/// Every type of the second body, in enum order.
inline constexpr std::array kAllQuadricTypes{QuadricType::Ellipsoid,
                                             QuadricType::HyperboloidOneSheet,
                                             QuadricType::HyperboloidTwoSheets,
                                             QuadricType::Cone,
                                             QuadricType::EllipticParaboloid,
                                             QuadricType::HyperbolicParaboloid,
                                             QuadricType::EllipticCylinder,
                                             QuadricType::HyperbolicCylinder,
                                             QuadricType::ParabolicCylinder,
                                             QuadricType::Slab,
                                             QuadricType::HalfSpace};

}  // namespace relpos::detail::general
