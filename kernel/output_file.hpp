#pragma once
// An output file whose every write is checked: opening, writing (the stream's error
// flag) and closing (the final flush, where a full disk shows). A failure is an
// InputError naming the file ("out.node:0: write failed: No space left on device"),
// so the command exits 2 instead of printing "wrote".
// The write is atomic where the target is a regular file (or does not exist yet): the
// text goes to PATH.part-PID-N beside it, renamed to PATH by close(). A failure, an
// exception on the way or an interrupt (kernel/exit_guard.hpp) removes the part file,
// so PATH is either the old file or the whole new one, never a cut one.
// A FIFO is written in place once a reader has opened it (kernel/fifo_wait.hpp: at most
// DTLAB_FIFO_WAIT seconds, then "no process opened the FIFO for reading within 10 s").
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "kernel/exit_guard.hpp"
#include "kernel/fifo_wait.hpp"
#include "kernel/input_error.hpp"

namespace dtlab {

// The files of one result written as a set (PREFIX.node and .ele, .points.npy and
// .tets.npy, a cell set's .obj, .json and .vtu) are each replaced atomically, but one
// after the other: an interrupt between two renames would leave a new file beside an
// old one of the same prefix, a set no run wrote. Removing the old members before the
// first is written leaves, at any interrupt, only files of the new run (a reader then
// meets a missing member, never a stale one). `paths` are all the set's members, those
// this run writes and those it does not (an old .vtu beside a new .node/.ele would be a
// stale member too). Paths that are not regular files (a device, a FIFO), are missing
// or are one of `keep` (the same file: the run's inputs) are left alone. Returns the
// paths removed.
inline bool same_file(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

inline std::vector<std::string> remove_output_set(const std::vector<std::string>& paths,
                                                  const std::vector<std::string>& keep = {}) {
  std::vector<struct stat> kept;
  for (const std::string& k : keep) {
    struct stat st {};
    if (!k.empty() && stat(k.c_str(), &st) == 0) kept.push_back(st);
  }
  std::vector<std::string> removed;
  for (const std::string& p : paths) {
    struct stat st {};
    if (p.empty() || stat(p.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    bool is_kept = false;
    for (const struct stat& k : kept) is_kept = is_kept || same_file(st, k);
    if (!is_kept && ::unlink(p.c_str()) == 0) removed.push_back(p);
  }
  return removed;
}

class OutputFile {
 public:
  explicit OutputFile(std::string path, const char* mode = "w") : path_(std::move(path)) {
    if (mode[0] == 'w' && replaceable(path_)) {
      static std::atomic<unsigned> counter{0};
      part_ = path_ + ".part-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
      guard_path(part_);
    }
    const bool fifo = part_.empty() && mode[0] != 'r' && is_fifo(path_);
    f_ = fifo ? open_fifo_for_writing(path_, mode) : std::fopen(part_.empty() ? path_.c_str() : part_.c_str(), mode);
    if (!f_) {
      const int e = errno;
      drop_part();
      if (fifo && e == ENXIO)
        throw InputError(path_, 0, "no process opened the FIFO for reading within " + fifo_wait_text() + " s");
      throw InputError(path_, 0, std::string("cannot open file for writing: ") + std::strerror(e));
    }
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  // Unclosed (an exception on the way): closed without a check, the part file removed.
  ~OutputFile() {
    if (f_) std::fclose(f_);
    drop_part();
  }
  std::FILE* get() const { return f_; }
  const std::string& path() const { return path_; }

  // Flushes and closes; throws if any write, the flush or the close failed.
  void close() {
    std::FILE* f = f_;
    f_ = nullptr;
    errno = 0;
    const bool write_error = std::ferror(f) != 0;
    const bool flush_error = std::fflush(f) != 0;
    const int flush_errno = errno;
    const bool close_error = std::fclose(f) != 0;
    int e = flush_errno ? flush_errno : errno;
    const bool failed = write_error || flush_error || close_error;
    if (!failed && !part_.empty()) {
      if (std::rename(part_.c_str(), path_.c_str()) == 0) {
        release_path(part_);
        part_.clear();
        return;
      }
      e = errno;
    }
    if (failed || !part_.empty()) {
      drop_part();
      throw InputError(path_, 0, std::string("write failed: ") + (e ? std::strerror(e) : "I/O error"));
    }
  }

 private:
  // A device, a FIFO or /dev/stdout is written in place.
  static bool replaceable(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) != 0 ? errno == ENOENT : S_ISREG(st.st_mode);
  }
  void drop_part() {
    if (part_.empty()) return;
    std::remove(part_.c_str());
    release_path(part_);
    part_.clear();
  }

  std::string path_;
  std::string part_;  // "": written in place
  std::FILE* f_ = nullptr;
};

// Writes `text` to `path` as a whole, checked.
inline void write_text_file(const std::string& path, const std::string& text) {
  OutputFile f(path);
  std::fwrite(text.data(), 1, text.size(), f.get());
  f.close();
}

}  // namespace dtlab
