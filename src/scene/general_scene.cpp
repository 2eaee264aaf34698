// Many ellipsoids against one general quadric, on all cores (include/relpos/general_scene.hpp).
#include "relpos/general_scene.hpp"

#include <CGAL/Interval_nt.h>

#include <chrono>

#include "base/worker_pool.hpp"
#include "general/decision.hpp"
#include "scene/chunk_loop.hpp"

namespace relpos {

static_assert(std::tuple_size<decltype(QuadricSceneResult::Counts::positions)>::value ==
                  detail::general::kAllQuadricPositions.size(),
              "one count per position");

QuadricSceneResult classify_scene(const Quadric& q, const Ellipsoid* bodies, std::size_t count,
                                  const SceneOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  QuadricSceneResult result;
  result.verdicts.resize(count);
  struct State {
    QuadricSceneResult::Counts counts;
  };
  QuadricVerdict* out = result.verdicts.data();
  detail::WorkerPool pool(
      detail::scene_threads(options, count));  // fewer threads when one cannot start: the others do its work
  result.threads = detail::classify_in_chunks<State>(pool, count, options, result.counts,
                                                     [&](State& s, std::size_t lo, std::size_t hi) {
                                                       // The filter's error bounds hold in rounding to nearest; threads
                                                       // inherit the caller's mode.
                                                       CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
                                                       for (std::size_t i = lo; i < hi; ++i) {
                                                         out[i] = decide_position(bodies[i], q);
                                                         s.counts.add(out[i]);
                                                       }
                                                     });
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relpos
