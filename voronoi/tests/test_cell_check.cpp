// The two forms of a cell's incidence (voronoi/cell_check.hpp): the bit sets that
// nearly every cell gets and the compressed rows of the rest give the same closedness
// verdict, defect named, and the same faces per vertex in the same order, on sound
// cells and on cells broken in each way the closedness test names.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "tests/support/random_points.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/voronoi.hpp"

using namespace dtlab;

namespace {

// A cell in arrays of its own, to be broken.
struct OwnedCell {
  std::vector<Point3> vertices;
  std::vector<std::uint32_t> offsets, corners;
  std::vector<std::int32_t> neighbor;
  VoronoiCell view() const { return cell_view(vertices, offsets, corners, neighbor); }
};

OwnedCell own(const VoronoiCell& c) {
  return {{c.vertices.begin(), c.vertices.end()},
          {c.face_offsets.begin(), c.face_offsets.end()},
          {c.face_vertices.begin(), c.face_vertices.end()},
          {c.face_neighbor.begin(), c.face_neighbor.end()}};
}

std::vector<std::uint32_t> faces_at(const CellIncidence& in, std::uint32_t v) {
  std::vector<std::uint32_t> out;
  in.visit_faces(v, [&](std::uint32_t f) {
    out.push_back(f);
    return true;
  });
  return out;
}

// Both forms of c's incidence agree; returns the verdict.
std::string both_forms(const VoronoiCell& c) {
  CellIncidence bits, rows;
  cell_incidence(c, bits);
  cell_rows(c, rows);
  REQUIRE_FALSE(rows.bits);
  const std::string verdict = check_cell_closed(c, rows);
  CHECK(check_cell_closed(c, bits) == verdict);
  for (std::uint32_t v = 0; v < c.vertices.size(); ++v) CHECK(faces_at(bits, v) == faces_at(rows, v));
  return verdict;
}

// Breaks cell `o` in one of several ways (index `how`), as a tool's rounding or bug might.
void mutate(OwnedCell& o, int how, std::mt19937_64& rng) {
  const std::size_t nf = o.neighbor.size();
  const std::size_t f = rng() % nf;
  const auto b = o.offsets[f], e = o.offsets[f + 1];
  switch (how) {
    case 0:  // two corners of a face swapped
      std::swap(o.corners[b], o.corners[b + 1 + rng() % (e - b - 1)]);
      break;
    case 1:  // one face reversed
      std::reverse(o.corners.begin() + b, o.corners.begin() + e);
      break;
    case 2:  // a face dropped
      o.corners.erase(o.corners.begin() + b, o.corners.begin() + e);
      o.offsets.erase(o.offsets.begin() + static_cast<std::ptrdiff_t>(f) + 1);
      for (std::size_t g = f + 1; g < o.offsets.size(); ++g) o.offsets[g] -= e - b;
      o.neighbor.erase(o.neighbor.begin() + static_cast<std::ptrdiff_t>(f));
      break;
    case 3:  // a corner replaced by another vertex of the cell (maybe one already in the face)
      o.corners[b + rng() % (e - b)] = static_cast<std::uint32_t>(rng() % o.vertices.size());
      break;
    case 4:  // a face listed twice
      o.corners.insert(o.corners.end(), o.corners.begin() + b, o.corners.begin() + e);
      o.offsets.push_back(static_cast<std::uint32_t>(o.corners.size()));
      o.neighbor.push_back(o.neighbor[f]);
      break;
    case 5:  // an unused vertex
      o.vertices.push_back(o.vertices[0]);
      break;
    default:  // a face's corner list rotated into another face (an edge from a vertex to itself)
      o.corners[b + 1] = o.corners[b];
      break;
  }
}

}  // namespace

TEST_CASE("cell incidence: the bit sets and the rows agree on sound and broken cells", "[cell_check]") {
  VoronoiOptions vo;
  const VoronoiDiagram vd = compute_voronoi(test::uniform(400, 7), vo);
  std::mt19937_64 rng(11);
  std::size_t broken = 0, sound = 0;
  for (const VoronoiCell& c : vd.cells) {
    if (c.face_count() == 0) continue;
    CHECK(both_forms(c).empty());
    ++sound;
    for (int how = 0; how < 7; ++how) {
      OwnedCell o = own(c);
      mutate(o, how, rng);
      INFO("mutation " << how);
      if (!both_forms(o.view()).empty()) ++broken;
    }
  }
  CHECK(sound == vd.cells.size());
  // Nearly every mutation breaks closedness (not: a corner replaced by itself).
  CHECK(broken > 6 * sound);
}

