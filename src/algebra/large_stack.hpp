// Work whose recursion depth grows with the size of its numbers, on a thread with a stack to match:
// CGAL's Descartes root isolation (Algebraic_kernel_d_1's solve_1) recurses once per bit of the
// separation of the roots it isolates. Internal: not part of the public API.
#pragma once

#include <cstddef>
#include <functional>

namespace relpos::detail {

/// The stack a pair of `bits` needs (the bits of the larger primitive integer form of its two
/// matrices), for the work around its root isolations: 128 bytes per bit, at least 16 MiB. The
/// isolations themselves ask for their own stack (isolate_on_fitting_stack below), which a pair's
/// closeness to a multiple root, not its size alone, decides.
std::size_t stack_for_bits(std::size_t bits);

/// The stack CGAL's Descartes isolation of a polynomial of `degree` whose coefficients have at most
/// `bits` bits may need, whatever its roots (doc/cli.md, "Limits"): it halves an interval from the
/// root bound (below 2^(bits+1)) until the interval is narrower than the roots' separation (above
/// 2^-((degree-1)(bits+1) + degree log2 degree), Mahler), so it goes at most about
/// degree (bits + degree) + 64 levels deep (CGAL's square-free factors have at most `degree` bits
/// more, Mignotte); a level takes about 210 bytes (measured: 40 260 levels fill 8 MiB), 256 here.
std::size_t stack_for_isolation(int degree, std::size_t bits);

/// The stack every thread that isolates roots can count on: a quarter of the usual 8 MiB.
inline constexpr std::size_t kCallerStack = std::size_t(2) << 20;

/// Runs fn() on a new thread whose stack holds `bytes`, waits for it and rethrows what fn threw.
/// Throws std::bad_alloc when the thread cannot be started.
void run_on_large_stack(std::size_t bytes, const std::function<void()>& fn);

/// fn() on the calling thread when the isolation of such a polynomial fits in kCallerStack, else on
/// a thread of its own with stack_for_isolation(degree, bits) (a near-double root of f in a pair of
/// large numbers: its recursion would otherwise overflow any thread's stack, the main thread's of a
/// report included).
template <class F>
void isolate_on_fitting_stack(int degree, std::size_t bits, F fn) {
  const std::size_t bytes = stack_for_isolation(degree, bits);
  if (bytes <= kCallerStack)
    fn();
  else
    run_on_large_stack(bytes, fn);
}

}  // namespace relpos::detail
