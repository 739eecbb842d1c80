#pragma once
// An output file whose every write is checked: opening, writing (the stream's error
// flag) and closing (the final flush, where a full disk shows). A failure is an
// InputError naming the file ("out.node:0: write failed: No space left on device"),
// so the command exits 2 instead of printing "wrote".
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "kernel/input_error.hpp"

namespace dtlab {

class OutputFile {
 public:
  explicit OutputFile(std::string path, const char* mode = "w")
      : path_(std::move(path)), f_(std::fopen(path_.c_str(), mode)) {
    if (!f_) throw InputError(path_, 0, std::string("cannot open file for writing: ") + std::strerror(errno));
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  // Unclosed (an exception on the way): closed without a check.
  ~OutputFile() {
    if (f_) std::fclose(f_);
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
    if (write_error || flush_error || close_error) {
      const int e = flush_errno ? flush_errno : errno;
      throw InputError(path_, 0, std::string("write failed: ") + (e ? std::strerror(e) : "I/O error"));
    }
  }

 private:
  std::string path_;
  std::FILE* f_;
};

// Writes `text` to `path` as a whole, checked.
inline void write_text_file(const std::string& path, const std::string& text) {
  OutputFile f(path);
  std::fwrite(text.data(), 1, text.size(), f.get());
  f.close();
}

}  // namespace dtlab
