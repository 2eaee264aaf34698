// The five relative positions of an ellipsoid and an elliptic paraboloid (math.md §3) and the
// certificate that proves each one with exact rational arithmetic alone, with its independent checker.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

enum class Position {
  I,   ///< the ellipsoid is interior to the paraboloid
  TI,  ///< tangent from inside
  C,   ///< the surfaces cross (non-tangent contact)
  TE,  ///< tangent from outside
  E,   ///< exterior
};
/// Every position, in enum order (tables indexed by Position take their size from here).
inline constexpr std::array kAllPositions{Position::I, Position::TI, Position::C, Position::TE, Position::E};
/// "I", "TI", "C", "TE", "E".
inline std::string to_string(Position p) {
  switch (p) {
    case Position::I:
      return "I";
    case Position::TI:
      return "TI";
    case Position::C:
      return "C";
    case Position::TE:
      return "TE";
    case Position::E:
      return "E";
  }
  throw std::logic_error("internal error: to_string: not a Position");
}

// Certificates: evidence for each position that anyone can check with exact rational arithmetic
// alone (math.md §8; doc/certificates.md). The matrices are the sign-normalized ones the
// library stores (Ellipsoid::matrix(): 3x3 block positive definite, det < 0; Paraboloid::matrix():
// 3x3 block positive semidefinite with positive trace); no rescaling, so lambda refers to exactly
// the matrices built from the input.
//
//   E, I    Definite:  rational lambda (> 0 for E, < 0 for I) with lambda P + E positive definite:
//                      then lambda p(x) + e(x) > 0 everywhere, so p has one sign on the solid ellipsoid.
//   TE, TI  Tangent:   rational lambda (> 0 TE, < 0 TI) with lambda P + E positive semidefinite and a
//                      rational contact point X = (x, y, z, 1) with X^T P X = 0 and X^T E X = 0.
//   TI      HardTangent (math.md §8, the hard case): lambda = lambda_s = a + b sqrt(d) (< 0),
//                      lambda P + E positive semidefinite, and the contact set
//                      { centre + w : w in span(directions), w^T M w = radius2 } where
//                      K (centre, 1) = 0, (lambda A + M) w = 0 for each direction, radius2 = -e(centre) >= 0
//                      (when radius2 > 0 there is at least one direction). Numbers are in Q(sqrt d).
//   C       Crossing:  two rational points of the solid ellipsoid (X^T E X <= 0), `inside` with
//                      X^T P X < 0 and `outside` with X^T P X > 0.
/// a + b sqrt(d) with rational a, b; d is a non-negative integer shared by all the numbers of one
/// certificate (b = 0 whenever d is a perfect square or the number is rational).
struct QuadraticNumber {
  Rational a, b;
};
using QuadraticVector3 = std::array<QuadraticNumber, 3>;

struct Certificate {
  enum class Kind { None, Definite, Tangent, HardTangent, Crossing };
  Kind kind = Kind::None;
  Rational lambda;  ///< Definite, Tangent
  Vector3 contact;  ///< Tangent: the contact point
  // HardTangent: lambda_s = lambda_q.a + lambda_q.b sqrt(d) and the contact set.
  Integer d;
  QuadraticNumber lambda_q;
  QuadraticVector3 centre;
  std::vector<QuadraticVector3> directions;
  QuadraticNumber radius2;
  Vector3 inside, outside;  ///< Crossing
};

/// Checks a certificate with exact rational arithmetic only (no code of the classifier): nullopt
/// when it proves `position` for the pair, otherwise the reason it does not.
std::optional<std::string> verify_certificate(const Ellipsoid& e, const Paraboloid& p, Position position,
                                              const Certificate& c);
/// The same on raw matrices (normalized here: E's 3x3 block made positive definite, P's made of positive
/// trace, by negation only).
std::optional<std::string> verify_certificate(const Matrix4& e, const Matrix4& p, Position position,
                                              const Certificate& c);

/// The exact sign (-1, 0, 1) of x.a + x.b sqrt(d), d >= 0 (the verifier's own Q(sqrt d) arithmetic,
/// exposed for tests).
int quadratic_sign(const QuadraticNumber& x, const Integer& d);

}  // namespace relpos
