// The one per-thread free list of relpos (doc/performance.md, "Memory: one strategy"): objects that
// own heap blocks -- GMP integers with their limbs -- are given back to their thread's list when
// their user is done and taken from it by the next user, so a warm thread computes without malloc.
// Two users: a pair's scratch (the integers the full evidence writes in place, S^4 f and S^3 s, the
// integer forms: src/pair/pair.hpp), taken when the pair first needs it and given back when the pair
// ends; and every exact-sign integer (PooledInteger, src/filters/pooled_integer.hpp), taken and given
// back per value. No scratch value is ever copied into a result (so writing it in place the next time
// is safe). The GMP blocks no such object owns are recycled by the block cache (gmp_blocks.cpp).
#pragma once

#include <memory>
#include <utility>
#include <vector>

namespace relpos::detail {

/// A T from this thread's free list (a new T when the list is empty), given back when the handle
/// dies; taken and given back on the same thread. Its values are what the previous user left.
template <class T>
class Recycled {
 public:
  Recycled() : p_(take()) {}
  ~Recycled() { give(std::move(p_)); }
  Recycled(const Recycled&) = delete;
  Recycled& operator=(const Recycled&) = delete;
  T& operator*() const { return *p_; }
  T* operator->() const { return p_.get(); }

  /// The same without a handle, for a caller that keeps the object in its own member (PooledInteger).
  static std::unique_ptr<T> take() {
    List& l = list();
    if (l.free.empty()) return std::make_unique<T>();
    std::unique_ptr<T> p = std::move(l.free.back());
    l.free.pop_back();
    return p;
  }
  static void give(std::unique_ptr<T> p) { list().free.push_back(std::move(p)); }

 private:
  struct List {
    std::vector<std::unique_ptr<T>> free;
    // One T made while the list is built: whatever thread-local state T's construction touches (the
    // list of PooledInteger's integers, for a pair's scratch) is then complete first and, destroyed in
    // reverse order, outlives this list.
    List() { free.push_back(std::make_unique<T>()); }
  };
  static List& list() {
    thread_local List l;
    return l;
  }
  std::unique_ptr<T> p_;
};

}  // namespace relpos::detail
