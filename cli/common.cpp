#include "common.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <new>

namespace relpos_cli {

bool LineReader::fill() {
  if (eof_) return false;
  newline_ = std::string::npos;
  if (begin_ > 0) {
    buffer_.erase(0, begin_);
    begin_ = 0;
  }
  constexpr std::size_t kBlock = std::size_t(1) << 16;
  const std::size_t old = buffer_.size();
  buffer_.resize(old + kBlock);
  ssize_t got;
  do got = ::read(fd_, &buffer_[old], kBlock);
  while (got < 0 && errno == EINTR);
  buffer_.resize(old + (got > 0 ? static_cast<std::size_t>(got) : 0));
  if (got < 0) error_ = errno;
  if (got <= 0) eof_ = true;
  return got > 0;
}

LineReader::Status LineReader::next(std::string& line) {
  bool skipping = false;
  try {
    for (;;) {
      const std::size_t nl = newline_ != std::string::npos ? newline_ : buffer_.find('\n', begin_);
      newline_ = std::string::npos;
      if (nl != std::string::npos || (eof_ && begin_ < buffer_.size())) {
        const std::size_t end = nl == std::string::npos ? buffer_.size() : nl;
        if (skipping || end - begin_ > max_) {
          begin_ = nl == std::string::npos ? buffer_.size() : nl + 1;
          return Status::TooLong;
        }
        if (end - begin_ > kMoveAbove) {
          // A long line is handed over, not copied: the buffer becomes the line and what follows
          // it (at most one block) a new buffer, so a line costs its own size once.
          std::string rest(buffer_, nl == std::string::npos ? buffer_.size() : nl + 1);
          buffer_.resize(end);
          buffer_.erase(0, begin_);
          line.swap(buffer_);
          buffer_.swap(rest);
          begin_ = 0;
          return Status::Line;
        }
        line.assign(buffer_, begin_, end - begin_);
        begin_ = nl == std::string::npos ? buffer_.size() : nl + 1;
        return Status::Line;
      }
      if (buffer_.size() - begin_ > max_) {  // too long: drop what is buffered, skip to '\n'
        skipping = true;
        buffer_.clear();
        begin_ = 0;
      }
      if (!fill()) {
        if (error_ != 0) return Status::Error;
        if (skipping) return Status::TooLong;
        if (begin_ < buffer_.size()) continue;
        return Status::End;
      }
    }
  } catch (const std::bad_alloc&) {
    // Skip the rest of this line in small blocks; the run goes on.
    std::string().swap(buffer_);
    line.clear();
    begin_ = 0;
    newline_ = std::string::npos;
    try {
      while (fill()) {
        const std::size_t nl = buffer_.find('\n');
        if (nl != std::string::npos) {
          begin_ = nl + 1;
          break;
        }
        buffer_.clear();
      }
    } catch (const std::bad_alloc&) {  // not even one block: the input cannot be read on
      error_ = ENOMEM;
      return Status::Error;
    }
    return error_ != 0 ? Status::Error : Status::OutOfMemory;
  }
}

bool LineReader::ready() {
  if (newline_ == std::string::npos) newline_ = buffer_.find('\n', begin_);
  if (newline_ != std::string::npos || eof_) return true;
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

Output::Output(int fd) : fd_(fd) { buffer_.reserve(kBuffer); }

void Output::write(std::string_view text) {
  if (buffer_.size() + text.size() > kBuffer) {
    flush();
    if (text.size() > kBuffer / 2) {  // long text goes out as it is: no copy
      put(text);
      return;
    }
  }
  buffer_.append(text);  // within the capacity reserved once: no allocation
}

void Output::put(std::string_view text) {
  std::size_t done = 0;
  while (!failed_ && done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      failed_ = true;
      error_ = n < 0 ? errno : EIO;
    } else {
      done += static_cast<std::size_t>(n);
    }
  }
}

bool Output::flush() {
  put(buffer_);
  buffer_.clear();
  return !failed_;
}

int Output::report_failure() {
  std::cerr << "relpos: cannot write the output: " << std::strerror(error_) << "\n";
  return kExitIo;
}

int finish_cout() {
  errno = 0;
  std::cout.flush();
  if (std::cout) return kExitOk;
  const int e = errno;
  std::cerr << "relpos: cannot write the output" << (e ? std::string(": ") + std::strerror(e) : std::string()) << "\n";
  return kExitIo;
}

int open_input(const std::string& file) {
  if (file.empty() || file == "-") return STDIN_FILENO;
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    ::close(fd);
    std::cerr << "relpos: cannot open '" << file << "': it is a directory, not a file\n";
    return -1;
  }
  if (fd < 0) std::cerr << "relpos: cannot open '" << file << "': " << std::strerror(errno) << "\n";
  return fd;
}

}  // namespace relpos_cli
