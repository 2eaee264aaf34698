// Work whose recursion depth grows with the size of its numbers, on a thread with a stack to match.
// Internal: not part of the public API.
#pragma once

#include <cstddef>
#include <functional>

namespace relpos::detail {

/// The stack a pair of `bits` needs (the bits of the larger primitive integer form of its two
/// matrices): CGAL's Descartes root isolation recurses once per bit of root separation, about 190
/// bytes a level; measured, a pair of 332 000 bits needs more than 8 MB and less than 16 MB
/// (doc/cli.md, Limits). 128 bytes per bit, at least 16 MiB.
std::size_t stack_for_bits(std::size_t bits);

/// Runs fn() on a new thread whose stack holds `bytes`, waits for it and rethrows what fn threw.
/// Throws std::bad_alloc when the thread cannot be started.
void run_on_large_stack(std::size_t bytes, const std::function<void()>& fn);

}  // namespace relpos::detail
