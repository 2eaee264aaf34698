// Shared by the commands of the relpos CLI: exit codes, usage errors, input lines and output.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/worker_pool.hpp"

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
  std::size_t newline_ = std::string::npos;  ///< the first '\n' from begin_ on, when ready() found it
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

/// The library's worker pool (src/base/worker_pool.hpp): batch answers its chunks on it.
using WorkerPool = relpos::detail::WorkerPool;

/// Flush std::cout; on failure print the one write-failure message and return kExitIo.
int finish_cout();

/// Open FILE for reading ("-" or empty: standard input). Returns the descriptor, or -1 after
/// printing "relpos: cannot open 'FILE': ..." (a directory says so).
int open_input(const std::string& file);

}  // namespace relpos_cli
