// The inserter on inputs built to hit every degenerate case of the flips: points on
// facets and edges, flat tets, config 4-4, cospherical and cocircular sets, points
// on hull planes and hull edges. Every result is validated with exact predicates.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "delaunay_check.hpp"
#include "kernel/build.hpp"

using namespace dtlab;

namespace {

std::vector<Point3> degenerate_family(int family, int n, std::mt19937_64& rng) {
  std::vector<Point3> pts;
  std::uniform_int_distribution<int> small(0, 4);
  std::uniform_real_distribution<double> unit(-1, 1);
  switch (family) {
    case 0:  // a random subset of a 5^3 lattice, with repeats
      for (int i = 0; i < n; ++i) pts.push_back({double(small(rng)), double(small(rng)), double(small(rng))});
      break;
    case 1:  // integer points of one sphere
      for (int x = -9; x <= 9; ++x)
        for (int y = -9; y <= 9; ++y)
          for (int z = -9; z <= 9; ++z)
            if (x * x + y * y + z * z == 81) pts.push_back({double(x), double(y), double(z)});
      break;
    case 2:  // three parallel planes
      for (int i = 0; i < n; ++i) pts.push_back({double(small(rng) % 3), unit(rng), unit(rng)});
      break;
    case 3:  // lattice points of a cube's surface: coplanar hull facets everywhere
      for (int i = 0; i < n; ++i) {
        const int face = small(rng) % 6;
        const double a = small(rng), b = small(rng), c = (face & 1) ? 4 : 0;
        pts.push_back(face < 2 ? Point3{c, a, b} : face < 4 ? Point3{a, c, b} : Point3{a, b, c});
      }
      break;
    default:  // two concentric integer spheres
      for (int x = -5; x <= 5; ++x)
        for (int y = -5; y <= 5; ++y)
          for (int z = -5; z <= 5; ++z)
            if (x * x + y * y + z * z == 25 || x * x + y * y + z * z == 9) pts.push_back({double(x), double(y), double(z)});
      std::shuffle(pts.begin(), pts.end(), rng);
  }
  return pts;
}

}  // namespace

TEST_CASE("degenerate families give valid Delaunay tetrahedralizations with exact predicates") {
  int built = 0;
  for (int family = 0; family < 5; ++family)
    for (int c = 0; c < 6; ++c)
      for (bool perturb : {false, true})
        for (auto order : {InsertionOrder::input, InsertionOrder::brio}) {
          std::mt19937_64 rng(1000 * c + family);
          auto pts = degenerate_family(family, 30 + 15 * c, rng);
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
// oracle/tests/test_naive_builds.cpp (the kernel's tests cannot link the checker).
