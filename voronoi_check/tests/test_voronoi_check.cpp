// The exact Voronoi checker: our own cells pass, and every mutation of them is caught.
#include <catch2/catch.hpp>

#include "sites.hpp"

#include "voronoi/cell_check.hpp"
#include "voronoi/convex_cell.hpp"
#include "voronoi_check/voronoi_check.hpp"

using namespace dtlab;

namespace {

using test::kBox;
using test::random_sites;

VoronoiDiagram cells_of(const std::vector<Point3>& sites, const vor::Box& box = kBox) {
  VoronoiOptions o;
  o.box = box;
  o.threads = 1;
  return compute_voronoi(sites, o);
}

// Rebuilds the tool cells with `edit` applied to cell k's arrays.
template <class Edit>
ToolCells mutated(const ToolCells& t, std::size_t k, Edit edit) {
  ToolCells out;
  for (std::size_t c = 0; c < t.size(); ++c) {
    const VoronoiCell v = t.cell(c);
    std::int64_t site = t.site(c);
    std::vector<Point3> vs(v.vertices.begin(), v.vertices.end());
    std::vector<std::uint32_t> fo(v.face_offsets.begin(), v.face_offsets.end());
    std::vector<std::uint32_t> fv(v.face_vertices.begin(), v.face_vertices.end());
    std::vector<std::int32_t> fn(v.face_neighbor.begin(), v.face_neighbor.end());
    if (c == k) edit(site, vs, fo, fv, fn);
    out.add_cell(site, vs, fo, fv, fn);
  }
  return out;
}

// A cell with at least one face towards a site, away from the walls.
std::size_t interior_cell(const ToolCells& t) {
  for (std::size_t c = 0; c < t.size(); ++c) {
    const VoronoiCell v = t.cell(c);
    bool wall = false;
    for (auto n : v.face_neighbor) wall |= n < 0;
    if (!wall) return c;
  }
  return 0;
}

}  // namespace

TEST_CASE("our own cells are exact on random sites") {
  const auto sites = random_sites(400, 1);
  const auto vd = cells_of(sites);
  const ToolCells t = tool_cells_of(vd);
  const auto r = check_voronoi(sites, kBox, t);
  INFO(voronoi_counts_text(r));
  CHECK(r.verdict == VoronoiVerdict::exact_topology);
  CHECK(r.topology == Topology::exact);
  CHECK(r.cells == 400);
  CHECK(r.degenerate_edges == 0);
  CHECK(r.max_vertex_ulps < 1e4);
  CHECK(r.volume_error < 1e-12);
  std::uint64_t site_faces = 0;
  for (const auto& c : vd.cells)
    for (auto n : c.face_neighbor) site_faces += n >= 0;
  CHECK(r.voronoi_edges >= site_faces);  // faces outside the box are not required
}

TEST_CASE("our own cells are exact on a cubic lattice, with the zero-area faces told apart") {
  std::vector<Point3> sites;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) sites.push_back({double(i), double(j), double(k)});
  const vor::Box box{{-0.5, -0.5, -0.5}, {4.5, 4.5, 4.5}};
  const auto r = check_voronoi(sites, box, tool_cells_of(cells_of(sites, box)));
  INFO(voronoi_counts_text(r));
  CHECK(r.verdict == VoronoiVerdict::exact_topology);
  // Every site's Voronoi neighbours are its axis neighbours: 6 per interior site.
  CHECK(r.voronoi_edges == 2 * 3 * 4 * 25);
  CHECK(r.degenerate_edges > 0);  // face and cube diagonals of the perturbed DT
}

TEST_CASE("duplicated sites: one cell per set of copies") {
  auto sites = random_sites(100, 2);
  sites.push_back(sites[10]);
  sites.push_back(sites[20]);
  const ToolCells t = tool_cells_of(cells_of(sites));
  auto r = check_voronoi(sites, kBox, t);
  CHECK(r.verdict == VoronoiVerdict::exact_topology);
  CHECK(r.distinct_sites == 100);
  // Both copies losing their cell (what voro++ does) is a missing cell.
  ToolCells lost = t;
  for (std::size_t c = 0; c < lost.size(); ++c)
    if (lost.site(c) == 10) lost.erase(c);
  r = check_voronoi(sites, kBox, lost);
  CHECK(r.count(VoronoiDefect::missing_cell) == 1);
  CHECK(r.verdict == VoronoiVerdict::wrong_topology);
}

