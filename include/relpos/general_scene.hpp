// Scenes against any real quadric: many ellipsoids against one general quadric, on all cores
// (doc/quadrics.md, "Scenes"; `relpos scene --quadric Q`).
//
// Every body gets exactly the verdict decide_position(e, q) gives for the pair (math.md §16–§17: the
// certified double filter, then the exact stage). The paraboloid's Scene (scene.hpp) has certified
// early-outs of its own (math.md §13); a general quadric has none: its filter is already the cheap
// first step, so the scene is the pair's decision spread over the threads.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "relpos/general_classify.hpp"
#include "relpos/scene.hpp"

namespace relpos {

/// The answers of a scene against a general quadric.
struct QuadricSceneResult {
  /// Counts per position (index = static_cast<int>(QuadricPosition), eight positions) and per stage
  /// (QuadricStage).
  struct Counts {
    std::size_t bodies = 0;
    std::array<std::size_t, 8> positions{};
    std::array<std::size_t, 2> stages{};  ///< Filter, Exact
    void add(const QuadricVerdict& v) {
      ++bodies;
      ++positions[static_cast<std::size_t>(v.position)];
      ++stages[static_cast<std::size_t>(v.stage)];
    }
    void merge(const Counts& o) {
      bodies += o.bodies;
      for (std::size_t i = 0; i < positions.size(); ++i) positions[i] += o.positions[i];
      for (std::size_t i = 0; i < stages.size(); ++i) stages[i] += o.stages[i];
    }
    std::size_t count(QuadricPosition p) const { return positions[static_cast<std::size_t>(p)]; }
    std::size_t count(QuadricStage s) const { return stages[static_cast<std::size_t>(s)]; }
  };
  std::vector<QuadricVerdict> verdicts;  ///< in input order, each decide_position(bodies[i], q)
  Counts counts;
  unsigned threads = 1;  ///< threads actually used
  double seconds = 0;    ///< wall-clock time of the classification
};

/// Many bodies against one quadric on options.threads threads (0: every core), chunks of
/// options.chunk bodies taken dynamically, options.progress advanced as chunks complete. The
/// paraboloid scene's early_outs and size_limit do not apply (the bodies' size is checked where
/// they are read: check_general_pair_size, as `relpos batch` does). Rethrows the first exception of
/// a worker after all workers have stopped.
QuadricSceneResult classify_scene(const Quadric& q, const Ellipsoid* bodies, std::size_t count,
                                  const SceneOptions& options = {});
inline QuadricSceneResult classify_scene(const Quadric& q, const std::vector<Ellipsoid>& bodies,
                                         const SceneOptions& options = {}) {
  return classify_scene(q, bodies.data(), bodies.size(), options);
}

}  // namespace relpos
