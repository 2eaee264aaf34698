// The one per-thread cache of a pair's scratch (doc/architecture.md, "One home for a pair"): the
// integers the full evidence writes in place (the integer forms, S^4 f and S^3 s) keep their limbs
// from pair to pair instead of being allocated and freed some forty times per pair. A pair takes a
// scratch object when it first needs one and gives it back when it ends; nothing else of the pair
// outlives its call, and no scratch value is ever copied into a result (so writing it in place the
// next time is safe).
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
  ~Recycled() { list().free.push_back(std::move(p_)); }
  Recycled(const Recycled&) = delete;
  Recycled& operator=(const Recycled&) = delete;
  T& operator*() const { return *p_; }
  T* operator->() const { return p_.get(); }

 private:
  struct List {
    std::vector<std::unique_ptr<T>> free;
    // One T made while the list is built: whatever thread-local state T's construction touches (the
    // pool of PooledInteger) is then complete first and, destroyed in reverse order, outlives the list.
    List() { free.push_back(std::make_unique<T>()); }
  };
  static List& list() {
    thread_local List l;
    return l;
  }
  static std::unique_ptr<T> take() {
    List& l = list();
    if (l.free.empty()) return std::make_unique<T>();
    std::unique_ptr<T> p = std::move(l.free.back());
    l.free.pop_back();
    return p;
  }
  std::unique_ptr<T> p_;
};

}  // namespace relpos::detail
