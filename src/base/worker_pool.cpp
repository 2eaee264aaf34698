#include "base/worker_pool.hpp"

#include <exception>

namespace relpos::detail {

WorkerPool::WorkerPool(unsigned threads) {
  try {
    for (unsigned w = 1; w < threads; ++w) workers_.emplace_back([this, w] { work(w); });
  } catch (const std::exception&) {
    // Too little memory for another thread's stack: the threads started do the work.
  }
}

WorkerPool::~WorkerPool() { stop_and_join(); }

void WorkerPool::stop_and_join() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (auto& t : workers_) t.join();
}

void WorkerPool::drain(unsigned w) {
  if (each_) {
    (*each_)(w);
    return;
  }
  for (std::size_t i; (i = next_.fetch_add(1)) < size_;) (*task_)(i);
}

void WorkerPool::work(unsigned w) {
  unsigned long seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    drain(w);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++finished_;
    }
    done_.notify_one();
  }
}

void WorkerPool::run(std::size_t n, const std::function<void(std::size_t)>& f) {
  if (workers_.empty() || n < 2) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  round(&f, nullptr, n);
}

void WorkerPool::run_on_each(const std::function<void(unsigned)>& f) {
  if (workers_.empty()) {
    f(0);
    return;
  }
  round(nullptr, &f, 0);
}

void WorkerPool::round(const std::function<void(std::size_t)>* task, const std::function<void(unsigned)>* each,
                       std::size_t n) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    task_ = task;
    each_ = each;
    size_ = n;
    next_.store(0);
    finished_ = 0;
    ++generation_;
  }
  start_.notify_all();
  drain(0);
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return finished_ == workers_.size(); });
}

}  // namespace relpos::detail
