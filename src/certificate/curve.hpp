// The pair's exact values along the certificates' curve (math.md §8): the forms e(x) = X^T E X and
// p(x) = X^T P X at rational points X = (x, 1), and the stationary point x(lambda) of lambda p + e.
// Shared by the certificates of every position.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "pair/pair.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::certificate {

using V3 = std::array<Rational, 3>;
using detail::PairContext;

/// X^T Q X for X = (x, 1).
Rational form(const Matrix4& q, const V3& x);
inline Rational e_at(const PairContext& pr, const V3& x) { return form(pr.ellipsoid().matrix(), x); }
inline Rational p_at(const PairContext& pr, const V3& x) { return form(pr.paraboloid().matrix(), x); }

/// x(lambda) = -(lambda A + M)^{-1} (lambda a + m): the stationary point of lambda p + e (math.md §8);
/// nullopt when lambda A + M is singular. For lambda = n/d the system times d lp le (E = Ez/le,
/// P = Pz/lp) has integer entries n le Pz + d lp Ez: Cramer's rule on integers, one rational
/// canonicalisation per coordinate.
std::optional<V3> x_of(const PairContext& pr, const Rational& lambda);

/// The error of a certificate that cannot be built (an internal error, doc/certificates.md).
std::logic_error internal_error(const std::string& what);

}  // namespace relpos::detail::certificate
