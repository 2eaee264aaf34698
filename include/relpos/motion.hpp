// Positions along a rigid polynomial motion (math.md §7): the certified first-contact time
// of an ellipsoid that starts exterior to a fixed paraboloid, and the full timeline of positions on
// a time interval [t0, t1].
//
// With E(t) the moving ellipsoid (below), f(l, t) = det(l P + E(t)) and
// s(l, t) = det(l A + M(t)) are polynomials in l and t. Between consecutive real zeros of the event
// polynomials (Disc_l f, or when it vanishes identically the discriminant of the square-free part
// of f and the resultants that track roots shared with s; the two smallness quantities) the root
// structure of f relative to s, hence the position, is constant: it is classified exactly at one
// rational time of each open interval. At a zero t* the position is decided exactly, for any size:
// with relpos::classify when t* is rational; otherwise, when f(., t*) is square-free, it is the
// (open) position of the neighbouring intervals, and when it is not, the real roots of f(., t*) are
// read off the subresultants of f and df/dl and the pencil l P + E(t*) is tested for definiteness
// between and at them, every sign being the sign of a univariate integer polynomial at the
// algebraic number t*.
//
// Rigid motions:
// Rigid motions whose matrices are polynomial in time (math.md §7).
//
// The ellipsoid is given in a reference placement E0 (a validated Ellipsoid). At time t it is the
// image of E0 under the rigid map
//
//   x = R(t) (y - p) + p + c(t),
//
// with c(t) a vector of polynomials in t (rational coefficients), p a fixed pivot (the origin, the
// centre of E0, or any point), and R(t) = Q(q(t)) / N(t) the rotation of a polynomial quaternion
// q(t) = (w, x, y, z)(t), not necessarily unit: Q holds quadratic forms in q, N = |q|^2 (the same
// formula as rotation_from_quaternion). Without a quaternion R = I.
//
// "Body frame" input (an ellipsoid centred at the origin, placed by the motion) is pivot = origin;
// "world frame" input (the ellipsoid where it is at the reference time, turned about its own
// centre) is pivot = centre. The placement at t equals E0 exactly when c(t) = 0 and q(t) is a
// multiple of (1, 0, 0, 0).
//
// With T(t) the map above, T^-1 = [[R^T, p - R^T (p + c)], [0, 1]] and
//   N T^-1 = [[Q^T, N p - Q^T (p + c)], [0, N]]
// is polynomial in t, so E(t) = (N T^-1)^T E0 (N T^-1) = N^2 T^-T E0 T^-1 is a polynomial matrix: the
// placed ellipsoid times the positive factor N^2, which changes no sign and no root multiplicity
// relpos looks at (math.md §1).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "relpos/algebraic_real.hpp"
#include "relpos/classify.hpp"
#include "relpos/interrupt.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

// ---- Rigid motions whose matrices are polynomial in time

/// A polynomial in time t with exact rational coefficients, index = power of t (low degree first).
/// The empty vector is the zero polynomial. p(t) is evaluate(p, t) (relpos/polynomials.hpp).
using TimePolynomial = RationalPolynomial;

/// Where the rotation R(t) is applied.
enum class Pivot {
  Origin,  ///< x = R(t) y + c(t)             (ellipsoid given in its body frame)
  Centre,  ///< about the centre of E0        (ellipsoid given where it is at the reference time)
  Point,   ///< about RigidMotion::pivot_point
};

struct RigidMotion {
  std::array<TimePolynomial, 3> translation;              ///< c(t); empty entries are 0
  std::optional<std::array<TimePolynomial, 4>> rotation;  ///< q(t) = (w, x, y, z); absent: R = I
  Pivot pivot = Pivot::Origin;
  Vector3 pivot_point{};  ///< used when pivot == Pivot::Point

  /// Pure translation by c(t).
  static RigidMotion translating(std::array<TimePolynomial, 3> c);
};

/// The centre -M^-1 e of an ellipsoid, exactly.
Vector3 centre_of(const Ellipsoid& e);

// ---- Positions along the motion

