#pragma once
// A fresh temporary directory ($TMPDIR or /tmp), removed with its contents when
// this object goes away, or by the exit watchdog when the process is interrupted or
// killed first (kernel/exit_guard.hpp).
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include "kernel/exit_guard.hpp"

namespace dtlab {

class TempDir {
 public:
  // The name is listed with the watchdog before the folder exists (as mkdtemp would
  // name it, then mkdir, retried on a name taken): a kill between the two finds the
  // folder listed, never an unlisted one left behind.
  explicit TempDir(const std::string& prefix = "dtlab") {
    const char* base = std::getenv("TMPDIR");
    const std::string stem = std::string(base && *base ? base : "/tmp") + "/" + prefix + "-";
    static constexpr char kChars[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::random_device random;
    for (int attempt = 0; attempt < 100; ++attempt) {
      std::string name = stem;
      for (int i = 0; i < 6; ++i) name += kChars[random() % (sizeof kChars - 1)];
      guard_path(name);
      if (mkdir(name.c_str(), 0700) == 0) {
        path_ = name;
        return;
      }
      const int err = errno;
      release_path(name);
      if (err != EEXIST) break;
    }
    throw std::runtime_error("cannot create a temporary directory " + stem + "XXXXXX");
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
