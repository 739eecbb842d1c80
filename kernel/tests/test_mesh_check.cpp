// check_combinatorics (kernel/mesh_check.hpp): it passes on the inserter's meshes, and
// each kind of corruption is caught by name. The per-flip check of a build runs only in
// builds with assertions (the clang build of `make test`); the direct calls run everywhere.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "degenerate_families.hpp"
#include "delaunay_check.hpp"
#include "kernel/build.hpp"
#include "kernel/inserter.hpp"
#include "kernel/mesh_check.hpp"
#include "predicates/exact.hpp"
#include "tests/support/random_points.hpp"

using namespace dtlab;

namespace {

// The corner tet o, x, y, z (inputs 0..3), (2,2,2) inserted into it, the infinite vertex 5.
struct SmallMesh {
  std::vector<Point3> pts = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}, {2, 2, 2}, {0, 0, 0}};
  Inserter<ExactPredicates> ins{pts.data(), ExactPredicates{}, 5, 1};
  SmallMesh() {
    ins.start(1, 0, 2, 3);  // orient3d(x, o, y, z) > 0
    REQUIRE(ins.insert(4) == Inserter<ExactPredicates>::Outcome::inserted);
  }
  std::string check(const TetMesh& m, bool all_positive = true) {
    return check_combinatorics(m, ins.geometry(), 6, all_positive);
  }
};

// The first live finite tet of m (no vertex 5).
std::uint32_t finite_tet(const TetMesh& m) {
  for (std::uint32_t t = 0; t < m.size(); ++t)
    if (!m.dead(t) && m.index_of(t, 5) < 0) return t;
  FAIL("no finite tet");
  return kNone;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("check_combinatorics passes on the inserter's mesh", "[mesh_check]") {
  SmallMesh s;
  CHECK(s.ins.mesh().live() == 8);  // 4 finite tets, 4 infinite
  CHECK(s.check(s.ins.mesh()) == "");
}

TEST_CASE("check_combinatorics catches a corrupted mesh", "[mesh_check]") {
  SmallMesh s;
  TetMesh& m = s.ins.mesh();  // rebuilt for each SECTION
  const std::uint32_t t = finite_tet(m);
  TetRecord& r = m.records()[t];

  SECTION("one-sided adjacency") {
    r.adj[0] = r.adj[1];
    CHECK(contains(s.check(m), "adjacency not symmetric"));
  }
  SECTION("a neighbour across other vertices") {
    const Facet a = r.adj[0], b = r.adj[1];  // swapped, and their mirrors with them
    r.adj[0] = b, r.adj[1] = a;
    m.records()[a.tet()].adj[a.face()] = Facet(t, 1);
    m.records()[b.tet()].adj[b.face()] = Facet(t, 0);
    CHECK(contains(s.check(m), "across other vertices"));
  }
  SECTION("a vertex twice") {
    r.v[1] = r.v[0];
    CHECK(contains(s.check(m), "twice"));
  }
  SECTION("a vertex that is no point") {
    r.v[2] = 17;
    CHECK(contains(s.check(m), "is no point"));
  }
  SECTION("a dead neighbour") {
    m.destroy(r.adj[0].tet());
    CHECK(contains(s.check(m), "is not a live tet"));
  }
  SECTION("a missing neighbour with an infinite vertex") {
    const Facet a = r.adj[3];
    r.adj[3] = kNoFacet;
    m.records()[a.tet()].adj[a.face()] = kNoFacet;
    CHECK(contains(s.check(m), "no neighbour"));
  }
  SECTION("a negative tet with consistent adjacency") {
    // Swapping two vertices and their facets keeps every adjacency valid; only the
    // orientation test sees it.
    const Facet a = r.adj[0], b = r.adj[1];
    std::swap(r.v[0], r.v[1]);
    r.adj[0] = b, r.adj[1] = a;
    m.records()[a.tet()].adj[a.face()] = Facet(t, 1);
    m.records()[b.tet()].adj[b.face()] = Facet(t, 0);
    CHECK(contains(s.check(m), "negatively oriented"));
  }
}

TEST_CASE("check_combinatorics: a facet of three tets, and flat tets between insertions", "[mesh_check]") {
  // Bigtet-style geometry (no infinite vertex): facets without a neighbour are allowed.
  std::vector<Point3> pts = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}, {4, 4, 0}};
  Geometry<ExactPredicates> geo(pts.data(), ExactPredicates{}, kNone);
  TetMesh m;
  m.create(1, 0, 2, 3);
  CHECK(check_combinatorics(m, geo, 5, true) == "");
  m.create(1, 0, 2, 3);  // the same tet again: each of its facets now has two tets, unlinked
  CHECK(contains(check_combinatorics(m, geo, 5, true), "a facet of 2 tets"));

  TetMesh flat;
  flat.create(0, 1, 2, 4);  // four points of the plane z = 0
  CHECK(check_combinatorics(flat, geo, 5, false) == "");
  CHECK(contains(check_combinatorics(flat, geo, 5, true), "flat"));
}

TEST_CASE("check_combinatorics after every flip: degenerate families and uniform points", "[mesh_check]") {
  for (int family = 0; family < 5; ++family)
    for (bool perturb : {false, true}) {
      std::mt19937_64 rng(77 + family);
      const std::vector<Point3> pts = test::degenerate_family(family, 40, rng);
      BuildOptions opt;
      opt.check_combinatorics = true;
      const BuildResult r = build_delaunay(pts, PredicateSpec{"exact", 0, false, perturb}, opt);
      INFO("family " << family << " perturb " << perturb);
      REQUIRE_FALSE(r.failure);
      CHECK(test::validate(r) == "");
      if (kMeshChecksCompiled)
        CHECK(r.stats.mesh_checks >= 2 * (r.stats.inserted - 4));
      else
        CHECK(r.stats.mesh_checks == 0);
    }
  BuildOptions opt;
  opt.check_combinatorics = true;
  const BuildResult r = build_delaunay(test::uniform(300, 5), PredicateSpec{}, opt);
  REQUIRE_FALSE(r.failure);
  const BuildStats& s = r.stats;
  CHECK(s.mesh_checks == (kMeshChecksCompiled ? 2 * s.flips14 + s.flips23 + s.flips32 + s.flips44 : 0));
}
