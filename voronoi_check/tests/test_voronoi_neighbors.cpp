// The relation's tables from the build's adjacency (Tetrahedralization::adjacency) against
// the same tables from the facet table: the same degenerate tets, hull edges and
// neighbour sets, on uniform sites and on degenerate families, from serial and threaded
// builds.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "fuzz/families.hpp"
#include "kernel/build.hpp"
#include "sites.hpp"
#include "voronoi_check/voronoi_neighbors.hpp"

using namespace dtlab;

namespace {

std::shared_ptr<const Tetrahedralization> dt_of(const std::vector<Point3>& sites, bool adjacency,
                                                unsigned threads = 1) {
  BuildOptions bo;
  bo.keep_adjacency = adjacency;
  bo.threads = threads;
  bo.parallel_grain = 1;
  BuildResult r = build_delaunay(sites, PredicateSpec{"adaptive", 0, false, true}, bo);
  REQUIRE(!r.failure);
  return std::make_shared<const Tetrahedralization>(std::move(r.mesh));
}

}  // namespace

TEST_CASE("relation tables: the build's adjacency gives the facet table's answers", "[voronoi_check]") {
  std::vector<std::pair<std::string, std::vector<Point3>>> inputs = {{"uniform", test::random_sites(3000, 5)}};
  for (const char* name : {"lattice", "cospherical", "lattice_subset", "clustered", "near_degenerate", "duplicates"})
    inputs.emplace_back(name, fuzz::find_family(name)->generate(600, 2));
  for (const auto& [name, sites] : inputs) {
    INFO(name);
    for (const unsigned threads : {1u, 3u}) {
      // Built and judged at `threads` (a threaded build's adjacency from its canonical order).
      const auto with = dt_of(sites, true, threads), without = dt_of(sites, false, threads);
      REQUIRE(with->adjacency.size() == 4 * with->tets.size());
      REQUIRE(without->adjacency.empty());
      REQUIRE(with->tets == without->tets);
      const VoronoiNeighbors a(sites, with, threads), b(sites, without, threads);
      CHECK(a.degenerate_tets() == b.degenerate_tets());
      NeighborScratch sa, sb;
      sa.mark.assign(sites.size(), 0), sb.mark.assign(sites.size(), 0);
      std::vector<std::uint32_t> pa, da, pb, db;
      std::size_t differ = 0, hull_differ = 0;
      for (std::uint32_t s = 0; s < sites.size(); ++s) {
        if (a.rep(s) != s) continue;
        a.neighbors(s, pa, da, sa);
        b.neighbors(s, pb, db, sb);
        differ += pa != pb || da != db;
        for (const auto t : pa) hull_differ += a.hull_edge(s, t) != b.hull_edge(s, t);
      }
      CHECK(differ == 0);
      CHECK(hull_differ == 0);
    }
  }
}

TEST_CASE("relation tables: every adjacency entry is the mirror facet", "[voronoi_check]") {
  const auto dt = dt_of(test::random_sites(2000, 9), true);
  std::size_t bad = 0, boundary = 0;
  for (std::size_t r = 0; r < dt->adjacency.size(); ++r) {
    const std::uint32_t m = dt->adjacency[r];
    if (m == 0xFFFFFFFFu) {
      ++boundary;
      continue;
    }
    bad += dt->adjacency[m] != r;  // symmetric
    const Tet &t = dt->tets[r / 4], &u = dt->tets[m / 4];
    // The facets share their three vertices; the apexes are not shared.
    for (int k = 0; k < 4; ++k) {
      if (k == static_cast<int>(r % 4)) continue;
      bad += std::find(u.begin(), u.end(), t[k]) == u.end();
    }
    bad += std::find(t.begin(), t.end(), u[m % 4]) != t.end();
  }
  CHECK(bad == 0);
  CHECK(boundary > 0);
}

TEST_CASE("representatives: the build's duplicates or, with none, every site its own", "[voronoi_check]") {
  for (const char* name : {"uniform", "duplicates", "lattice_subset", "extreme_scale"}) {
    const fuzz::Family* f = fuzz::find_family(name);
    REQUIRE(f);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto sites = f->generate(400, seed);  // "duplicates": repeats, some with 0.0 as -0.0
      std::unique_ptr<VoronoiNeighbors> nb;
      try {
        nb = std::make_unique<VoronoiNeighbors>(sites);
      } catch (const std::invalid_argument&) {
        continue;  // coplanar
      }
      const auto sorted = site_representatives(sites);
      INFO(name << " seed " << seed);
      std::size_t copies = 0;
      for (std::uint32_t i = 0; i < sites.size(); ++i) {
        REQUIRE(nb->rep(i) == sorted[i]);
        copies += sorted[i] != i;
      }
      if (std::string(name) == "duplicates") CHECK(copies > 0);
      if (std::string(name) == "uniform") CHECK(copies == 0);
    }
  }
}
