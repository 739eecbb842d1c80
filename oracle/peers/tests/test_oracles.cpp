// CGAL's and TetGen's outputs pass the checker, and the canonical comparison
// finds them equal, on uniform, lattice and exactly cospherical inputs.
#include <catch2/catch.hpp>

#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/check/tests/point_sets.hpp"
#include "oracle/peers/cgal_oracle.hpp"
#include "oracle/peers/tetgen_oracle.hpp"

using namespace dtlab;

namespace {

std::string summary(const CheckReport& r) {
  std::string s;
  for (const auto& d : r.defects) s += std::string(defect_name(d.kind)) + ": " + d.detail + "\n";
  return s;
}

CheckReport checked(const OracleRun& run) {
  INFO(run.name << ": " << run.note);
  REQUIRE(run.mesh);
  const CheckReport r = check_tetrahedralization(*run.mesh, {.duplicates = run.duplicates});
  INFO(run.name << "\n" << summary(r));
  CHECK(r.ok());
  return r;
}

}  // namespace

TEST_CASE("CGAL and TetGen agree with the checker and with each other", "[oracle]") {
  struct Family {
    const char* name;
    std::vector<Point3> points;
    bool general;
  };
  std::vector<Point3> with_dups = test::uniform_points(200, 7);
  with_dups.push_back(with_dups[3]);
  with_dups.push_back(with_dups[10]);
  std::vector<Point3> sphere_center = test::sphere_points(41);
  sphere_center.push_back({0, 0, 0});
  const Family families[] = {
      {"uniform", test::uniform_points(300, 1), true}, {"uniform+duplicates", with_dups, true},
      {"lattice", test::lattice_points(5), false},     {"sphere", test::sphere_points(50), false},
      {"sphere+center", sphere_center, false},
  };
  for (const Family& f : families) {
    INFO(f.name << " (" << f.points.size() << " points)");
    const OracleRun cgal = cgal_delaunay(f.points);
    const OracleRun tetgen = tetgen_delaunay(f.points);
    const CheckReport rc = checked(cgal), rt = checked(tetgen);
    CHECK(rc.stats.vertices + rc.stats.duplicates == f.points.size());
    const Comparison c = compare_canonical(*cgal.mesh, rc, *tetgen.mesh, rt);
    CHECK(c.general_position == f.general);
    CHECK(c.complexes_equal);
    CHECK(c.agree());
    if (f.general) CHECK(c.tets_equal);
  }
}

TEST_CASE("TetGen failures are no answer", "[oracle]") {
  const std::vector<Point3> collinear = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  const OracleRun r = tetgen_delaunay(collinear);
  if (r.mesh)
    CHECK(r.mesh->tets.empty());
  else
    CHECK_FALSE(r.note.empty());
  const OracleRun missing = tetgen_delaunay(collinear, {.binary = "/nonexistent/tetgen"});
  CHECK_FALSE(missing.mesh);
  CHECK_FALSE(missing.note.empty());
}

TEST_CASE("checker passes a 10^5-point CGAL result", "[oracle][slow]") {
  const auto pts = test::uniform_points(100000, 11);
  const CheckReport r = checked(cgal_delaunay(pts));
  CHECK(r.stats.degree_checked);
  CHECK(r.stats.cover_proven);
}
