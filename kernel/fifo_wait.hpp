#pragma once
// A FIFO's other end. Opening a FIFO blocks until the other side opens it too (as
// `cat fifo` and `cat > fifo` do), so an input FIFO nobody writes, or an output FIFO
// nobody reads, would hang dtlab for ever. Both wait at most fifo_wait_s() seconds
// (DTLAB_FIFO_WAIT, default 10) for the other process, then fail with an InputError
// naming the file (exit 2). A regular file, a device or a missing path is not waited for.
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "kernel/input_error.hpp"

namespace dtlab {

// DTLAB_FIFO_WAIT seconds (a number in [0, 86400]; anything else: the default), default 10.
inline double fifo_wait_s() {
  const char* v = std::getenv("DTLAB_FIFO_WAIT");
  if (!v || !*v) return 10;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  return *end == '\0' && s >= 0 && s <= 86400 ? s : 10;
}

inline bool is_fifo(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
}

inline std::string fifo_wait_text() {
  char wait[32];
  std::snprintf(wait, sizeof wait, "%g", fifo_wait_s());
  return wait;
}

// Opens the FIFO at `path` for writing once a process reads it (a non-blocking open
// fails with ENXIO until then), then makes the descriptor blocking again; nullptr with
// errno set when it fails, ENXIO when no reader came within the wait.
inline std::FILE* open_fifo_for_writing(const std::string& path, const char* mode) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(fifo_wait_s());
  for (;;) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      std::FILE* f = ::fdopen(fd, mode);
      if (!f) ::close(fd);
      return f;
    }
    if (errno != ENXIO || std::chrono::steady_clock::now() >= until) return nullptr;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// An input FIFO opened for reading once a process has opened it for writing: a
// non-blocking read end, polled (Linux reports nothing until a writer comes), then made
// blocking; the reader reads from that descriptor (release()). A second, blocking open
// would not do: once a quick writer has written and closed, it waits for the next
// writer, although the data sits in the pipe. Throws "no process opened the FIFO for
// writing within 10 s". For other paths fd() is -1.
class FifoWriterWait {
 public:
  explicit FifoWriterWait(const std::string& path) {
    if (!is_fifo(path)) return;
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) return;  // the reader's own open names the error
    pollfd p{fd_, POLLIN, 0};
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(fifo_wait_s());
    int ready = 0;
    do {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
      ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
    } while (ready < 0 && errno == EINTR);
    if (ready == 0 && !writer_connected()) {
      ::close(fd_);
      fd_ = -1;
      throw InputError(path, 0, "no process opened the FIFO for writing within " + fifo_wait_text() + " s");
    }
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
  }
  int fd() const { return fd_; }
  // The descriptor, now the caller's to close.
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }
  ~FifoWriterWait() {
    if (fd_ >= 0) ::close(fd_);
  }
  FifoWriterWait(const FifoWriterWait&) = delete;
  FifoWriterWait& operator=(const FifoWriterWait&) = delete;

 private:
  // After a quiet wait: whether a writer holds the FIFO open without having written yet
  // (a slow producer), told apart from no writer at all without consuming a byte: tee(2)
  // copies pipe data without removing it, and with no data it answers EAGAIN while a
  // writer is connected and 0 (end of file) when none is. Where tee cannot say, the
  // benefit of the doubt (the read then blocks, as any read of a FIFO).
  bool writer_connected() const {
    int scratch[2];
    if (::pipe2(scratch, O_CLOEXEC | O_NONBLOCK) != 0) return true;
    const ssize_t n = ::tee(fd_, scratch[1], 1, SPLICE_F_NONBLOCK);  // 1: data; -1: EAGAIN or no tee
    ::close(scratch[0]);
    ::close(scratch[1]);
    return n != 0;
  }

  int fd_ = -1;
};

}  // namespace dtlab
