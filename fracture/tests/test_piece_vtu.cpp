#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>

#include "fracture/fracture.hpp"
#include "fracture/piece_io.hpp"
#include "fracture/tests/meshes.hpp"
#include "kernel/tests/vtu_reader.hpp"

using namespace dtlab;
using test::unit_cube;

TEST_CASE("pieces VTU: binary decodes to the ASCII values; one polyhedron per piece") {
  FractureOptions o;
  o.pieces = 12;
  o.seed = 4;
  o.recurse = {0};
  o.recurse_pieces = 3;
  const FractureResult r = fracture_mesh(unit_cube(), o);
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string a = dir + "/dtlab_pieces_ascii.vtu", b = dir + "/dtlab_pieces_binary.vtu";
  write_pieces_vtu(a, r, VtuFormat::ascii);
  write_pieces_vtu(b, r);
  const test::VtuFile fa = test::read_vtu(a), fb = test::read_vtu(b);
  REQUIRE(fa.arrays.size() == fb.arrays.size());
  for (const auto& [name, arr] : fa.arrays) {
    INFO(name);
    CHECK(fb.arrays.at(name).format == "binary");
    CHECK(fb.arrays.at(name).values == arr.values);
  }
  REQUIRE(fb.cells == r.pieces.size());
  const auto& volume = fb.arrays.at("volume").values;
  const auto& parent = fb.arrays.at("parent").values;
  const auto& faces = fb.arrays.at("faces").values;
  const auto& faceoffsets = fb.arrays.at("faceoffsets").values;
  double sum = 0;
  std::size_t children = 0, stream = 0;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    CHECK(volume[i] == r.pieces[i].volume);
    CHECK(parent[i] == r.pieces[i].parent);
    CHECK(fb.arrays.at("site").values[i] == static_cast<double>(r.pieces[i].site_index));
    children += parent[i] >= 0;
    sum += volume[i];
    // The cell's face stream: its triangle count, then 3 and three point ids per face.
    CHECK(faces[stream] == static_cast<double>(r.pieces[i].geometry.mesh.triangles.size()));
    stream = static_cast<std::size_t>(faceoffsets[i]);
  }
  CHECK(children >= 2);
  CHECK(sum == Approx(1).epsilon(1e-9));
  std::remove(a.c_str());
  std::remove(b.c_str());
}
