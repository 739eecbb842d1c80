#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <utility>

#include "tests/support/random_points.hpp"
#include "voronoi/cell_arena.hpp"
#include "voronoi/voronoi.hpp"

using namespace dtlab;
using namespace dtlab::vor;

TEST_CASE("cell arena: copies stay in place across blocks, large arrays and moves") {
  CellArena arena;
  std::vector<std::span<const std::uint32_t>> views;
  std::vector<std::uint32_t> a(1000);
  for (std::uint32_t k = 0; k < 600; ++k) {  // ~2.4 MB: several 1 MiB blocks
    std::iota(a.begin(), a.end(), k);
    views.push_back(arena.copy(std::span<const std::uint32_t>(a)));
  }
  std::vector<double> big(300000, 2.5);  // 2.4 MB in one array: a block of its own
  const auto bv = arena.copy(std::span<const double>(big));
  const auto empty = arena.copy(std::span<const double>());
  CHECK(empty.empty());
  CHECK(arena.blocks() >= 3);
  CellArena moved(std::move(arena));
  CHECK(arena.blocks() == 0);
  for (std::uint32_t k = 0; k < views.size(); ++k) {
    REQUIRE(views[k].size() == 1000);
    CHECK(views[k].front() == k);
    CHECK(views[k].back() == k + 999);
    CHECK(reinterpret_cast<std::uintptr_t>(views[k].data()) % alignof(std::uint32_t) == 0);
  }
  CHECK(reinterpret_cast<std::uintptr_t>(bv.data()) % alignof(double) == 0);
  CHECK(std::all_of(bv.begin(), bv.end(), [](double x) { return x == 2.5; }));
}

TEST_CASE("cell views stay valid in moved and copied diagrams") {
  const std::vector<Point3> pts = test::uniform(300, 5, 0, 1);
  VoronoiOptions o;
  o.threads = 2;
  VoronoiDiagram copy;
  {
    VoronoiDiagram vd = compute_voronoi(pts, o);
    const double v0 = vd.cells[7].volume;
    const Point3 p0 = vd.cells[7].vertices[0];
    copy = vd;
    VoronoiDiagram moved = std::move(vd);
    CHECK(moved.cells[7].vertices[0] == p0);
    CHECK(moved.cells[7].volume == v0);
  }
  // The originals are gone; the copy shares their storage.
  double sum = 0;
  for (const auto& c : copy.cells) {
    REQUIRE(c.face_offsets.size() == c.face_count() + 1);
    REQUIRE(c.face_offsets.back() == c.face_vertices.size());
    for (auto v : c.face_vertices) REQUIRE(v < c.vertices.size());
    sum += c.volume;
  }
  CHECK(sum == Approx(copy.box.volume()).epsilon(1e-12));
}
