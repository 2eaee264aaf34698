// Per-thread recycling of GMP's small blocks (include/relpos/numbers.hpp, install_gmp_block_cache):
// the second home of relpos's one memory strategy, recycle per thread (doc/performance.md, "Memory:
// one strategy", with the A/B against glibc, jemalloc and mimalloc). Whole integers are given back
// to the free list (recycled.hpp); the limbs of the numbers no object keeps (CGAL's handles, the
// evidence's rationals) come here. GMP passes the size to free and realloc, so a cache keyed on
// the exact size needs no header and never hands a block to a request larger than the block.
#include <gmp.h>

#include <cstdlib>
#include <cstring>
#include <new>

#include "relpos/numbers.hpp"

namespace relpos {
namespace {

constexpr std::size_t kMaxBytes = 512;               // limb arrays of up to 64 limbs
constexpr std::size_t kClasses = kMaxBytes / 8 + 1;  // one free list per multiple of 8 bytes
constexpr unsigned kPerClass = 512;                  // at most 256 KiB per thread and class

struct Block {
  Block* next;
};

struct Cache {
  Block* head[kClasses] = {};
  unsigned count[kClasses] = {};
  ~Cache();
};

thread_local bool t_alive = false;    // trivially destructible: readable while t_cache is destroyed
thread_local bool t_started = false;  // t_cache was constructed on this thread
thread_local Cache t_cache;

Cache::~Cache() {
  t_alive = false;  // frees after this point go straight to free()
  for (std::size_t c = 0; c < kClasses; ++c)
    for (Block* b = head[c]; b;) {
      Block* next = b->next;
      std::free(b);
      b = next;
    }
}

/// Thrown through GMP's C frames (built with unwind tables): a number being grown keeps its old
/// limbs, so the caller's numbers stay valid and out of memory is one answer's error, not the end
/// of the process (doc/cli.md, "Out of memory").
[[noreturn]] void out_of_memory() { throw std::bad_alloc(); }

/// The cache holding blocks of exactly n bytes (list c), or nothing: other sizes, or the thread's
/// cache is already destroyed.
Cache* cache_for(std::size_t n, std::size_t& c) {
  if (n == 0 || n > kMaxBytes || n % 8 != 0) return nullptr;
  if (!t_alive) {
    if (t_started) return nullptr;
    t_started = t_alive = true;  // t_cache is constructed by its first use, below
  }
  c = n / 8;
  return &t_cache;
}

void* allocate(std::size_t n) {
  std::size_t c;
  if (Cache* k = cache_for(n, c); k && k->head[c]) {
    Block* b = k->head[c];
    k->head[c] = b->next;
    --k->count[c];
    return b;
  }
  void* p = std::malloc(n);
  if (!p) out_of_memory();
  return p;
}

void release(void* p, std::size_t n) {
  std::size_t c;
  if (Cache* k = cache_for(n, c); k && k->count[c] < kPerClass) {
    Block* b = static_cast<Block*>(p);
    b->next = k->head[c];
    k->head[c] = b;
    ++k->count[c];
    return;
  }
  std::free(p);
}

void* reallocate(void* p, std::size_t old_size, std::size_t new_size) {
  std::size_t c;
  if (!cache_for(old_size, c) && !cache_for(new_size, c)) {  // large numbers: realloc may grow in place
    void* q = std::realloc(p, new_size);
    if (!q) out_of_memory();
    return q;
  }
  void* q = allocate(new_size);
  std::memcpy(q, p, old_size < new_size ? old_size : new_size);
  release(p, old_size);
  return q;
}

}  // namespace

void install_gmp_block_cache() { mp_set_memory_functions(allocate, reallocate, release); }

}  // namespace relpos
