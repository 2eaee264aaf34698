// Ctrl-C in long compiled calls (doc/python.md, "Interrupting a call"): the work runs with the GIL
// released in pieces, and between pieces the thread that entered the module takes the GIL for a
// moment to let Python run its signal handlers. A handler that raises (KeyboardInterrupt) stops the
// work at its next piece, and its exception is raised when the call returns: nothing keeps running
// and the interpreter stays usable.
#pragma once

#include <atomic>
#include <chrono>
#include <future>
#include <optional>
#include <relpos/interrupt.hpp>
#include <thread>
#include <utility>

#include "module.hpp"

namespace relpos_python {

/// The stop flag of one call and the poll of Python's signals.
class SignalWatch {
 public:
  /// How often the GIL is taken to check for signals while the work runs.
  static constexpr std::chrono::milliseconds kInterval{50};

  /// With the GIL released, on the thread that entered the module: true once a signal handler has
  /// raised (now or before); the other threads then see stopped(). Takes the GIL at most once per
  /// kInterval.
  bool poll();
  /// Whether the work must stop (any thread).
  bool stopped() const { return stop_.load(std::memory_order_relaxed); }
  /// With the GIL held, after the work: raises the handler's exception, if one was raised.
  void raise_if_stopped();

 private:
  std::atomic<bool> stop_{false};
  std::optional<py::error_already_set> error_;
  std::chrono::steady_clock::time_point next_ = std::chrono::steady_clock::now() + kInterval;
};

/// Runs `work()` on a worker thread with the GIL released while the calling thread checks Python's
/// signals every SignalWatch::kInterval; a signal cancels `interrupt`, which the work polls (the
/// motion of relpos/motion.hpp stops at its next check). Returns the work's result or rethrows its
/// exception; after a signal, raises the signal's exception once the work has stopped. Called with
/// the GIL held.
template <class Work>
auto run_watched(relpos::Interrupt& interrupt, Work work) -> decltype(work()) {
  using Result = decltype(work());
  SignalWatch watch;
  std::future<Result> done;
  {
    py::gil_scoped_release release;
    std::packaged_task<Result()> task(std::move(work));
    done = task.get_future();
    std::thread worker(std::move(task));
    while (done.wait_for(SignalWatch::kInterval) != std::future_status::ready)
      if (watch.poll()) interrupt.cancel();
    worker.join();
  }
  watch.raise_if_stopped();
  return done.get();
}

}  // namespace relpos_python
