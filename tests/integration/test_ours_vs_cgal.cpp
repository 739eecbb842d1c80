// Our inserter with the symbolic perturbation builds the same tetrahedralization as
// CGAL's Delaunay_triangulation_3, tet for tet, even on degenerate input: both use
// the Devillers-Teillaud perturbation with the lexicographic order. Without the
// perturbation only the Delaunay complex must agree.
#include <catch2/catch.hpp>

#include "fuzz/families.hpp"
#include "kernel/build.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/peers/cgal_oracle.hpp"

using namespace dtlab;

namespace {

Comparison against_cgal(const std::vector<Point3>& pts, const PredicateSpec& spec) {
  BuildResult ours = build_delaunay(pts, spec);
  REQUIRE_FALSE(ours.failure);
  const CheckReport mine = check_tetrahedralization(ours.mesh, {.duplicates = ours.duplicates});
  REQUIRE(mine.ok());
  OracleRun cgal = cgal_delaunay(pts);
  REQUIRE(cgal.mesh);
  const CheckReport theirs = check_tetrahedralization(*cgal.mesh, {.duplicates = cgal.duplicates});
  REQUIRE(theirs.ok());
  return compare_canonical(ours.mesh, mine, *cgal.mesh, theirs);
}

}  // namespace

TEST_CASE("with sos our tets equal CGAL's on general and degenerate inputs", "[oracle]") {
  for (const char* family : {"uniform", "lattice", "lattice_subset", "cospherical", "cylinder",
                             "coplanar_slabs", "duplicates", "near_degenerate", "moment_curve"}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto pts = fuzz::find_family(family)->generate(300, seed);
      for (const char* backend : {"adaptive", "exact"}) {
        INFO(family << " seed " << seed << " " << backend);
        const Comparison c = against_cgal(pts, PredicateSpec{backend, 0, false, true});
        CHECK(c.tets_equal);
        CHECK(c.agree());
      }
    }
  }
}

TEST_CASE("without sos the Delaunay complex still equals CGAL's", "[oracle]") {
  for (const char* family : {"lattice", "cospherical", "cylinder"}) {
    const auto pts = fuzz::find_family(family)->generate(300, 7);
    INFO(family);
    const Comparison c = against_cgal(pts, PredicateSpec{"adaptive", 0, false, false});
    CHECK(c.complexes_equal);
  }
}
