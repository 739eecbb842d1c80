#include "fuzz/results_log.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace dtlab::fuzz {

ResultsLog::ResultsLog(std::string path) : path_(std::move(path)) {
  fd_ = open(path_.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
  // flock ends with the process, however it ends: a killed campaign leaves no stale lock.
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    close(fd_);
    fd_ = -1;
    if (e == EWOULDBLOCK)
      throw std::invalid_argument("another campaign is writing " + path_ +
                                  " now (its lock is held): wait for it to end or use another --out");
    throw std::runtime_error("cannot lock " + path_ + ": " + std::strerror(e));
  }
  drop_cut_line();
}

ResultsLog::~ResultsLog() {
  if (fd_ >= 0) close(fd_);
}

// Cuts the file back to just after its last newline.
void ResultsLog::drop_cut_line() {
  struct stat st {};
  if (fstat(fd_, &st) != 0) throw std::runtime_error("cannot read " + path_);
  off_t end = st.st_size;
  std::vector<char> chunk(1 << 16);
  while (end > 0) {
    const off_t from = end > off_t(chunk.size()) ? end - off_t(chunk.size()) : 0;
    const ssize_t n = pread(fd_, chunk.data(), static_cast<std::size_t>(end - from), from);
    if (n != end - from) throw std::runtime_error("cannot read " + path_);
    off_t i = n;
    while (i > 0 && chunk[static_cast<std::size_t>(i - 1)] != '\n') --i;
    if (i > 0) {
      end = from + i;
      break;
    }
    end = from;
  }
  if (end != st.st_size && ftruncate(fd_, end) != 0)
    throw std::runtime_error("cannot repair the cut last line of " + path_ + ": " + std::strerror(errno));
}

void ResultsLog::append(const std::string& lines) {
  std::size_t done = 0;
  while (done < lines.size()) {
    const ssize_t n = write(fd_, lines.data() + done, lines.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("write failed: " + path_ + ": " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace dtlab::fuzz
