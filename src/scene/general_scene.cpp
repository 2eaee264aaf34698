// Many ellipsoids against one general quadric, on all cores (include/relpos/general_scene.hpp).
#include "relpos/general_scene.hpp"

#include <CGAL/Interval_nt.h>

#include <chrono>
#include <limits>
#include <optional>

#include "algebra/pair_size.hpp"
#include "base/large_stack.hpp"
#include "base/worker_pool.hpp"
#include "general/decision.hpp"
#include "scene/chunk_loop.hpp"

namespace relpos {

static_assert(std::tuple_size<decltype(QuadricSceneResult::Counts::positions)>::value ==
                  general::kAllQuadricPositions.size(),
              "one count per position");

namespace {

/// decide_position(e, q), for a pair beyond the default size limit (read under a raised limit: `relpos
/// scene --max-bits`) on a thread whose stack fits the exact stage's root isolation, whose recursion
/// grows with the numbers (base/large_stack.hpp; as decide_position does for a paraboloid). No limit
/// is checked here (the bodies' size is checked where they are read).
QuadricVerdict decide_on_fitting_stack(const Ellipsoid& e, const Quadric& q) {
  if (storage_of(e).within_size_limit() && storage_of(q).within_size_limit()) return decide_position(e, q);
  const std::size_t bits =
      detail::check_normalized_size(storage_of(e), storage_of(q), SizeLimit{std::numeric_limits<std::size_t>::max()});
  if (bits <= kMaxNormalizedBits) return decide_position(e, q);
  std::optional<QuadricVerdict> out;
  detail::run_on_large_stack(detail::stack_for_bits(bits), [&] { out.emplace(decide_position(e, q)); });
  return *out;
}

}  // namespace

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
                                                         out[i] = decide_on_fitting_stack(bodies[i], q);
                                                         s.counts.add(out[i]);
                                                       }
                                                     });
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relpos
