// A scene's many bodies classified on a worker pool the caller keeps (base/worker_pool.hpp): the
// CLI's `relpos scene` reads, parses and classifies each block of lines on one pool instead of
// starting a pool per block (Scene::classify starts one for its call and runs the same code).
#pragma once

#include <cstddef>

#include "base/worker_pool.hpp"
#include "relpos/scene.hpp"

namespace relpos::detail {

struct SceneAccess {
  /// scene.classify(bodies, count, options) on the threads of `pool` (options.threads is not read):
  /// the same verdicts and counts; `threads` of the result is the number of pool threads that had
  /// bodies to take (at most one per chunk).
  static SceneResult classify(const Scene& scene, const Ellipsoid* bodies, std::size_t count,
                              const SceneOptions& options, WorkerPool& pool);
};

}  // namespace relpos::detail
