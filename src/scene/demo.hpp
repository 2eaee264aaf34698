// Reproducible demo scenes (relpos scene --generate, scene_bench).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "relpos/quadric.hpp"

namespace relpos {

// ------------------------------------------------------------------------------------------------
// Demo / benchmark scenes
// ------------------------------------------------------------------------------------------------

/// One body of a generated scene, in exact form (so that it can be written out as text).
struct DemoBody {
  enum class Kind : unsigned char { Sphere, Coefficients };
  Kind kind = Kind::Sphere;
  Vector3 centre;               ///< Sphere
  Rational radius;              ///< Sphere
  Coefficients10 coefficients;  ///< Coefficients (A x^2 + ... + J, quadric.hpp order)
  Ellipsoid ellipsoid() const;
};

/// A reproducible "particles in a parabolic container" scene for x^2/a^2 + y^2/b^2 = z (vertex at
/// the origin; doc/performance.md describes it): bulk small bodies anywhere in the cup (some
/// crossing the wall), a fraction `wall` placed at the wall (resting against it inside or outside at
/// gaps r 2^-j, crossing it, and rational near-tangencies at relative gaps down to 2^-40), 8 %
/// spilled outside, 0.5 % not small, and 1 in 10^4 exact tangencies (TI and TE). Spheres and
/// ellipsoids given by coefficients; most entries are exact doubles (dyadic). Bodies come one at a
/// time, so a scene of any size can be streamed.
class DemoSceneGenerator {
 public:
  static constexpr double kDefaultWall = 0.04;
  DemoSceneGenerator(std::uint64_t seed, const Rational& a, const Rational& b, double wall = kDefaultWall);
  ~DemoSceneGenerator();
  DemoSceneGenerator(const DemoSceneGenerator&) = delete;
  DemoSceneGenerator& operator=(const DemoSceneGenerator&) = delete;
  DemoBody next();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

/// The first n bodies of DemoSceneGenerator(seed, a, b, wall).
std::vector<DemoBody> demo_container_scene(std::size_t n, std::uint64_t seed, const Rational& a, const Rational& b,
                                           double wall = DemoSceneGenerator::kDefaultWall);

}  // namespace relpos
