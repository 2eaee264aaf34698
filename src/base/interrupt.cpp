// Stopping a long computation: cancellation and time budget (relpos/interrupt.hpp).
#include "relpos/interrupt.hpp"

namespace relpos {

Interrupt::Interrupt(std::chrono::steady_clock::duration budget)
    : deadline_(std::chrono::steady_clock::now() + budget) {}

void Interrupt::check() const {
  if (cancelled_.load(std::memory_order_relaxed)) throw Interrupted("the computation was cancelled", false);
  if (deadline_ && std::chrono::steady_clock::now() >= *deadline_)
    throw Interrupted("the computation exceeded its time budget", true);
}

}  // namespace relpos
