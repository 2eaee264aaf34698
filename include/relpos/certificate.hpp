// Certificates: evidence for each position that anyone can check with exact rational arithmetic
// alone (math.md section 8; doc/certificates.md). The matrices are the sign-normalized ones the
// library stores (Ellipsoid::matrix(): 3x3 block positive definite, det < 0; Paraboloid::matrix():
// 3x3 block positive semidefinite with positive trace); no rescaling, so lambda refers to exactly
// the matrices built from the input.
//
//   E, I    Definite:  rational lambda (> 0 for E, < 0 for I) with lambda P + E positive definite:
//                      then lambda p(x) + e(x) > 0 everywhere, so p has one sign on the solid ellipsoid.
//   TE, TI  Tangent:   rational lambda (> 0 TE, < 0 TI) with lambda P + E positive semidefinite and a
//                      rational contact point X = (x, y, z, 1) with X^T P X = 0 and X^T E X = 0.
//   TI      HardTangent (math.md section 8, the hard case): lambda = lambda_s = a + b sqrt(d) (< 0),
//                      lambda P + E positive semidefinite, and the contact set
//                      { centre + w : w in span(directions), w^T M w = radius2 } where
//                      K (centre, 1) = 0, (lambda A + M) w = 0 for each direction, radius2 = -e(centre) >= 0
//                      (when radius2 > 0 there is at least one direction). Numbers are in Q(sqrt d).
//   C       Crossing:  two rational points of the solid ellipsoid (X^T E X <= 0), `inside` with
//                      X^T P X < 0 and `outside` with X^T P X > 0.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

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

enum class Position;  // classify.hpp

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

/// The JSON form of a certificate (doc/certificates.md): numbers as exact strings ("3/4", "-2").
///   None         null
///   Definite     {"lambda": q}
///   Tangent      {"lambda": q, "contact": [x, y, z]}
///   HardTangent  {"lambda": {"a": q, "b": q, "d": n},
///                 "contact_set": {"center": [{"a", "b"} x3], "directions": [[{"a", "b"} x3], ...],
///                                 "radius2": {"a", "b"},
///                                 "decimal": {"lambda", "center": [3], "radius2"}}}
///   Crossing     {"inside": [x, y, z], "outside": [x, y, z]}
/// "decimal" holds `digits` significant digits for humans and is ignored by certificate_from_json.
nlohmann::ordered_json certificate_to_json(const Certificate& c, int digits = 12);
/// The inverse of certificate_to_json (numbers also accepted as JSON numbers, read exactly). Throws
/// relpos::InputError naming the field on malformed input (unknown or missing keys, wrong types,
/// non-numbers, d not a non-negative integer).
Certificate certificate_from_json(const nlohmann::ordered_json& j);

}  // namespace relpos
