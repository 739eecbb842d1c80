#pragma once
// While alive (and `on`), the process's stdout goes to stderr: commands with --json
// keep their human-readable progress and reports visible and leave stdout to the
// one JSON summary.
#include <cstdio>

#include <unistd.h>

namespace dtlab::cli {

class StdoutToStderr {
 public:
  explicit StdoutToStderr(bool on) : saved_(on ? dup(1) : -1) {
    if (saved_ >= 0) std::fflush(stdout), dup2(2, 1);
  }
  ~StdoutToStderr() {
    if (saved_ >= 0) std::fflush(stdout), dup2(saved_, 1), close(saved_);
  }
  StdoutToStderr(const StdoutToStderr&) = delete;
  StdoutToStderr& operator=(const StdoutToStderr&) = delete;

 private:
  int saved_;
};

}  // namespace dtlab::cli
