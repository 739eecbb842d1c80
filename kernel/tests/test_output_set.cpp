#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "kernel/output_file.hpp"

using namespace dtlab;
namespace fs = std::filesystem;

namespace {
void touch(const std::string& path) { std::ofstream(path) << "old\n"; }
}  // namespace

TEST_CASE("remove_output_set: the old regular members go, the kept file, folders and FIFOs stay") {
  const fs::path dir = fs::temp_directory_path() / ("dtlab_output_set_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string p = (dir / "out").string();
  touch(p + ".node");
  touch(p + ".ele");
  touch(p + ".vtu");
  touch(p + ".other");               // not a member: stays
  fs::create_directory(p + ".obj");  // not a regular file: stays
  REQUIRE(mkfifo((p + ".json").c_str(), 0600) == 0);
  fs::create_hard_link(p + ".node", p + ".input.node");  // the same file as .node: kept

  const auto removed = remove_output_set({p + ".ele", p + ".vtu", p + ".obj", p + ".json", p + ".missing", ""});
  CHECK(removed == std::vector<std::string>{p + ".ele", p + ".vtu"});  // what was removed, in order
  CHECK(!fs::exists(p + ".ele"));
  CHECK(!fs::exists(p + ".vtu"));
  CHECK(fs::is_directory(p + ".obj"));
  CHECK(fs::is_fifo(p + ".json"));
  CHECK(fs::exists(p + ".other"));

  CHECK(remove_output_set({p + ".node", ""}, {"", p + ".other", p + ".input.node"}).empty());
  CHECK(fs::exists(p + ".node"));  // the input read as the output is kept
  remove_output_set({p + ".node"});
  CHECK(!fs::exists(p + ".node"));
  fs::remove_all(dir);
}
