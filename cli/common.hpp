// Shared by the commands of the relpos CLI: exit codes, usage errors, input lines and output.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace relpos_cli {

/// The exit codes of every command (doc/cli.md, "Exit codes").
constexpr int kExitOk = 0;
constexpr int kExitInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitIo = 3;
constexpr int kExitInternal = 4;
constexpr int kExitBudget = 5;  // motion: --max-seconds exceeded

/// Reads lines from a file descriptor in blocks: memory O(longest line kept), lines longer than the
/// limit are skipped (their bytes are read, not stored) and reported as such.
class LineReader {
 public:
  enum class Status { Line, TooLong, OutOfMemory, End, Error };
  LineReader(int fd, std::size_t max_line_bytes) : fd_(fd), max_(max_line_bytes) {}
  /// The next line without its '\n' (status Line), or why there is none.
  Status next(std::string& line);
  /// True when next() would not block (a line is buffered, the input has data or has ended).
  bool ready();
  int error() const { return error_; }  ///< errno of the failed read (status Error)

 private:
  bool fill();
  static constexpr std::size_t kMoveAbove = std::size_t(1) << 20;  ///< longer lines are moved out
  int fd_;
  std::size_t max_;
  std::string buffer_;
  std::size_t begin_ = 0;
  bool eof_ = false;
  int error_ = 0;
};

/// Buffered output through write(2) (standard output unless told): a closed pipe or a full disk is
/// seen (SIGPIPE is ignored) and reported once, with exit code kExitIo. Allocates only when made:
/// a long text is written as it is, so that writing never runs out of memory.
class Output {
 public:
  explicit Output(int fd = 1);
  void write(std::string_view text);
  bool flush();  ///< false once a write has failed
  bool failed() const { return failed_; }
  int report_failure();  ///< prints "relpos: cannot write the output: ..." and returns kExitIo

 private:
  static constexpr std::size_t kBuffer = std::size_t(1) << 16;
  void put(std::string_view text);
  int fd_;
  std::string buffer_;
  bool failed_ = false;
  int error_ = 0;
};

/// Worker threads kept for a whole command: batch answers its input in short chunks (so that
/// interactive use is answered at once), and starting threads for each chunk cost more than the
/// work of a short one. The calling thread works too.
class WorkerPool {
 public:
  explicit WorkerPool(unsigned threads);  ///< threads - 1 workers (none for 1)
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }
  /// f(i) for every i in [0, n), each index once, on every thread (dynamic: items differ in cost);
  /// returns when all are done. f must not throw.
  void run(std::size_t n, const std::function<void(std::size_t)>& f);

 private:
  void work();
  void drain();
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  // Every worker takes part in every round and run() waits for all of them, so no worker can act
  // on a round that has ended (task_ and size_ are written under the mutex before the round starts).
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t size_ = 0;
  std::atomic<std::size_t> next_{0};
  unsigned long generation_ = 0;
  std::size_t finished_ = 0;
  bool stop_ = false;
};

/// Flush std::cout; on failure print the one write-failure message and return kExitIo.
int finish_cout();

/// Open FILE for reading ("-" or empty: standard input). Returns the descriptor, or -1 after
/// printing "relpos: cannot open 'FILE': ..." (a directory says so).
int open_input(const std::string& file);

}  // namespace relpos_cli
