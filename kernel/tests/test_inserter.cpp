#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

#include "delaunay_check.hpp"
#include "kernel/build.hpp"
#include "predicates/exact.hpp"
#include "tests/support/random_points.hpp"

using namespace dtlab;

namespace {

using test::uniform;

std::vector<Point3> lattice(int k) {
  std::vector<Point3> pts;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) pts.push_back({double(x), double(y), double(z)});
  return pts;
}

std::set<std::array<std::uint32_t, 4>> canonical(const Tetrahedralization& t) {
  std::set<std::array<std::uint32_t, 4>> s;
  for (auto k : t.tets) {
    std::sort(k.begin(), k.end());
    s.insert(k);
  }
  return s;
}

// All 4-subsets with an empty circumsphere: the DT of points in general position.
std::set<std::array<std::uint32_t, 4>> brute_force_dt(const std::vector<Point3>& p) {
  ExactPredicates ex;
  std::set<std::array<std::uint32_t, 4>> s;
  const auto n = static_cast<std::uint32_t>(p.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c)
        for (std::uint32_t d = c + 1; d < n; ++d) {
          int o = ex.orient3d(p[a], p[b], p[c], p[d]);
          if (o == 0) continue;
          bool empty = true;
          for (std::uint32_t e = 0; e < n && empty; ++e)
            if (e != a && e != b && e != c && e != d) empty = o * ex.insphere(p[a], p[b], p[c], p[d], p[e]) <= 0;
          if (empty) s.insert({a, b, c, d});
        }
  return s;
}

const PredicateSpec kExactSos{"exact", 0, false, true};
const PredicateSpec kExactRaw{"exact", 0, false, false};

}  // namespace

TEST_CASE("random points: the tet set equals the brute-force Delaunay tetrahedralization") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    auto pts = uniform(25, seed);
    auto expected = brute_force_dt(pts);
    for (auto order : {InsertionOrder::input, InsertionOrder::brio}) {
      BuildOptions opt;
      opt.order = order;
      opt.seed = seed;
      auto r = build_delaunay(pts, kExactSos, opt);
      REQUIRE_FALSE(r.failure);
      CHECK(canonical(r.mesh) == expected);
      auto r2 = build_delaunay(pts, kExactRaw, opt);
      CHECK(canonical(r2.mesh) == expected);
    }
  }
}

TEST_CASE("larger random inputs are valid with exact and with naive predicates") {
  auto pts = uniform(3000, 42);
  auto r = build_delaunay(pts, kExactSos);
  REQUIRE_FALSE(r.failure);
  CHECK(test::validate(r) == "");
  CHECK(r.stats.inserted == pts.size());
  auto n = build_delaunay(pts, PredicateSpec{"naive", 0, false, true});
  REQUIRE_FALSE(n.failure);
  CHECK(canonical(n.mesh) == canonical(r.mesh));
}

TEST_CASE("lattice points (cospherical, coplanar, collinear everywhere) give a valid DT") {
  for (int k : {2, 3, 5}) {
    auto pts = lattice(k);
    for (auto order : {InsertionOrder::input, InsertionOrder::brio}) {
      BuildOptions opt;
      opt.order = order;
      auto r = build_delaunay(pts, kExactSos, opt);
      INFO("k=" << k << " order=" << int(order));
      REQUIRE_FALSE(r.failure);
      CHECK(test::validate(r) == "");
      auto raw = build_delaunay(pts, kExactRaw, opt);
      REQUIRE_FALSE(raw.failure);
      CHECK(test::validate(raw) == "");
    }
  }
}

TEST_CASE("the perturbed DT does not depend on insertion order") {
  auto pts = lattice(4);
  std::set<std::array<std::uint32_t, 4>> first;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    BuildOptions opt;
    opt.seed = seed;
    auto r = build_delaunay(pts, kExactSos, opt);
    REQUIRE_FALSE(r.failure);
    if (seed == 1) first = canonical(r.mesh);
    else CHECK(canonical(r.mesh) == first);
  }
  BuildOptions in;
  in.order = InsertionOrder::input;
  CHECK(canonical(build_delaunay(pts, kExactSos, in).mesh) == first);
}

