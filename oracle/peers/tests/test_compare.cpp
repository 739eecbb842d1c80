// The canonical comparison: equal Delaunay complexes for CGAL and TetGen on an
// exactly cospherical input although their tets differ; a witness when not equal.
#include <algorithm>
#include <catch2/catch.hpp>

#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/check/tests/point_sets.hpp"
#include "oracle/peers/cgal_oracle.hpp"
#include "oracle/peers/tetgen_oracle.hpp"

using namespace dtlab;

namespace {

CheckReport checked(const OracleRun& run) {
  INFO(run.name << ": " << run.note);
  REQUIRE(run.mesh);
  const CheckReport r = check_tetrahedralization(*run.mesh, {.duplicates = run.duplicates});
  CHECK(r.ok());
  return r;
}

}  // namespace

TEST_CASE("cospherical: equal complexes although the tet counts differ", "[oracle]") {
  const auto pts = test::sphere_points(33 * 33);  // 390 integer points on one sphere
  REQUIRE(pts.size() == 390);
  const OracleRun cgal = cgal_delaunay(pts);
  const OracleRun tetgen = tetgen_delaunay(pts);
  const CheckReport rc = checked(cgal), rt = checked(tetgen);
  CHECK(cgal.mesh->tets.size() != tetgen.mesh->tets.size());
  const Comparison c = compare_canonical(*cgal.mesh, rc, *tetgen.mesh, rt);
  CHECK_FALSE(c.general_position);
  CHECK_FALSE(c.tets_equal);
  CHECK(c.complexes_equal);
  CHECK(c.cells_a == 1);  // all points on one empty sphere: one cell
}

TEST_CASE("the comparison reports a differing cell with a witness", "[oracle]") {
  const auto pts = test::uniform_points(100, 3);
  const OracleRun cgal = cgal_delaunay(pts);
  const CheckReport rc = checked(cgal);
  Tetrahedralization other = *cgal.mesh;
  other.tets.pop_back();  // not a valid DT any more; the comparison still names the cell
  CheckReport ro = check_tetrahedralization(other);
  CHECK_FALSE(ro.ok());
  const Comparison c = compare_canonical(*cgal.mesh, rc, other, ro);
  CHECK_FALSE(c.agree());
  CHECK(c.only_a_count == 1);
  CHECK(c.only_b_count == 0);
  REQUIRE(c.only_a.size() == 1);
  auto last = cgal.mesh->tets.back();
  std::sort(last.begin(), last.end());
  CHECK(c.only_a[0] == std::vector<std::uint32_t>(last.begin(), last.end()));
}
