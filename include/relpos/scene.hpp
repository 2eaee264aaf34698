// Scenes: one elliptic paraboloid against many ellipsoids (math.md §13).
//
// Every body gets exactly the position decide_position() / classify_exact() give for the pair. A body
// whose answer is cheap to prove is settled by a certified early-out: signs of polynomials in the
// matrix entries, evaluated in double with a certified running error bound (running_bound.hpp; no
// rounding-mode switch), the irrational constants of the paraboloid enclosed once by intervals:
//
//   * outside certificate: P(x) > 0 on the whole closed solid ellipsoid  =>  position E;
//   * inside certificate:  P(x) < 0 on the whole closed solid ellipsoid  =>  position I when the
//     ellipsoid is small (rho <= 1, the core's rho of smallness.hpp, certified the same way); a body
//     that is not small goes to the core, which decides it exactly (math.md §8).
//
// math.md §13 proves that these are the core's answers: for surfaces with no common point f has only
// real roots and f~ = f / gcd(f, s) no multiple root, and the sign pattern of the simultaneous
// diagonal form gives no positive root (inside) or two distinct ones (outside). Everything the
// early-outs cannot certify goes to decide_position().
//
// P(x) on the ellipsoid (x - c)^T M (x - c) <= k is bounded through P(c + d) = P(c) + g.d + d^T A d
// (g = grad P(c)): max g.d = sqrt(k g^T M^-1 g), 0 <= d^T A d <= k * mu_max with mu_max the largest
// eigenvalue of A relative to M. Cleared of denominators (D = det M > 0, K = -det E > 0), the
// certificates become signs of the polynomials of ContainmentQuantities / SphereQuantities
// (src/scene/certificates.hpp).
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "relpos/classify.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

namespace detail {
struct SceneAccess;  // the library's access to a scene (src/scene/scene_pool.hpp)
}  // namespace detail

// ------------------------------------------------------------------------------------------------
// Scene classification
// ------------------------------------------------------------------------------------------------

/// The answer for one body: position and rule are exactly decide_position()'s (contact_of(position)).
struct SceneVerdict {
  Position position = Position::C;
  Rule rule = Rule::None;
  Stage stage = Stage::StaticDouble;  ///< an early-out or the classifier stage that decided
};

/// Counts per position (index = static_cast<int>(Position)) and per stage (index = Stage).
struct SceneCounts {
  std::size_t bodies = 0;
  std::array<std::size_t, kAllPositions.size()> positions{};  ///< I, TI, C, TE, E
  std::array<std::size_t, kAllStages.size()> stages{};
  void add(const SceneVerdict& v) {
    ++bodies;
    ++positions[static_cast<std::size_t>(v.position)];
    ++stages[static_cast<std::size_t>(v.stage)];
  }
  void merge(const SceneCounts& o) {
    bodies += o.bodies;
    for (std::size_t i = 0; i < positions.size(); ++i) positions[i] += o.positions[i];
    for (std::size_t i = 0; i < stages.size(); ++i) stages[i] += o.stages[i];
  }
  std::size_t count(Position p) const { return positions[static_cast<std::size_t>(p)]; }
  std::size_t count(Stage s) const { return stages[static_cast<std::size_t>(s)]; }
};

struct SceneOptions {
  unsigned threads = 0;      ///< worker threads; 0 = std::thread::hardware_concurrency()
  bool early_outs = true;    ///< false: every body goes through decide_position (reference / benchmarks)
  std::size_t chunk = 1024;  ///< bodies per work item (threads take chunks dynamically)
  /// When set, the number of settled bodies is added to it as chunks complete (relaxed order), so
  /// another thread can draw a progress bar.
  std::atomic<std::size_t>* progress = nullptr;
  SizeLimit size_limit;  ///< the pair size limit of the bodies sent to decide_position (quadric.hpp)
};

struct SceneResult {
  std::vector<SceneVerdict> verdicts;  ///< in input order
  SceneCounts counts;
  unsigned threads = 1;  ///< threads actually used
  double seconds = 0;    ///< wall-clock time of the classification
};

/// One paraboloid, prepared once (power-of-two scaling, adj(A), det P, enclosures of lambda_max(A)
/// and of the sphere smallness constant, the operation counts of the certificate programs), against
/// any number of ellipsoids. Thread-safe: every method is const. Every method runs its arithmetic in
/// rounding to nearest whatever the caller's rounding mode (switching and restoring if needed).
class Scene {
 public:
  explicit Scene(const Paraboloid& p);

  const Paraboloid& paraboloid() const { return p_; }

  /// The certified early-outs alone; nullopt when neither certificate holds (or smallness of an
  /// interior body is not certified). Never calls the exact stages.
  std::optional<SceneVerdict> early_out(const Ellipsoid& e) const;

  /// One body: early-outs, then decide_position().
  SceneVerdict classify(const Ellipsoid& e) const;

  /// Many bodies, on options.threads threads; verdicts in input order. Rethrows the first exception
  /// of a worker (e.g. std::bad_alloc) after all workers have stopped.
  SceneResult classify(const Ellipsoid* bodies, std::size_t count, const SceneOptions& options = {}) const;
  SceneResult classify(const std::vector<Ellipsoid>& bodies, const SceneOptions& options = {}) const {
    return classify(bodies.data(), bodies.size(), options);
  }

  struct PreparedParaboloid;  // the precomputed paraboloid data (scene.cpp)

 private:
  friend struct detail::SceneAccess;
  Paraboloid p_;
  std::shared_ptr<const PreparedParaboloid> prepared_;
};

/// Convenience: Scene(p).classify(bodies, options).
SceneResult classify_scene(const Paraboloid& p, const std::vector<Ellipsoid>& bodies, const SceneOptions& options = {});

}  // namespace relpos
