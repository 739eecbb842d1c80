#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"

using namespace dtlab;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / "dtlab_tests";
  fs::create_directories(dir);
  return dir / name;
}
void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string error_of(const std::string& path) {
  try {
    read_points(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("node reader accepts TetGen's format with comments, attributes and markers") {
  auto p = scratch("ok.node");
  write_text(p, "# a comment\n3 3 1 1\n1 0.5 1e-3 -2 7.0 1 # point one\n\n2 1 2 3 0 0\n3 4 5 6 0 1\n");
  PointFile f = read_node(p.string());
  REQUIRE(f.first_index == 1);
  REQUIRE(f.points.size() == 3);
  CHECK(f.points[0] == Point3{0.5, 1e-3, -2});
  CHECK(f.points[2] == Point3{4, 5, 6});
}

TEST_CASE("malformed node files name the file, the line and the reason") {
  auto p = scratch("bad.node");
  write_text(p, "3 3 0 0\n0 0 0 0\n1 1 x 0\n2 0 0 1\n");
  CHECK(error_of(p.string()) == p.string() + ":3: not a number: 'x'");
  write_text(p, "3 3 0 0\n0 0 0 0\n1 1 0 0\n");
  CHECK(error_of(p.string()) == p.string() + ":3: expected 3 points, file ends after 2");
  write_text(p, "2 2 0 0\n0 0 0\n1 1 0\n");
  CHECK(error_of(p.string()) == p.string() + ":1: dimension must be 3, got 2");
  write_text(p, "2 3 0 0\n0 0 0 0\n5 1 0 0\n");
  CHECK(error_of(p.string()) == p.string() + ":3: point index 5 out of sequence (expected 1)");
  write_text(p, "1 3 0 0\n0 nan 0 0\n");
  CHECK(error_of(p.string()) == p.string() + ":2: non-finite coordinate: 'nan'");
  CHECK(error_of(scratch("missing.node").string()) == scratch("missing.node").string() + ":0: cannot open file");
}

TEST_CASE("xyz reader and writer round-trip doubles exactly") {
  std::vector<Point3> pts = {{0.1, 0.2, 0.3}, {1e-300, -1e300, 4.9406564584124654e-324}, {1, 2, 3}};
  auto p = scratch("rt.xyz");
  write_xyz(p.string(), pts);
  CHECK(read_points(p.string()).points == pts);
  auto q = scratch("rt.node");
  write_node(q.string(), pts);
  CHECK(read_points(q.string()).points == pts);
  write_text(p, "1 2\n");
  CHECK(error_of(p.string()) == p.string() + ":1: expected 'x y z', got 2 field(s)");
}

TEST_CASE("tetgen .node/.ele round trip keeps dtlab's orientation") {
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.tets = {{0, 1, 2, 3}};
  auto prefix = scratch("rt_mesh").string();
  write_tetgen(prefix, t);
  Tetrahedralization back = read_tetgen(prefix);
  CHECK(back.points == t.points);
  REQUIRE(back.tets.size() == 1);
  CHECK(back.tets[0] == t.tets[0]);
  write_text(prefix + ".ele", "1 4 0\n0 0 1 2 9\n");
  CHECK_THROWS_WITH(read_tetgen(prefix), prefix + ".ele:2: vertex index 9 out of range");
}
