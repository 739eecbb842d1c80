#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>

#include "kernel/tests/vtu_reader.hpp"
#include "kernel/tet_io.hpp"
#include "kernel/vtu_writer.hpp"

using namespace dtlab;

namespace {
std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("dtlab_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

// Every array of the binary file equals the ASCII file's, value for value.
void check_same_arrays(const test::VtuFile& ascii, const test::VtuFile& binary) {
  CHECK(ascii.points == binary.points);
  CHECK(ascii.cells == binary.cells);
  REQUIRE(ascii.arrays.size() == binary.arrays.size());
  for (const auto& [name, a] : ascii.arrays) {
    INFO(name);
    REQUIRE(binary.arrays.count(name) == 1);
    const auto& b = binary.arrays.at(name);
    CHECK(a.format == "ascii");
    CHECK(b.format == "binary");
    CHECK(a.type == b.type);
    CHECK(a.components == b.components);
    CHECK(b.header_bytes == b.values.size() * (b.type == "UInt8" ? 1 : 8));
    CHECK(a.values == b.values);
  }
}
}  // namespace

TEST_CASE("vtu: base64 of the RFC 4648 test vectors") {
  const std::string in = "foobar";
  const char* expected[] = {"", "Zg==", "Zm8=", "Zm9v", "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy"};
  for (std::size_t n = 0; n <= in.size(); ++n) {
    CHECK(base64_encode(in.data(), n) == expected[n]);
    const auto back = test::base64_decode(expected[n]);
    CHECK(std::string(back.begin(), back.end()) == in.substr(0, n));
  }
}

TEST_CASE("vtu: a tetrahedralization in binary decodes to the ASCII file's values") {
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {0.5, 0.5, 0}};
  // dtlab's orientation: orient3d > 0 (the writer swaps the first two for VTK).
  t.tets = {{1, 0, 2, 3}, {1, 2, 4, 3}, {0, 1, 5, 2}};  // the last one is flat: a defect
  const std::string a = temp_path("tets_ascii.vtu"), b = temp_path("tets_binary.vtu");
  write_vtu(a, t, VtuFormat::ascii);
  write_vtu(b, t);  // binary is the default
  const test::VtuFile fa = test::read_vtu(a), fb = test::read_vtu(b);
  CHECK(fb.first_lines ==
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">");
  check_same_arrays(fa, fb);
  CHECK(fb.points == 6);
  CHECK(fb.cells == 3);
  CHECK(fb.arrays.at("Points").components == 3);
  CHECK(fb.arrays.at("Points").values.size() == 18);
  CHECK(fb.arrays.at("Points").values[12] == 1.0);  // point 4: (1, 1, 1)
  CHECK(fb.arrays.at("connectivity").values == std::vector<double>{0, 1, 2, 3, 2, 1, 4, 3, 1, 0, 5, 2});
  CHECK(fb.arrays.at("offsets").values == std::vector<double>{4, 8, 12});
  CHECK(fb.arrays.at("types").values == std::vector<double>{10, 10, 10});
  CHECK(fb.arrays.at("volume").values[0] == Approx(1.0 / 6));
  CHECK(fb.arrays.at("volume").values[1] == Approx(1.0 / 3));
  CHECK(fb.arrays.at("volume").values[2] == 0.0);
  CHECK(fb.arrays.at("defect").values == std::vector<double>{0, 0, 1});
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST_CASE("vtu: a polyhedron cell's face stream, and a bad format name") {
  VtuGrid g;
  const Point3 v[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::uint32_t off[] = {0, 3, 6, 9, 12};
  const std::uint32_t fv[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  g.add_polyhedron(v, off, fv);
  g.add_polyhedron(v, off, fv);
  g.cell_data.push_back({"volume", std::vector<double>{1.0 / 6, 1.0 / 6}});
  CHECK(g.cell_count() == 2);
  CHECK(g.faceoffsets == std::vector<std::int64_t>{17, 34});
  CHECK(g.faces[17] == 4);
  CHECK(g.faces[18] == 3);
  CHECK(g.faces[19] == 4);  // the second cell's points start at 4
  const std::string a = temp_path("poly_ascii.vtu"), b = temp_path("poly_binary.vtu");
  write_vtu_grid(a, g, VtuFormat::ascii);
  write_vtu_grid(b, g, VtuFormat::binary);
  check_same_arrays(test::read_vtu(a), test::read_vtu(b));
  CHECK(test::read_vtu(b).arrays.at("faces").values.size() == 34);
  std::remove(a.c_str());
  std::remove(b.c_str());
  CHECK(parse_vtu_format("ascii") == VtuFormat::ascii);
  CHECK_THROWS_AS(parse_vtu_format("raw"), std::invalid_argument);
}
