#pragma once
// A fresh temporary directory ($TMPDIR or /tmp), removed with its contents when
// this object goes away, or by the exit watchdog when the process is interrupted or
// killed first (kernel/exit_guard.hpp).
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "kernel/exit_guard.hpp"

namespace dtlab {

class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "dtlab") {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/" + prefix + "-XXXXXX";
    std::vector<char> buf(tmpl.begin(), tmpl.end());
    buf.push_back('\0');
    if (mkdtemp(buf.data()) == nullptr) throw std::runtime_error("cannot create a temporary directory in " + tmpl);
    path_ = buf.data();
    guard_path(path_.string());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    release_path(path_.string());
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace dtlab