TEST_CASE("cell incidence: cells beyond 64 vertices or faces use the rows", "[cell_check]") {
  // A prism over a 70-gon: 140 vertices, 72 faces.
  OwnedCell o;
  const int k = 70;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < k; ++i) o.vertices.push_back({std::cos(i * 2 * M_PI / k), std::sin(i * 2 * M_PI / k), 1.0 * z});
  o.offsets.push_back(0);
  for (int i = k - 1; i >= 0; --i) o.corners.push_back(static_cast<std::uint32_t>(i));  // bottom, seen from below
  o.offsets.push_back(static_cast<std::uint32_t>(o.corners.size()));
  for (int i = 0; i < k; ++i) o.corners.push_back(static_cast<std::uint32_t>(k + i));  // top
  o.offsets.push_back(static_cast<std::uint32_t>(o.corners.size()));
  for (int i = 0; i < k; ++i) {
    const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>((i + 1) % k);
    for (auto v : {a, b, b + k, a + k}) o.corners.push_back(v);
    o.offsets.push_back(static_cast<std::uint32_t>(o.corners.size()));
  }
  o.neighbor.assign(k + 2, -1);
  CellIncidence in;
  cell_incidence(o.view(), in);
  CHECK_FALSE(in.bits);
  CHECK(check_cell_closed(o.view(), in).empty());
  std::swap(o.corners[0], o.corners[1]);
  CHECK_FALSE(check_cell_closed(o.view()).empty());
}

namespace {

// check_cell_convex's verdict by its definition, face by face in order: a face of area
// below tol^2 skipped; its tolerance t = tol, or rounded_plane_tolerance(e, R, D, ...) where
// that is larger (R: the face's farthest corner from its first, at most D; D: the
// diagonal of the vertices' box); "non-planar face" when a corner is farther than t from
// the plane, else "not convex" when a vertex lies beyond it by more than t.
struct ConvexVerdict {
  std::string why;
  bool skipped = false, widened = false;
};
ConvexVerdict convex_by_definition(const VoronoiCell& c, double tol, double e) {
  ConvexVerdict out;
  Point3 lo = c.vertices[0], hi = lo;
  for (const auto& v : c.vertices) lo = min3(lo, v), hi = max3(hi, v);
  const double D = norm(hi - lo);
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    const auto b = c.face_offsets[f], end = c.face_offsets[f + 1];
    Point3 n{0, 0, 0}, o = c.vertices[c.face_vertices[b]];
    for (auto k = b + 1; k + 1 < end; ++k)
      n = n + cross(c.vertices[c.face_vertices[k]] - o, c.vertices[c.face_vertices[k + 1]] - o);
    const double area2 = norm(n);
    if (area2 <= tol * tol) {
      out.skipped = true;
      continue;
    }
    double t = tol;
    if (e > 0) {
      double r2 = 0;
      for (auto k = b + 1; k < end; ++k) r2 = std::max(r2, norm2(c.vertices[c.face_vertices[k]] - o));
      const double R = std::min(D, std::sqrt(r2) * (1 + 1e-15));
      const double r = rounded_plane_tolerance(e, R, D, area2, end - b - 2);
      if (r > tol) t = r, out.widened = true;
    }
    n = 1.0 / area2 * n;
    for (auto k = b; k < end; ++k)
      if (std::abs(dot(n, c.vertices[c.face_vertices[k]] - o)) > t) {
        out.why = "non-planar face";
        return out;
      }
    for (const auto& v : c.vertices)
      if (dot(n, v - o) > t) {
        out.why = "not convex";
        return out;
      }
  }
  return out;
}

}  // namespace

TEST_CASE("check_cell_convex names the defect its definition names, tolerances widened as defined", "[cell_check]") {
  VoronoiOptions vo;
  const VoronoiDiagram vd = compute_voronoi(test::uniform(300, 5), vo);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> jitter(0, 1);
  std::size_t named[3] = {0, 0, 0}, widened = 0, kept = 0, skipped = 0;  // named: sound, non-planar, not convex
  for (const VoronoiCell& c : vd.cells) {
    for (int trial = 0; trial < 4; ++trial) {
      OwnedCell o = own(c);
      // One vertex moved by about 1e-3 of the cell, or 0.1 (trial 3; trial 0: none moved).
      const double size = std::cbrt(c.volume);
      if (trial > 0) {
        Point3& v = o.vertices[rng() % o.vertices.size()];
        v = v + (trial == 3 ? 0.1 : 1e-3) * size * Point3{jitter(rng), jitter(rng), jitter(rng)};
      }
      // Vertex errors from none to beyond tol, some near the widening's threshold; a
      // tolerance large enough for some faces to be too small to test.
      for (const double tol : {1e-6 * size, 2e-2 * size})
        for (const double e : {0.0, 1e-15 * size, 1e-9 * size, 4e-8 * size, 1e-7 * size, 3e-7 * size, 1e-5 * size}) {
          const ConvexVerdict want = convex_by_definition(o.view(), tol, e);
          ConvexFindings found;
          CHECK(check_cell_convex(o.view(), {tol, true, e}, &found) == want.why);
          // The findings of the faces up to the one that failed.
          CHECK(found.widened == want.widened);
          CHECK(found.skipped == want.skipped);
          widened += want.widened, kept += !want.widened && e > 0, skipped += want.skipped;
          if (e == 0 && tol < 1e-5 * size) ++named[want.why.empty() ? 0 : want.why == "non-planar face" ? 1 : 2];
        }
    }
  }
  CHECK(named[0] >= vd.cells.size());
  CHECK(named[1] > 0);
  CHECK(named[2] > 0);
  CHECK(widened > 0);
  CHECK(kept > 0);
  CHECK(skipped > 0);
}
