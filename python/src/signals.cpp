// Python's signals polled during long compiled calls (signals.hpp).
#include "signals.hpp"

namespace relpos_python {

bool SignalWatch::poll() {
  if (stopped()) return true;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return false;
  next_ = now + kInterval;
  const py::gil_scoped_acquire gil;
  // Runs the handlers of the signals received since the last check (main thread only: elsewhere
  // Python never runs them, and this returns 0).
  if (PyErr_CheckSignals() != 0) {
    error_.emplace();  // takes the handler's exception (KeyboardInterrupt) out of the thread state
    stop_.store(true, std::memory_order_relaxed);
  }
  return stopped();
}

void SignalWatch::raise_if_stopped() {
  if (error_) throw *error_;
}

}  // namespace relpos_python
