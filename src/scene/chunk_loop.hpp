// The loop both scenes run their bodies through (src/scene/scene.cpp for a paraboloid,
// src/scene/general_scene.cpp for any quadric): chunks of bodies taken in turn by the threads of a
// worker pool, counts kept per thread and merged once, the first error of any thread rethrown after
// all have stopped.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "base/worker_pool.hpp"
#include "relpos/scene.hpp"

namespace relpos::detail {

/// The threads a scene of `count` bodies asks for: options.threads (0: every core), at most one per
/// chunk, at least one.
inline unsigned scene_threads(const SceneOptions& options, std::size_t count) {
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  const unsigned threads = options.threads ? options.threads : std::thread::hardware_concurrency();
  return static_cast<unsigned>(
      std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(1, (count + chunk - 1) / chunk)));
}

/// The bodies [0, count) in chunks of options.chunk on the threads of `pool`: each thread makes one
/// State (its counts in `counts`, plus whatever scratch the chunks reuse) and calls
/// classify(state, lo, hi) for each chunk it takes, which writes the verdicts of [lo, hi) and adds
/// them to state.counts. Adds every thread's counts to `total` and reports each finished chunk to
/// options.progress. Returns how many of the pool's threads had bodies to take (at most one per
/// chunk). An exception in one thread stops the others after their chunk and is rethrown here.
template <class State, class Counts, class Classify>
unsigned classify_in_chunks(WorkerPool& pool, std::size_t count, const SceneOptions& options, Counts& total,
                            const Classify& classify) {
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  const std::size_t chunks = (count + chunk - 1) / chunk;
  const unsigned threads = pool.threads();
  std::atomic<std::size_t> next{0};
  std::vector<Counts> counts(threads);
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](unsigned w) {
    State state;  // per thread: no shared cache lines while counting
    try {
      for (;;) {
        const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
        if (c >= chunks) break;
        const std::size_t lo = c * chunk, hi = std::min(count, lo + chunk);
        classify(state, lo, hi);
        if (options.progress) options.progress->fetch_add(hi - lo, std::memory_order_relaxed);
      }
    } catch (...) {
      errors[w] = std::current_exception();
      next.store(chunks, std::memory_order_relaxed);  // the others stop after their chunk
    }
    counts[w] = state.counts;
  };
  pool.run_on_each(work);
  for (const auto& err : errors)
    if (err) std::rethrow_exception(err);
  for (const auto& c : counts) total.merge(c);
  return static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, chunks)));
}

}  // namespace relpos::detail
