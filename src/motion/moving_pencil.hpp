// The pencil of a moving pair over Z[t] (math.md §7): f = det(l P + E(t)) and s = det(l A + M(t))
// with coefficients in Z[t] (the generic pencil code of pencil.hpp on CGAL::Polynomial), the
// polynomials in t whose signs decide (Sturm-Habicht principal coefficients, the smallness
// quantities), and the event polynomials whose real zeros are the only instants where the position
// can change.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "algebra/pencil.hpp"
#include "motion/instant_position.hpp"
#include "relpos/motion.hpp"

namespace relpos::detail {

/// The polynomials [first, last) divided by the gcd of all their integer coefficients (a positive
/// factor: signs, roots and ratios of polynomials divided by the same constant are kept).
void make_primitive(PolyZ* first, PolyZ* last);

/// The moving pencil, every polynomial a positive multiple of the true quantity.
struct MovingPencil {
  Quartic<PolyZ> f;
  Quadratic<PolyZ> s;
  // Sturm-Habicht sequence of f in l (sturm.hpp): StHa_j = (non-zero constant) * g_j, so the
  // principal coefficients g2[0], g1[0], disc are the principal subresultant coefficients of f and
  // df/dl up to non-zero constants, and StHa_1 = g1[0] l + g1[1], StHa_2 = g2[0] l^2 + g2[1] l + g2[2].
  PolyZ g2[3], g1[2], disc;
  PolyZ vertex, graeffe;  // smallness quantities (smallness.hpp), polynomials in t
  bool disc_zero = false;
  PolyZ merge;  // real zeros contain every t where two roots of f meet (Disc f, or Disc of sqf(f))
  std::vector<std::pair<PolyZ, unsigned>> events;  // every candidate instant, with its cause
  std::optional<InstantPencil> instant;            // the decision at instants where f has a multiple root

  MovingPencil(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p);

 private:
  void add_square_free_events();
  void add_multiple_factor_events();
};

}  // namespace relpos::detail