TEST_CASE("mutation suite: every mutant is detected") {
  const auto sites = random_sites(300, 3);
  const ToolCells t = tool_cells_of(cells_of(sites));
  const std::size_t k = interior_cell(t);
  REQUIRE(check_voronoi(sites, kBox, t).verdict == VoronoiVerdict::exact_topology);
  using D = VoronoiDefect;

  SECTION("a vertex moved") {
    const auto m = mutated(t, k, [](auto&, auto& vs, auto&, auto&, auto&) { vs[0].x += 1e-3; });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::vertex_off) >= 1);
    CHECK(r.verdict != VoronoiVerdict::exact_topology);
  }
  SECTION("a vertex moved by a few ulps is within tolerance, and measured") {
    const auto m = mutated(t, k, [](auto&, auto& vs, auto&, auto&, auto&) {
      vs[0].x = std::nextafter(std::nextafter(vs[0].x, 2.0), 2.0);
    });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.verdict == VoronoiVerdict::exact_topology);
    CHECK(r.max_vertex_ulps >= 1);
  }
  SECTION("a face dropped") {
    const auto m = mutated(t, k, [](auto&, auto&, auto& fo, auto& fv, auto& fn) {
      const auto n = fo[1];
      fv.erase(fv.begin(), fv.begin() + n);
      fo.erase(fo.begin());
      for (auto& o : fo) o -= n;
      fn.erase(fn.begin());
    });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::missing_face) == 1);
    CHECK(r.count(D::not_convex) == 1);  // no longer closed
    CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  }
  SECTION("two cells swapped") {
    std::int64_t other = -1;
    auto m = mutated(t, k, [&](auto& site, auto&, auto&, auto&, auto&) { other = site; });
    const std::size_t j = (k + 150) % t.size();
    const std::int64_t sj = t.site(j);
    m = mutated(mutated(t, k, [&](auto& site, auto&, auto&, auto&, auto&) { site = sj; }), j,
                [&](auto& site, auto&, auto&, auto&, auto&) { site = other; });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::spurious_face) > 0);
    CHECK(r.count(D::missing_face) > 0);
    CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  }
  SECTION("a neighbour id changed") {
    const auto m = mutated(t, k, [&](auto& site, auto&, auto&, auto&, auto& fn) {
      for (auto& n : fn)
        if (n >= 0) {
          n = static_cast<std::int32_t>((site + 150) % 300);
          break;
        }
    });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::spurious_face) == 1);
    CHECK(r.count(D::missing_face) == 1);
    CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  }
  SECTION("a neighbour id that is no site") {
    const auto m = mutated(t, k, [&](auto&, auto&, auto&, auto&, auto& fn) { fn[0] = 100000; });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::bad_neighbor) == 1);
    CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  }
  SECTION("a cell split in two") {
    const VoronoiCell v = t.cell(k);
    ToolCells m;
    for (std::size_t c = 0; c < t.size(); ++c) {
      const VoronoiCell w = t.cell(c);
      if (c != k) {
        m.add_cell(t.site(c), w.vertices, w.face_offsets, w.face_vertices, w.face_neighbor);
        continue;
      }
      for (double side : {1.0, -1.0}) {
        vor::ConvexCell half;
        half.assign(v.vertices, v.face_offsets, v.face_vertices, v.face_neighbor, sites[t.site(c)]);
        half.clip({side, 0, 0}, 0, static_cast<std::int32_t>(t.site(c)), 1e-15);  // the cut: a face towards itself
        half.translate(sites[t.site(c)]);
        m.add_cell(t.site(c), half.vertices(), half.face_offsets(), half.face_vertices(), half.face_tags());
      }
    }
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::extra_cell) == 1);
    CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  }
  SECTION("a cell dropped") {
    ToolCells m = t;
    m.erase(k);
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::missing_cell) == 1);
    CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  }
  SECTION("a cell scaled (volumes no longer sum to the box)") {
    const auto m = mutated(t, k, [&](auto& site, auto& vs, auto&, auto&, auto&) {
      for (auto& p : vs) p = sites[site] + 0.9 * (p - sites[site]);
    });
    const auto r = check_voronoi(sites, kBox, m);
    CHECK(r.count(D::volume_mismatch) == 1);
    CHECK(r.count(D::vertex_off) > 0);
    CHECK(r.verdict == VoronoiVerdict::volume_mismatch);
  }
}

