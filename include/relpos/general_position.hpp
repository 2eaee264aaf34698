// The positions of an ellipsoid against any real quadric (math.md §16) and the certificates that
// prove them with exact rational arithmetic alone, with their independent checker (math.md §18).
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "relpos/general_quadric.hpp"
#include "relpos/position.hpp"

namespace relpos {

/// Where the solid ellipsoid E sits against the solid {q <= 0} of a quadric Q. The first five hold
/// for every type; O, TO and EQ only when Q is an ellipsoid too.
enum class QuadricPosition : unsigned char {
  I,   ///< E inside the solid: q < 0 on E
  TI,  ///< E inside, touching: q <= 0 on E, = 0 somewhere
  C,   ///< the surfaces cross
  TE,  ///< E outside, touching: q >= 0 on E, = 0 somewhere
  E,   ///< E outside the solid: q > 0 on E
  O,   ///< Q's solid inside E: e < 0 on it (Q an ellipsoid)
  TO,  ///< Q's solid inside E, touching (Q an ellipsoid)
  EQ,  ///< the same ellipsoid (TI and TO together)
};
/// "I", "TI", "C", "TE", "E", "O", "TO", "EQ".
inline std::string to_string(QuadricPosition p) {
  switch (p) {
    case QuadricPosition::I:
      return "I";
    case QuadricPosition::TI:
      return "TI";
    case QuadricPosition::C:
      return "C";
    case QuadricPosition::TE:
      return "TE";
    case QuadricPosition::E:
      return "E";
    case QuadricPosition::O:
      return "O";
    case QuadricPosition::TO:
      return "TO";
    case QuadricPosition::EQ:
      return "EQ";
  }
  throw std::logic_error("internal error: to_string: not a QuadricPosition");
}

/// The contact a position states (the surfaces of EQ coincide: touching everywhere).
constexpr Contact contact_of(QuadricPosition p) {
  switch (p) {
    case QuadricPosition::C:
      return Contact::Crossing;
    case QuadricPosition::TI:
    case QuadricPosition::TE:
    case QuadricPosition::TO:
    case QuadricPosition::EQ:
      return Contact::Touching;
    default:
      return Contact::None;
  }
}

// Certificates (math.md §18). The matrices are the sign-normalized ones the library stores
// (Ellipsoid::matrix(): M positive definite, det E < 0; Quadric::matrix()); t multiplies E:
//
//   E, I, O   Definite:    rational t with Q + t E positive definite (E: t > 0, O: t < 0) or
//                          negative definite (I: t < 0).
//   TE,TI,TO  Tangent:     rational t (TE: > 0, TI and TO: < 0) with Q + t E positive (TE, TO) or
//                          negative (TI) semidefinite, and a rational point on both surfaces.
//   TE,TI,TO  HardTangent: t = a + b sqrt(d) (an end of the multipliers' interval), Q + t E
//                          semidefinite as above over Q(sqrt d), and the contact set
//                          { centre + w : w in span(directions), w^T M w = radius2 }: (centre, 1) in the
//                          kernel of Q + t E, each direction in the kernel of B + t M and M-orthogonal to
//                          M centre + m, radius2 = -e(centre) >= 0, the directions spanning that kernel.
//   C         Crossing:    points of the solid ellipsoid with q < 0 (`inside`) and q > 0 (`outside`);
//                          when B is positive definite (Q an ellipsoid) also a point of Q's solid
//                          outside E (`beyond`, e > 0).
//   EQ        Equal:       Q = ratio * E with ratio > 0.
struct QuadricCertificate {
  enum class Kind { None, Definite, Tangent, HardTangent, Crossing, Equal };
  Kind kind = Kind::None;
  Rational t;       ///< Definite, Tangent
  Vector3 contact;  ///< Tangent
  // HardTangent: t = t_q.a + t_q.b sqrt(d) and the contact set.
  Integer d;
  QuadraticNumber t_q;
  QuadraticVector3 centre;
  std::vector<QuadraticVector3> directions;
  QuadraticNumber radius2;
  Vector3 inside, outside;        ///< Crossing
  std::optional<Vector3> beyond;  ///< Crossing, Q an ellipsoid
  Rational ratio;                 ///< Equal
};

/// Checks a certificate with exact rational arithmetic only (no code of the classifier): nullopt when
/// it proves `position` for the pair, otherwise the reason it does not.
std::optional<std::string> verify_certificate(const Ellipsoid& e, const Quadric& q, QuadricPosition position,
                                              const QuadricCertificate& c);
/// The same on raw matrices. E is normalized here by negation (M positive definite); Q by negation
/// when its 3x3 block has more negative than positive eigenvalues, as Quadric::from_matrix does.
std::optional<std::string> verify_certificate(const Matrix4& e, const Matrix4& q, QuadricPosition position,
                                              const QuadricCertificate& c);

}  // namespace relpos
