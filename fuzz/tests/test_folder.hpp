#pragma once
// A fresh folder under the temp dir for one test, removed at scope exit.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace dtlab::fuzz {

struct TestFolder {
  std::filesystem::path path;
  TestFolder() {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("dtlab_fuzz_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path);
  }
  ~TestFolder() { std::filesystem::remove_all(path); }
  TestFolder(const TestFolder&) = delete;
  TestFolder& operator=(const TestFolder&) = delete;
};

}  // namespace dtlab::fuzz