TEST_CASE("a box far larger than the sites: vertex tolerances of the cells' scale, and of a far vertex's distance") {
  // 200 sites in the unit cube, box +-1e10: 1e-9 of the box diagonal is 35, three hundred
  // times the cells' size; the ulp floor (4 ulps of 1e10) is 7.6e-6.
  const auto sites = random_sites(200, 7);
  const vor::Box huge{{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}};
  const ToolCells t = tool_cells_of(cells_of(sites, huge));
  REQUIRE(check_voronoi(sites, huge, t).verdict == VoronoiVerdict::exact_topology);
  const std::size_t k = interior_cell(t);
  // An interior vertex 1e-3 off: far below the old 35, far above the floor.
  const auto near = mutated(t, k, [](auto&, auto& vs, auto&, auto&, auto&) { vs[0].x += 1e-3; });
  const auto r = check_voronoi(sites, huge, near);
  CHECK(r.count(VoronoiDefect::vertex_off) == 1);
  CHECK(r.verdict == VoronoiVerdict::bad_geometry);
  // A corner on a far wall 1e-3 off along the wall: within 1e-9 of its distance (~1e10).
  std::size_t far_cell = t.size();
  std::size_t far_vertex = 0;
  for (std::size_t c = 0; c < t.size() && far_cell == t.size(); ++c) {
    const VoronoiCell v = t.cell(c);
    for (std::size_t j = 0; j < v.vertices.size(); ++j)
      if (v.vertices[j].x == 1e10 && std::abs(v.vertices[j].y) < 9e9 && std::abs(v.vertices[j].z) < 9e9) {
        far_cell = c, far_vertex = j;
        break;
      }
  }
  REQUIRE(far_cell < t.size());
  const auto far = mutated(t, far_cell, [&](auto&, auto& vs, auto&, auto&, auto&) { vs[far_vertex].y += 1e-3; });
  CHECK(check_voronoi(sites, huge, far).count(VoronoiDefect::vertex_off) == 0);
}

TEST_CASE("coplanar or non-finite sites are refused") {
  std::vector<Point3> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  CHECK_THROWS_AS(check_voronoi(flat, kBox, ToolCells{}), std::invalid_argument);
  auto sites = random_sites(10, 4);
  sites[3].y = NAN;
  CHECK_THROWS_AS(check_voronoi(sites, kBox, ToolCells{}), std::invalid_argument);
  CHECK_THROWS_AS(check_voronoi(random_sites(10, 4), vor::Box{{0, 0, 0}, {0, 1, 1}}, ToolCells{}),
                  std::invalid_argument);
}

TEST_CASE("add_cell names the face of fewer than 3 corners and neighbours not one per face") {
  const std::vector<Point3> vs{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::uint32_t> fv{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  const std::vector<std::int32_t> fn{-1, -2, -3, 4};
  ToolCells t;
  t.add_cell(7, vs, std::vector<std::uint32_t>{0, 3, 6, 9, 12}, fv, fn);
  CHECK(t.size() == 1);
  CHECK_THROWS_WITH(t.add_cell(7, vs, std::vector<std::uint32_t>{0, 3, 5, 9, 12}, fv, fn),
                    "cell of site 7: face 1 has 2 corners (a face needs at least 3)");
  CHECK_THROWS_WITH(t.add_cell(7, vs, std::vector<std::uint32_t>{0, 3, 6, 12}, fv, fn),
                    "cell of site 7: 4 face neighbours for 3 faces (one per face)");
  CHECK_THROWS_WITH(t.add_cell(7, vs, std::vector<std::uint32_t>{0, 6, 3, 9, 12}, fv, fn),
                    "cell of site 7: face offsets do not rise");
  CHECK(t.size() == 1);
}

TEST_CASE("the convexity test's volume is cell_volume's, and is left unset when the test stops early") {
  const auto sites = random_sites(300, 11);
  const auto vd = cells_of(sites);
  const ToolCells t = tool_cells_of(vd);
  double fused_sum = 0, fanned_sum = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const VoronoiCell c = t.view(k);
    ConvexFindings found;
    REQUIRE(check_cell_convex(c, {1e-12, true}, &found).empty());
    const double volume = found.volume, fanned = cell_volume(c);
    CHECK(std::abs(volume - fanned) <= 1e-13 * fanned);
    fused_sum += volume, fanned_sum += fanned;
  }
  CHECK(std::abs(fused_sum - kBox.volume()) <= 1e-12 * kBox.volume());
  CHECK(std::abs(fanned_sum - kBox.volume()) <= 1e-12 * kBox.volume());
  // A vertex pushed far out: not convex, and no volume from a test cut short.
  const ToolCells bent = mutated(t, 0, [](auto&, auto& vs, auto&, auto&, auto&) { vs[0] = 2.0 * vs[0] - vs[1]; });
  ConvexFindings found;
  CHECK_FALSE(check_cell_convex(bent.view(0), {1e-12, true}, &found).empty());
  CHECK(std::isnan(found.volume));
}
