// Many ellipsoids against one general quadric, on all cores (include/relpos/general_scene.hpp).
#include "relpos/general_scene.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

#include "base/worker_pool.hpp"
#include "general/decision.hpp"

namespace relpos {

static_assert(std::tuple_size<decltype(QuadricSceneResult::Counts::positions)>::value ==
                  general::kAllQuadricPositions.size(),
              "one count per position");

QuadricSceneResult classify_scene(const Quadric& q, const Ellipsoid* bodies, std::size_t count,
                                  const SceneOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  QuadricSceneResult result;
  result.verdicts.resize(count);
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  const std::size_t chunks = (count + chunk - 1) / chunk;
  unsigned threads = options.threads ? options.threads : std::thread::hardware_concurrency();
  threads = static_cast<unsigned>(std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(1, chunks)));

  std::atomic<std::size_t> next{0};
  std::vector<QuadricSceneResult::Counts> counts(threads);
  std::vector<std::exception_ptr> errors(threads);
  QuadricVerdict* out = result.verdicts.data();
  auto work = [&](unsigned w) {
    QuadricSceneResult::Counts local;  // per thread, merged once at the end
    try {
      for (;;) {
        const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
        if (c >= chunks) break;
        const std::size_t lo = c * chunk, hi = std::min(count, lo + chunk);
        // The filter's error bounds hold in rounding to nearest; threads inherit the caller's mode.
        CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
        for (std::size_t i = lo; i < hi; ++i) {
          out[i] = decide_position(bodies[i], q);
          local.add(out[i]);
        }
        if (options.progress) options.progress->fetch_add(hi - lo, std::memory_order_relaxed);
      }
    } catch (...) {
      errors[w] = std::current_exception();
      next.store(chunks, std::memory_order_relaxed);  // the others stop after their chunk
    }
    counts[w] = local;
  };
  detail::WorkerPool pool(threads);
  result.threads = pool.threads();  // fewer when a thread cannot start: the others do its work
  pool.run_on_each(work);
  for (const auto& err : errors)
    if (err) std::rethrow_exception(err);
  for (const auto& c : counts) result.counts.merge(c);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relpos
