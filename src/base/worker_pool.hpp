// The one pool of worker threads of relpos: scenes, `relpos batch` and `relpos scene` run their
// parallel loops on it. Internal: not part of the public API.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace relpos::detail {

/// Worker threads kept for the pool's lifetime; the thread that calls run() works too, so a pool of
/// n threads starts n - 1. Keeping the threads matters to a caller that runs many short rounds
/// (starting threads for each round would cost more than the work of a short one).
class WorkerPool {
 public:
  /// threads - 1 workers (none for 0 or 1). A thread that cannot be started (too little memory for
  /// its stack) leaves the work to the others: threads() says how many there are.
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// f(i) for every i in [0, n), each index once, on every thread (dynamic: items differ in cost);
  /// returns when all are done. f must not throw.
  void run(std::size_t n, const std::function<void(std::size_t)>& f);

  /// f(w) once on each thread, w in [0, threads()) (w = 0 on the calling thread); returns when all
  /// are done. For loops that keep per-thread state and take their own work items. f must not throw.
  void run_on_each(const std::function<void(unsigned)>& f);

 private:
  void work(unsigned w);
  void drain(unsigned w);
  /// One round: every thread takes part (the caller as thread 0); returns when all are done.
  void round(const std::function<void(std::size_t)>* task, const std::function<void(unsigned)>* each, std::size_t n);
  void stop_and_join();
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  // Every worker takes part in every round and run() waits for all of them, so no worker can act
  // on a round that has ended (the task and size_ are written under the mutex before the round starts).
  const std::function<void(std::size_t)>* task_ = nullptr;
  const std::function<void(unsigned)>* each_ = nullptr;
  std::size_t size_ = 0;
  std::atomic<std::size_t> next_{0};
  unsigned long generation_ = 0;
  std::size_t finished_ = 0;
  bool stop_ = false;
};

}  // namespace relpos::detail
