// Readers against hostile files: counts the file cannot hold, numbers beyond a double,
// tokens too long to echo, directories, trailing records.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"

using namespace dtlab;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / "dtlab_tests_limits";
  fs::create_directories(dir);
  return dir / name;
}
void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a header count beyond what the file can hold is refused before any reservation") {
  const auto p = scratch("big.node");
  write_text(p, "5000000 3 0 0\n0 0 0 0\n");
  CHECK(error_of([&] { read_node(p.string()); }) ==
        p.string() + ":1: point count too large: '5000000' in a file of 22 bytes");
  // The largest count the size allows still reads (and then finds the file short).
  write_text(p, "2 3 0 0\n0 0 0 0\n");
  CHECK(error_of([&] { read_node(p.string()); }) == p.string() + ":2: expected 2 points, file ends after 1");
  const auto e = scratch("big.ele");
  write_text(e, "99999999999 4 0\n0 0 1 2 3\n");
  CHECK(error_of([&] { read_ele(e.string(), 0, 4); }).starts_with(e.string() + ":1: tetrahedron count too large"));
}

TEST_CASE("numbers beyond a double are out of range, and long tokens are not echoed in full") {
  const auto p = scratch("range.xyz");
  write_text(p, "0 0 0\n1 0 0\n0 1e999 0\n");
  CHECK(error_of([&] { read_xyz(p.string()); }) == p.string() + ":3: number out of range of a double: '1e999'");
  write_text(p, "0 0 0\n-1e-999 0 0\n");
  CHECK(error_of([&] { read_xyz(p.string()); }) == p.string() + ":2: number out of range of a double: '-1e-999'");
  write_text(p, "0 0 1" + std::string(400, '0') + "\n");
  const std::string msg = error_of([&] { read_xyz(p.string()); });
  CHECK(msg == p.string() + ":1: number out of range of a double: '100000000000000000000000...' (401 characters)");
  const auto n = scratch("range.node");
  write_text(n, "99999999999999999999 3 0 0\n");
  CHECK(error_of([&] { read_node(n.string()); }) == n.string() + ":1: integer out of range: '99999999999999999999'");
}

TEST_CASE("a directory given as an input file is named as one") {
  const auto d = scratch("folder.node");
  fs::create_directories(d);
  CHECK(error_of([&] { read_node(d.string()); }) == d.string() + ":0: is a directory");
}

TEST_CASE(".ele: trailing records and extreme ids are refused") {
  const auto p = scratch("trail.node");
  write_text(p, "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  write_text(scratch("trail.ele"), "1 4 0\n0 1 0 2 3\n1 1 0 2 3\n");
  const std::string prefix = scratch("trail").string();
  CHECK(error_of([&] { read_tetgen(prefix); }) ==
        prefix + ".ele:3: unexpected data after the last tetrahedron (the header says 1)");
  write_text(scratch("trail.ele"), "1 4 9223372036854775807\n0 1 0 2 3\n");
  CHECK(error_of([&] { read_tetgen(prefix); }) == prefix + ".ele:1: attribute count too large: 9223372036854775807");
  write_text(scratch("trail.ele"), "1 4 0\n1 1 2 3 -9223372036854775808\n");
  CHECK(error_of([&] { read_ele(prefix + ".ele", 1, 4); }) ==
        prefix + ".ele:2: vertex index -9223372036854775808 out of range");
}
