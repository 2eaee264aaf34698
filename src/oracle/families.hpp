// The case families of `relpos cases` (doc/oracle.md, "Families"): pairs whose position is known
// by construction, without trusting relpos (the proofs are in doc/oracle.md), as the parameters a
// float code starts from: an ellipsoid by centre, semi-axes and rotation quaternion, a paraboloid by
// vertex, a, b and rotation quaternion (the JSON forms of doc/cli.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relpos/position.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::oracle {

/// The parameters of a pair: what a float code starts from.
struct Parameters {
  Vector3 centre, axes;
  Quaternion e_rotation{Rational(1), Rational(0), Rational(0), Rational(0)};
  Vector3 vertex;
  Rational a, b;
  Quaternion p_rotation{Rational(1), Rational(0), Rational(0), Rational(0)};
};

/// One constructed pair.
struct Construction {
  Parameters exact;
  /// The position known by construction; nullopt for the random family (no construction: its
  /// label is relpos's, with a certificate the independent verifier checks).
  std::optional<Position> position;
  /// s*, the factor by which the ellipsoid scaled about its centre first touches the paraboloid,
  /// when the construction knows it (1 + eps, 1 or 1 - eps for the near-tangent families).
  std::optional<Rational> s_star;
  std::string side;  ///< "inside" or "outside": where the centre lies ("" when not constructed)
};

struct Family {
  const char* name;
  const char* description;
  bool uses_eps;  ///< false: the family is made at eps = 0 only (exact tangencies, random pairs)
};

/// Every family, in the order `relpos cases all` writes them.
const std::vector<Family>& families();

/// The family of that name, or nullptr.
const Family* find_family(std::string_view name);

/// Case `index` of `family` at relative distance eps (0 <= eps < 1; 0 is the exact tangency), from
/// the random stream of (seed, family, index): the same case whatever else is asked for. For the
/// near-tangent families, case index has the centre inside the cup when index is even and outside
/// when odd (families that have both sides), and s* = 1 + eps when index / 2 (index, for
/// inside-only families) is even, 1 - eps when odd: I, C (inside) or E, C (outside); TI, TE at eps = 0.
Construction construct(const Family& family, const Rational& eps, std::uint64_t seed, std::uint64_t index);

}  // namespace relpos::detail::oracle
