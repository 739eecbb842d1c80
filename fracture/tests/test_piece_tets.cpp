// Tetrahedralized pieces (TetGen -pY) and the exact volume identity of a fracture.
#include <catch2/catch.hpp>

#include <cstdlib>

#include "fracture/fracture.hpp"
#include "fracture/piece_tets.hpp"
#include "fracture/tests/meshes.hpp"
#include "fracture/volume_identity.hpp"

using namespace dtlab;
using test::small_torus;
using test::unit_cube;

namespace {

bool have_tetgen() { return std::system("command -v tetgen >/dev/null 2>&1") == 0; }

FractureResult fracture_torus(std::size_t pieces, std::uint64_t seed, Point3 scale = {1, 1, 1}) {
  FractureOptions o;
  o.pieces = pieces;
  o.seed = seed;
  o.threads = 1;
  o.exact_tiling = true;
  o.cell_scale = scale;
  return fracture_mesh(small_torus(), o);
}
}  // namespace

TEST_CASE("the unrounded pieces tile the mesh exactly; the written ones to 1e-15", "[fracture][exact]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const FractureResult r = fracture_torus(20, seed);
    CHECK(r.exact_tiling_checked);
    CHECK(r.exact_tiling);
    CHECK(r.exact_tiling_difference == 0);
    const VolumeIdentity id = volume_identity(r);
    CHECK(std::abs(id.relative(id.float_difference, r.mesh_volume)) <= 1e-12);
    // Rounding the cut vertices to doubles moves them off their planes: not exact.
    CHECK(std::abs(id.relative(id.exact_difference, r.mesh_volume)) <= 1e-14);
  }
  // Stretched cells (mapped back by the scale) tile exactly too.
  const FractureResult s = fracture_torus(12, 4, {1, 1, 4});
  CHECK(s.exact_tiling);
}

TEST_CASE("with a gap the exact tiling is not claimed", "[fracture][exact]") {
  FractureOptions o;
  o.pieces = 6;
  o.threads = 1;
  o.exact_tiling = true;
  o.margin = 0.05;
  const FractureResult r = fracture_mesh(small_torus(), o);
  CHECK_FALSE(r.exact_tiling_checked);
  CHECK_FALSE(r.exact_tiling);
  const VolumeIdentity id = volume_identity(r);
  CHECK(id.float_difference < 0);  // the gap removed volume
  CHECK(id.exact_difference < 0);
}

TEST_CASE("TetGen tetrahedralizes a cube and fractured pieces to their exact volumes", "[fracture][tets]") {
  if (!have_tetgen()) {
    WARN("tetgen is not installed: skipped");
    return;
  }
  const PieceTets cube = tetrahedralize_piece(unit_cube());
  CHECK(cube.exact_match);
  CHECK(cube.volume == 1);
  CHECK(cube.steiner == 0);
  CHECK(cube.tets.size() >= 5);
  const FractureResult r = fracture_torus(8, 5);
  const std::vector<PieceTets> tets = tetrahedralize_pieces(r);
  REQUIRE(tets.size() == r.pieces.size());
  for (std::size_t i = 0; i < tets.size(); ++i) {
    INFO("piece " << i);
    CHECK(tets[i].exact_match);
    CHECK(tets[i].volume == Approx(r.pieces[i].volume).epsilon(1e-12));
    // The surface's vertices come first, bit for bit.
    for (std::size_t v = 0; v < r.pieces[i].geometry.mesh.vertices.size(); ++v)
      CHECK(tets[i].points[v].x == r.pieces[i].geometry.mesh.vertices[v].x);
  }
}

TEST_CASE("a surface TetGen cannot tetrahedralize is a named failure", "[fracture][tets]") {
  if (!have_tetgen()) return;
  TriangleMesh open = unit_cube();
  open.triangles.pop_back();  // a hole: not a closed surface
  bool named = false;
  try {
    (void)tetrahedralize_piece(open);
  } catch (const std::runtime_error& e) {
    named = std::string(e.what()).find("tetgen") != std::string::npos;
  }
  CHECK(named);
  TetgenRunOptions missing;
  missing.binary = "/nonexistent/tetgen";
  CHECK_THROWS_WITH(tetrahedralize_piece(unit_cube(), missing), Catch::Contains("tetgen"));
}
