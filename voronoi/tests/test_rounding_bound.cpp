// The rounding bounds of voronoi/rounding_bound.hpp and voronoi/cell_check.hpp: how far
// a cell's volume and a vertex's side of a face plane can move when every vertex moves
// by at most d.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "voronoi/cell_arena.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/convex_cell.hpp"
#include "voronoi/rounding_bound.hpp"

using namespace dtlab;
using namespace dtlab::vor;

namespace {

// A cell's arrays, owned, with a view of them.
struct OwnedCell {
  std::vector<Point3> vertices;
  std::vector<std::uint32_t> offsets, corners;
  std::vector<std::int32_t> neighbors;
  VoronoiCell view() const {
    VoronoiCell c;
    c.vertices = vertices, c.face_offsets = offsets, c.face_vertices = corners, c.face_neighbor = neighbors;
    return c;
  }
};

OwnedCell owned(const ConvexCell& c) {
  return {c.vertices(), {c.face_offsets().begin(), c.face_offsets().end()},
          {c.face_vertices().begin(), c.face_vertices().end()}, {c.face_tags().begin(), c.face_tags().end()}};
}

// The volume as the checker's cell_volume takes it: each face fanned from its first corner.
double fan_volume(const VoronoiCell& c) {
  const Point3 o = c.vertices[0];
  double v = 0;
  for (std::size_t f = 0; f < c.face_count(); ++f)
    for (auto k = c.face_offsets[f] + 1; k + 1 < c.face_offsets[f + 1]; ++k)
      v += det3(c.vertices[c.face_vertices[c.face_offsets[f]]] - o, c.vertices[c.face_vertices[k]] - o,
                c.vertices[c.face_vertices[k + 1]] - o);
  return v / 6;
}

// Every vertex moved by a random vector of length at most d.
OwnedCell moved(const OwnedCell& c, double d, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0, 1);
  OwnedCell out = c;
  for (auto& v : out.vertices) {
    const Point3 dir{g(rng), g(rng), g(rng)};
    v = v + (d * std::cbrt(u(rng)) / norm(dir)) * dir;
  }
  return out;
}

}  // namespace

TEST_CASE("volume_rounding_bound: a unit cube with every corner pushed out by d along its diagonal") {
  ConvexCell box;
  box.reset({{0, 0, 0}, {1, 1, 1}});
  OwnedCell cube = owned(box);
  for (double d : {1e-12, 1e-3, 0.1, 1.0}) {
    OwnedCell grown = cube;
    for (auto& v : grown.vertices) v = v + (d / std::sqrt(3.0)) * (2.0 * v - Point3{1, 1, 1});
    const double change = fan_volume(grown.view()) - fan_volume(cube.view());
    const double s = 1 + 2 * d / std::sqrt(3.0);
    CHECK(change == Approx(s * s * s - 1).epsilon(1e-9));
    const VolumeRoundingBound b = volume_rounding_bound(cube.view(), d);
    CHECK(b.surface == Approx(6));
    INFO("d " << d << ": change " << change << ", bound " << b.volume);
    CHECK(change <= b.volume);
    CHECK(b.volume <= 5 * change);  // within a small factor of this worst-case push
    // From the moved cell's side too (the bound is symmetric).
    CHECK(change <= volume_rounding_bound(grown.view(), d).volume);
  }
}

TEST_CASE("volume_rounding_bound and rounded_plane_tolerance hold for random moves of clipped cells") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int cell = 0; cell < 40; ++cell) {
    // A random convex cell: a box, flat in z for every fourth one, cut by random planes.
    ConvexCell c;
    const double h = cell % 4 == 0 ? 1e-3 : 1;
    c.reset({{-1, -1, -h}, {1, 1, h}});
    for (int k = 0; k < 8; ++k) {
      const Point3 n{u(rng), u(rng), u(rng)};
      c.clip(n, 0.6 * norm(n) * h, k, 1e-12);
    }
    const OwnedCell base = owned(c);
    REQUIRE(check_cell_convex(base.view(), {1e-12}).empty());
    for (double d : {1e-9, 1e-6, 1e-4 * h, 0.05 * h}) {
      const VolumeRoundingBound b = volume_rounding_bound(base.view(), d);
      for (int trial = 0; trial < 20; ++trial) {
        const OwnedCell m = moved(base, d, rng);
        const double change = std::abs(fan_volume(m.view()) - fan_volume(base.view()));
        INFO("cell " << cell << " d " << d << ": change " << change << ", bound " << b.volume);
        CHECK(change <= b.volume);
        // The moved cell is convex within what the move allows for each face's plane.
        CHECK(check_cell_convex(m.view(), {1e-15, true, d}).empty());
      }
    }
  }
}

TEST_CASE("check_cell_convex: a vertex moved beyond what the rounding allows is still not convex") {
  ConvexCell box;
  box.reset({{0, 0, 0}, {1, 1, 1}});
  OwnedCell m = owned(box);
  const double e = 1e-6;
  ConvexFindings found;
  CHECK(check_cell_convex(m.view(), {1e-15, true, e}, &found).empty());
  CHECK(found.widened);
  // One corner pushed out along x by 100 e: beyond 2 e + theta D for the unit faces.
  for (auto& v : m.vertices)
    if (v.x == 1 && v.y == 1 && v.z == 1) v.x += 100 * e;
  CHECK_FALSE(check_cell_convex(m.view(), {1e-15, true, e}).empty());
  // e = 0: the tolerance alone, as before.
  CHECK_FALSE(check_cell_convex(m.view(), {1e-9, true}).empty());
}

TEST_CASE("check_cell: a corner pair rounded to one point passes, a cell left open does not") {
  ConvexCell box;
  box.reset({{0, 0, 0}, {1, 1, 1}});
  // Cut one corner by a plane so close to it that the new triangle's corners lie 1e-7
  // apart: with vertices within e = 1e-6 of their true places they may be one point.
  box.clip({1, 1, 1}, 3 - 1e-7, 99, 1e-15);
  OwnedCell m = owned(box);
  REQUIRE(m.offsets.size() == 8);  // 7 faces
  const double tol = 1e-12, e = 1e-6;
  // Round the three new corners to one point, as doubles near a huge coordinate would.
  const Point3 corner{1, 1, 1};
  for (auto& v : m.vertices)
    if (norm(v - corner) < 1e-6) v = corner;
  CHECK(has_edge_within(m.view(), 0));          // two corners are one point
  CHECK(check_cell(m.view(), tol, e).empty());  // within the rounding
  // Without the floor too: the corner lies on its three faces' planes, the cut face is
  // below tol^2, and a short (here zero) edge alone is no defect.
  CHECK(check_cell(m.view(), tol).empty());
  // A face dropped: not closed under either rule.
  OwnedCell open = owned(box);
  open.offsets.pop_back();
  open.neighbors.pop_back();
  open.corners.resize(open.offsets.back());
  CHECK_FALSE(check_cell(open.view(), tol, e).empty());
  CHECK_FALSE(check_cell(open.view(), tol).empty());
}
