// "Approximate; if certain, return; else exact", written once (math.md §11; CGAL's
// Filtered_predicate): an approximation answers with a std::optional, empty when it cannot certify
// its answer, and runs under the rounding mode its error bounds assume -- set here, the one place
// that protects the rounding mode for a filter. The exact computation runs only when every
// approximation before it was uncertain (or skipped). Used by the decision ladder's gap test, the
// certificates' signs at candidate points, the shape test of a quadric given as doubles, the scene's
// early-outs and the contact-only decision.
#pragma once

#include <CGAL/FPU.h>

#include <optional>
#include <type_traits>
#include <utility>

#include "algebra/rounding.hpp"

namespace relpos::detail {

/// The rounding mode an approximation's error bounds assume.
enum class Rounding {
  Nearest,    ///< round to nearest; skipped (uncertain) in any other mode: a caller inside an upward
              ///< block (CGAL interval code) gets the next approximation instead
  ToNearest,  ///< round to nearest, switched to for the call when another mode is set
  Upward,     ///< towards +inf (CGAL::Interval_nt<false>), switched to for the call
};

/// approx() under R: its answer (empty when uncertain), or empty when R = Nearest and the mode is
/// another.
template <Rounding R, class Approx>
auto approximate(Approx&& approx) -> decltype(approx()) {
  if constexpr (R == Rounding::Upward) {
    CGAL::Protect_FPU_rounding<true> guard;
    return approx();
  } else if constexpr (R == Rounding::ToNearest) {
    if (rounding_to_nearest()) return approx();  // two additions: cheaper than setting the mode
    CGAL::Protect_FPU_rounding<true> guard(CGAL_FE_TONEAREST);
    return approx();
  } else {
    if (!rounding_to_nearest()) return {};
    return approx();
  }
}

/// The approximation's answer when it is certain, else exact()'s.
template <Rounding R, class Approx, class Exact>
auto filtered(Approx&& approx, Exact&& exact) -> decltype(exact()) {
  if (auto a = approximate<R>(approx)) return *std::move(a);
  return exact();
}

/// One level of a ladder of approximations (settle()).
template <Rounding R, class F>
struct Level {
  static constexpr Rounding rounding = R;
  F approx;
};
template <Rounding R, class F>
Level<R, std::decay_t<F>> level(F&& approx) {
  return {std::forward<F>(approx)};
}

/// An answer and the index of what gave it: a level, or the number of levels for the exact one.
template <class T>
struct Settled {
  T value;
  int by;
};

/// The first certain answer of the levels, in order, else exact()'s (filtered() with several
/// approximations, cheapest first).
template <class Exact, class... Levels>
Settled<std::decay_t<decltype(std::declval<Exact&>()())>> settle(Exact&& exact, Levels&&... levels) {
  std::optional<std::decay_t<decltype(exact())>> answer;
  int by = 0;
  auto certain = [&](auto& level) {  // true when `level` answered; else counts it
    answer = approximate<std::decay_t<decltype(level)>::rounding>(level.approx);
    if (answer) return true;
    ++by;
    return false;
  };
  static_cast<void>((certain(levels) || ...));
  if (answer) return {*std::move(answer), by};
  return {exact(), by};
}

}  // namespace relpos::detail
