// The library's side of relpos::Interrupt (relpos/interrupt.hpp): a computation polls an optional
// interrupt between its steps.
#pragma once

#include "relpos/interrupt.hpp"

namespace relpos::detail {

/// interrupt->check() for an optional interrupt (computations take `const Interrupt*`, null: never stop).
inline void check(const Interrupt* interrupt) {
  if (interrupt) interrupt->check();
}

}  // namespace relpos::detail
