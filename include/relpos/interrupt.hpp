// Stopping a long computation from outside (the motion of relpos/motion.hpp): cancelled by another
// thread (Ctrl-C in the Python package) or past a time budget (`relpos motion --max-seconds`, the
// Python motion functions' max_seconds). One mechanism for both: the computation calls check()
// between its steps and stops at the first check after the request, with Interrupted; no step is
// cut short, so nothing is left half-built (doc/cli.md, "Limits").
#pragma once

#include <atomic>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>

namespace relpos {

/// Thrown by check() once the computation must stop.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(const std::string& what, bool budget) : std::runtime_error(what), budget_(budget) {}
  /// True when the time budget ran out; false when the computation was cancelled.
  bool budget() const { return budget_; }

 private:
  bool budget_;
};

class Interrupt {
 public:
  /// Stops only when cancelled.
  Interrupt() = default;
  /// Also stops once `budget` has passed from now.
  explicit Interrupt(std::chrono::steady_clock::duration budget);
  Interrupt(const Interrupt&) = delete;
  Interrupt& operator=(const Interrupt&) = delete;

  /// Requests the stop; safe from any thread, at any time.
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  /// Throws Interrupted when cancelled or past the deadline; else returns at once (an atomic load
  /// and, with a budget, a read of the clock).
  void check() const;

 private:
  std::atomic<bool> cancelled_{false};
  std::optional<std::chrono::steady_clock::time_point> deadline_;
};

}  // namespace relpos
