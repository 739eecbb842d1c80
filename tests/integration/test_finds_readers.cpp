// The reader inputs that once broke dtlab (tests/finds/readers, README.txt there): each
// is now an InputError with file:line and a reason, never a crash, a bare
// std::bad_alloc, a reservation of what the file cannot hold, or a signed overflow.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "kernel/input_error.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"
#include "sampling/mesh_io.hpp"

namespace fs = std::filesystem;
using namespace dtlab;

namespace {

const fs::path kFinds = fs::path(DTLAB_SOURCE_DIR) / "tests" / "finds" / "readers";

// The InputError's message, or "" when the call succeeded. Any other exception fails the test.
std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string file(const std::string& name) { return (kFinds / name).string(); }

}  // namespace

TEST_CASE("finds: a header count larger than the file is refused at line 1", "[finds]") {
  for (const char* name : {"huge.node", "huge2.node", "maxsize.node", "big5e8.node"}) {
    INFO(name);
    const std::string msg = input_error([&] { read_node(file(name)); });
    CHECK(msg.starts_with(file(name) + ":1: point count too large"));
  }
  const std::string msg = input_error([] { read_tetgen(file("hugeele")); });
  CHECK(msg.starts_with(file("hugeele.ele") + ":1: tetrahedron count too large"));
}

TEST_CASE("finds: attribute counts and ids near LONG_MAX/LONG_MIN are range-checked", "[finds]") {
  CHECK(input_error([] { read_node(file("attrs_ovf.node")); }) ==
        file("attrs_ovf.node") + ":1: attribute count too large: 9223372036854775807");
  CHECK(input_error([] { read_tetgen(file("attrovf")); }) ==
        file("attrovf.ele") + ":1: attribute count too large: 9223372036854775807");
  CHECK(input_error([] { read_tetgen(file("oormin1")); }) ==
        file("oormin1.ele") + ":2: vertex index -9223372036854775808 out of range");
}

TEST_CASE("finds: an .ele with more tets than its header says is refused", "[finds]") {
  CHECK(input_error([] { read_tetgen(file("trailing2")); })
            .starts_with(file("trailing2.ele") + ":3: unexpected data after the last tetrahedron"));
}

TEST_CASE("finds: OFF face size and PLY integers beyond their types", "[finds]") {
  CHECK(input_error([] { read_mesh(file("facekovf.off")); }) ==
        file("facekovf.off") + ":7: face announces 9223372036854775807 corners, lists 3");
  CHECK(input_error([] { read_mesh(file("bigint_asc.ply")); }) ==
        file("bigint_asc.ply") + ":14: integer out of range of its type: '1e30'");
  CHECK(input_error([] { read_mesh(file("bigint2_asc.ply")); }) ==
        file("bigint2_asc.ply") + ":14: integer out of range of its type: '1e300'");
}

// The reader fuzzer's finds: byte 0 selected the format in that fuzzer, so each file's
// remaining bytes go through every reader. Each must answer or throw InputError.
TEST_CASE("finds: every reader fuzz find, through every reader", "[finds]") {
  const fs::path dir = fs::temp_directory_path() / ("dtlab_finds_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  int files = 0;
  for (const auto& e : fs::directory_iterator(kFinds)) {
    const std::string name = e.path().filename().string();
    if (!name.starts_with("crash-") && !name.starts_with("oom-")) continue;
    ++files;
    std::ifstream in(e.path(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    for (const char* ext : {".node", ".xyz", ".ele", ".off", ".obj", ".ply", ".stl"}) {
      const fs::path p = dir / (std::string("in") + ext);
      std::ofstream(p, std::ios::binary) << (bytes.empty() ? "" : bytes.substr(1));
      INFO(name << " as " << ext);
      const std::string path = p.string();
      std::string msg;
      if (std::string(ext) == ".ele") {
        msg = input_error([&] { read_ele(path, 0, 16); });
        if (!msg.empty()) CHECK(msg.starts_with(path + ":"));
        msg = input_error([&] { read_ele(path, 1, 16); });
      } else if (std::string(ext) == ".node" || std::string(ext) == ".xyz") {
        msg = input_error([&] { read_points(path); });
      } else {
        msg = input_error([&] { read_mesh(path); });
      }
      if (!msg.empty()) CHECK(msg.starts_with(path + ":"));
    }
  }
  fs::remove_all(dir);
  CHECK(files >= 40);
}
