#pragma once
// Scratch files for the sampling tests, under the system temp directory.
#include <filesystem>
#include <fstream>
#include <string>

#include "kernel/input_error.hpp"

namespace dtlab::test {

inline std::filesystem::path scratch(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "dtlab_sampling_tests";
  std::filesystem::create_directories(dir);
  return dir / name;
}

inline std::string write_file(const std::string& name, const std::string& bytes) {
  const auto p = scratch(name);
  std::ofstream(p, std::ios::binary) << bytes;
  return p.string();
}

// "line:reason" of the InputError thrown by f, or "" when none is thrown.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ":" + e.reason();
  }
  return "";
}

}  // namespace dtlab::test
