// A thread with a large stack for one piece of work (large_stack.hpp).
#include "algebra/large_stack.hpp"

#include <pthread.h>

#include <algorithm>
#include <exception>
#include <new>

namespace relpos::detail {

std::size_t stack_for_bits(std::size_t bits) { return std::max<std::size_t>(std::size_t(16) << 20, 128 * bits); }

std::size_t stack_for_isolation(int degree, std::size_t bits) {
  const std::size_t n = degree > 0 ? static_cast<std::size_t>(degree) : 0;
  return 256 * (n * (bits + n) + 64);
}

namespace {

struct Job {
  const std::function<void()>* fn;
  std::exception_ptr error;
};

void* run_job(void* arg) {
  Job& job = *static_cast<Job*>(arg);
  try {
    (*job.fn)();
  } catch (...) {
    job.error = std::current_exception();
  }
  return nullptr;
}

}  // namespace

void run_on_large_stack(std::size_t bytes, const std::function<void()>& fn) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) throw std::bad_alloc();
  Job job{&fn, nullptr};
  pthread_t thread;
  const bool started =
      pthread_attr_setstacksize(&attr, bytes) == 0 && pthread_create(&thread, &attr, run_job, &job) == 0;
  pthread_attr_destroy(&attr);
  if (!started) throw std::bad_alloc();  // no room for the stack
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

}  // namespace relpos::detail
