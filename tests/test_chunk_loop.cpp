// chunk_loop.hpp: the loop both scenes run their bodies through. Identities: every body is given to
// exactly one chunk, the chunks tile [0, count) in pieces of options.chunk, the merged counts are the
// sum of what the chunks counted, progress reaches count, the threads reported are at most one per
// chunk; an exception of one chunk reaches the caller; scene_threads clamps to the chunks.
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "base/worker_pool.hpp"
#include "scene/chunk_loop.hpp"

namespace {

struct Tally {
  std::size_t bodies = 0, chunks = 0;
  void merge(const Tally& o) {
    bodies += o.bodies;
    chunks += o.chunks;
  }
};

struct State {
  Tally counts;
};

}  // namespace

TEST_CASE("classify_in_chunks: every body once, the chunks tiling the bodies, counts and progress adding up",
          "[chunk_loop]") {
  for (const unsigned threads : {1u, 3u})
    for (const std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(1000)})
      for (const std::size_t chunk : {std::size_t(1), std::size_t(64), std::size_t(5000)}) {
        CAPTURE(threads, count, chunk);
        relpos::detail::WorkerPool pool(threads);
        std::atomic<std::size_t> progress{0};
        relpos::SceneOptions options;
        options.chunk = chunk;
        options.progress = &progress;
        std::vector<std::atomic<int>> seen(count);
        std::atomic<int> misplaced{0};
        Tally total;
        const unsigned used = relpos::detail::classify_in_chunks<State>(
            pool, count, options, total, [&](State& s, std::size_t lo, std::size_t hi) {
              if (lo % chunk != 0 || (hi - lo != chunk && hi != count))
                misplaced.fetch_add(1);  // Catch2 is one thread's
              for (std::size_t i = lo; i < hi; ++i) seen[i].fetch_add(1);
              s.counts.bodies += hi - lo;
              ++s.counts.chunks;
            });
        CHECK(misplaced.load() == 0);
        for (std::size_t i = 0; i < count; ++i) CHECK(seen[i].load() == 1);
        const std::size_t chunks = (count + chunk - 1) / chunk;
        CHECK(total.bodies == count);
        CHECK(total.chunks == chunks);
        CHECK(progress.load() == count);
        CHECK(used >= 1);
        CHECK(used <= pool.threads());
        CHECK(used <= std::max<std::size_t>(1, chunks));
      }
}

TEST_CASE("classify_in_chunks: a chunk's exception reaches the caller, the other threads stop", "[chunk_loop]") {
  relpos::detail::WorkerPool pool(3);
  relpos::SceneOptions options;
  options.chunk = 10;
  Tally total;
  std::atomic<std::size_t> ran{0};
  CHECK_THROWS_AS(relpos::detail::classify_in_chunks<State>(pool, 100000, options, total,
                                                            [&](State&, std::size_t lo, std::size_t) {
                                                              ran.fetch_add(1);
                                                              if (lo == 0) throw std::runtime_error("body 0");
                                                            }),
                  std::runtime_error);
  CHECK(ran.load() < 10000);  // stopped after the failing chunk, not run to the end
  // The pool is still usable after the error.
  CHECK(relpos::detail::classify_in_chunks<State>(
            pool, 20, options, total, [&](State& s, std::size_t lo, std::size_t hi) { s.counts.bodies += hi - lo; }) >=
        1);
}

TEST_CASE("scene_threads: the threads asked for, at most one per chunk, at least one", "[chunk_loop]") {
  relpos::SceneOptions options;
  options.chunk = 100;
  options.threads = 8;
  CHECK(relpos::detail::scene_threads(options, 0) == 1);
  CHECK(relpos::detail::scene_threads(options, 100) == 1);
  CHECK(relpos::detail::scene_threads(options, 101) == 2);
  CHECK(relpos::detail::scene_threads(options, 100000) == 8);
  options.threads = 0;  // every core, still at most one per chunk
  CHECK(relpos::detail::scene_threads(options, 1) == 1);
  CHECK(relpos::detail::scene_threads(options, 100000) >= 1);
  options.chunk = 0;  // read as one body a chunk
  options.threads = 3;
  CHECK(relpos::detail::scene_threads(options, 2) == 2);
}
