// The inserter on inputs built to hit every degenerate case of the flips: points on
// facets and edges, flat tets, config 4-4, cospherical and cocircular sets, points
// on hull planes and hull edges. Every result is validated with exact predicates.
#include <catch2/catch.hpp>

#include "degenerate_families.hpp"
#include "delaunay_check.hpp"
#include "kernel/build.hpp"

using namespace dtlab;

TEST_CASE("degenerate families give valid Delaunay tetrahedralizations with exact predicates") {
  int built = 0;
  for (int family = 0; family < 5; ++family)
    for (int c = 0; c < 6; ++c)
      for (bool perturb : {false, true})
        for (auto order : {InsertionOrder::input, InsertionOrder::brio}) {
          std::mt19937_64 rng(1000 * c + family);
          auto pts = test::degenerate_family(family, 30 + 15 * c, rng);
          BuildOptions opt;
          opt.order = order;
          opt.seed = c + 1;
          auto r = build_delaunay(pts, PredicateSpec{"exact", 0, false, perturb}, opt);
          INFO("family " << family << " case " << c << " perturb " << perturb);
          REQUIRE_FALSE(r.failure);
          CHECK(test::validate(r) == "");
          ++built;
        }
  CHECK(built == 120);
}

// The naive backend's builds are judged by the exact checker in
// oracle/peers/tests/test_naive_builds.cpp (the kernel's tests cannot link the checker).
