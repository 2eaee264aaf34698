// FLINT keeps a per-thread cache of integers; a thread that exits without flint_cleanup() leaks it
// (the CLI answers on worker threads). Every function that calls FLINT first calls
// flint_thread_cleanup_at_exit(), which registers the cleanup once per thread.
#pragma once

#include <flint/flint.h>

namespace relpos::detail {

struct FlintThreadCleanup {
  ~FlintThreadCleanup() { flint_cleanup(); }
};

inline void flint_thread_cleanup_at_exit() {
  static thread_local FlintThreadCleanup guard;
  (void)guard;
}

}  // namespace relpos::detail