/// Why an instant of the timeline is there (bit flags).
enum EventCause : unsigned {
  kCauseStart = 1,         ///< t0
  kCauseEnd = 2,           ///< t1
  kCauseDiscriminant = 4,  ///< a root of f merges with another (Disc_l of f, or of its square-free part)
  kCauseSpecialRoot =
      8,  ///< a root of f meets a root of s, or the roots of s merge (only when Disc_l f = 0 identically)
  kCauseSmallness = 16,  ///< rho(t) - 1 may change sign (a zero of a smallness quantity)
};

/// The position at one instant.
struct MotionInstant {
  AlgebraicReal time;
  Position position = Position::C;
  bool small = false;  ///< rho(t) <= 1 at that instant (reported; no answer depends on it)
  unsigned causes = 0;
  std::string how;  ///< how the position was decided, one sentence
};

/// The position on the open interval between two consecutive instants (constant there).
struct MotionInterval {
  Rational sample;  ///< the rational time inside the interval where it was classified
  Position position = Position::C;
  bool small = false;
};

/// An instant at which the position differs from the position just before or just after it.
struct PositionChange {
  AlgebraicReal time;
  std::optional<Position> before;  ///< absent at t0
  Position at = Position::C;
  std::optional<Position> after;  ///< absent at t1
};

/// A maximal stretch of time with one position: [from, to], (from, to), [from, to), ...
struct PositionSpan {
  AlgebraicReal from, to;
  bool from_closed = true, to_closed = true;
  Position position = Position::C;
};

struct Timeline {
  Rational t0, t1;
  /// Increasing; instants.front() is t0 and instants.back() is t1 (a single instant if t0 == t1).
  std::vector<MotionInstant> instants;
  /// intervals[i] is the open interval between instants[i] and instants[i + 1].
  std::vector<MotionInterval> intervals;
  /// Disc_l f(l, t) vanishes for every t (e.g. along the axis of a circular paraboloid, where -a^2
  /// stays a double root of f and of s; or a persistent tangency).
  bool discriminant_identically_zero = false;
  /// Degree in t of the polynomial whose real zeros are the candidate instants.
  int event_degree = 0;

  std::vector<PositionChange> changes() const;
  /// Maximal spans of constant position, in order, covering [t0, t1].
  std::vector<PositionSpan> spans() const;
  /// The position at a rational time in [t0, t1], located exactly among the instants. Throws
  /// InputError outside [t0, t1] and on an empty timeline (Timeline{}: use relpos::timeline).
  Position position_at(const Rational& t) const;
};

/// First contact of a body that starts exterior.
struct FirstContact {
  enum class Kind {
    NotExteriorAtStart,  ///< the position at t0 is not E (contact at t0 is a result, not an error)
    Contact,             ///< E at t0; `time` is the first t in (t0, t1] where the position is not E
    None,                ///< E on all of [t0, t1]
  };
  Kind kind = Kind::None;
  Position start_position = Position::E;  ///< the position at t0
  std::optional<AlgebraicReal> time;      ///< t0 for NotExteriorAtStart, t* for Contact
  Position position = Position::E;        ///< the position at `time` (E for Kind::None)
  std::string how;                        ///< how that position was decided
};

/// "not-exterior-at-start", "contact", "none".
std::string to_string(FirstContact::Kind kind);

/// Certified first contact on [t0, t1]. Separation (E) and its end are decided for an ellipsoid of
/// any size (math.md §6), so this needs no smallness. Throws InputError on invalid input
/// (t0 > t1, a quaternion that vanishes on [t0, t1]), and Interrupted when `interrupt` (if given)
/// asks it to stop (cancelled, or past its time budget; relpos/interrupt.hpp).
FirstContact first_contact(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                           const Rational& t1, const Interrupt* interrupt = nullptr);

/// Every change of position on [t0, t1], with the position on each open interval and at each
/// instant, for an ellipsoid of any size (math.md §7). Throws InputError on invalid input,
/// Interrupted as first_contact, and std::logic_error ("internal error") if an instant contradicts
/// its neighbouring intervals.
Timeline timeline(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                  const Rational& t1, const Interrupt* interrupt = nullptr);

}  // namespace relpos