TEST_CASE("duplicates are not inserted, and are reported by index") {
  std::vector<Point3> pts = uniform(50, 9);
  pts.push_back(pts[3]);
  pts.push_back(pts[10]);
  pts.push_back(pts[3]);
  BuildOptions in;
  in.order = InsertionOrder::input;
  auto r = build_delaunay(pts, kExactSos, in);
  REQUIRE_FALSE(r.failure);
  CHECK(r.duplicates == std::vector<std::uint32_t>{50, 51, 52});
  CHECK(test::validate(r) == "");
}

TEST_CASE("with any insertion order the first occurrence in input order is the vertex") {
  // Copies of a point are reported as duplicates of its first occurrence, as CGAL and
  // TetGen do, even when BRIO inserts a later copy first.
  std::vector<Point3> pts = uniform(400, 4);
  for (int k = 0; k < 400; k += 3) pts.push_back(pts[k]);
  for (int k = 0; k < 400; k += 7) pts.push_back(pts[k]);
  std::vector<std::uint32_t> expected;
  for (std::uint32_t i = 400; i < pts.size(); ++i) expected.push_back(i);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    BuildOptions opt;
    opt.seed = seed;
    auto r = build_delaunay(pts, kExactSos, opt);
    REQUIRE_FALSE(r.failure);
    INFO("seed " << seed);
    CHECK(r.duplicates == expected);
    CHECK(test::validate(r) == "");
  }
}

TEST_CASE("lower-dimensional inputs are a named failure, not a crash") {
  auto fails = [](std::vector<Point3> pts) {
    auto r = build_delaunay(pts, kExactSos);
    return r.failure && r.failure->kind == FailureKind::lower_dimensional && r.mesh.tets.empty();
  };
  CHECK(fails({}));
  CHECK(fails({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  CHECK(fails({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}));
  CHECK(fails({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {0.5, 0.5, 0.5}}));
  CHECK(fails({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {7, 3, 0}}));
}

TEST_CASE("points on the hull planes and outside the current hull") {
  // A cube's corners, face centres and edge midpoints, inserted in input order, so
  // many insertions land on the plane of a hull facet or on a hull edge.
  std::vector<Point3> pts;
  for (double x : {0.0, 0.5, 1.0})
    for (double y : {0.0, 0.5, 1.0})
      for (double z : {0.0, 0.5, 1.0}) pts.push_back({x, y, z});
  std::reverse(pts.begin(), pts.end());
  BuildOptions in;
  in.order = InsertionOrder::input;
  for (auto spec : {kExactSos, kExactRaw}) {
    auto r = build_delaunay(pts, spec, in);
    REQUIRE_FALSE(r.failure);
    CHECK(test::validate(r) == "");
  }
}

TEST_CASE("bigtet boundary: far enough gives the DT, too close loses hull tets") {
  auto pts = uniform(400, 5);
  auto ref = canonical(build_delaunay(pts, kExactSos).mesh);
  BuildOptions far;
  far.boundary = Boundary::bigtet;
  far.bigtet_factor = 1e6;
  auto r = build_delaunay(pts, kExactSos, far);
  REQUIRE_FALSE(r.failure);
  CHECK(canonical(r.mesh) == ref);
  BuildOptions near = far;
  near.bigtet_factor = 1.5;
  auto q = build_delaunay(pts, kExactSos, near);
  REQUIRE_FALSE(q.failure);
  CHECK(q.mesh.tets.size() < ref.size());
}

TEST_CASE("a build that owns its points gives them back in input order, with the same tets") {
  const std::vector<Point3> input = uniform(3000, 11);
  PredicateSpec spec;
  for (const auto boundary : {Boundary::infinite, Boundary::bigtet}) {
    BuildOptions options;
    options.boundary = boundary;
    const BuildResult by_span = build_delaunay(std::span<const Point3>(input), spec, options);
    std::vector<Point3> owned = input;
    const BuildResult by_move = build_delaunay(std::move(owned), spec, options);
    CHECK(by_move.mesh.points == input);
    CHECK(by_span.mesh.points == input);
    CHECK(by_move.mesh.tets == by_span.mesh.tets);
    CHECK(!by_move.mesh.tets.empty());
  }
  // A lower-dimensional input comes back unchanged too.
  std::vector<Point3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}};
  const BuildResult r = build_delaunay(std::vector<Point3>(flat), spec);
  CHECK(r.failure);
  CHECK(r.mesh.points == flat);
}
