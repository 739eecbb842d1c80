#include "sampling/mesh_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "kernel/ids.hpp"
#include "predicates/adaptive.hpp"
#include "sampling/bvh.hpp"
#include "sampling/merge_vertices.hpp"
#include "sampling/self_intersection.hpp"
#include "sampling/winding_number.hpp"

namespace dtlab {

namespace {
struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

std::string point_text(const Point3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
  return buf;
}

std::string at_text(const std::vector<Point3>& at) {
  if (at.empty()) return "";
  std::string s = ", e.g. at " + point_text(at[0]);
  for (std::size_t i = 1; i < at.size(); ++i) s += ", " + point_text(at[i]);
  return s;
}

std::string count_text(std::uint64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
std::size_t count_nested_shells(const TriangleMesh& mesh) {
  const std::vector<TriangleMesh> shells = connected_shells(mesh);
  if (shells.size() < 2 || shells.size() > 64) return 0;
  const std::vector<char> nested = nested_same_orientation(shells);
  return static_cast<std::size_t>(std::count(nested.begin(), nested.end(), 1));
}

}  // namespace

// Shell j is nested in shell i when a vertex of j has winding number +-1 with respect
// to i (the shells are disjoint); with the same orientation (the signs of their volumes
// agree) it covers its volume a second time.
std::vector<char> nested_same_orientation(const std::vector<TriangleMesh>& shells) {
  std::vector<double> volume;
  for (const auto& c : shells) volume.push_back(signed_volume(c));
  std::vector<char> nested(shells.size(), 0);
  for (std::size_t j = 0; j < shells.size(); ++j)
    for (std::size_t i = 0; i < shells.size() && !nested[j]; ++i)
      nested[j] = i != j && (volume[i] > 0) == (volume[j] > 0) &&
                  std::abs(winding_number_exact(shells[i], shells[j].vertices[0])) > 0.5;
  return nested;
}

bool MeshReport::solid() const {
  return closed && manifold && oriented && self_intersections == 0 && degenerate_triangles == 0 && volume != 0 &&
         measurable() && nested_shells == 0;  // a NaN, infinite or underflowing volume proves nothing
}

bool MeshReport::measurable() const { return magnitude_problem(magnitude, !closed).empty(); }

std::vector<std::string> MeshReport::problems() const {
  std::vector<std::string> p;
  if (triangles == 0) p.push_back("no triangles");
  if (boundary_edges > 0)
    p.push_back("not closed: " + count_text(boundary_edges, "boundary edge", "boundary edges") + " in " +
                count_text(boundary_loops, "boundary loop", "boundary loops") + at_text(boundary_at));
  if (!manifold)
    p.push_back("not manifold: " + count_text(nonmanifold_edges, "edge", "edges") + " in more than two triangles, " +
                count_text(nonmanifold_vertices, "pinched vertex", "pinched vertices") + at_text(nonmanifold_at));
  if (misoriented_edges > 0)
    p.push_back("not oriented: " + count_text(misoriented_edges, "edge", "edges") + " used twice in the same direction" +
                at_text(misoriented_at));
  if (self_intersections > 0)
    p.push_back("self-intersecting: " + count_text(self_intersections, "triangle pair", "triangle pairs") +
                at_text(self_intersection_at));
  if (degenerate_triangles > 0)
    p.push_back(count_text(degenerate_triangles, "degenerate triangle", "degenerate triangles") + at_text(degenerate_at));
  if (const std::string m = magnitude_problem(magnitude, !closed); !m.empty())
    p.push_back(m);
  else if (triangles > 0 && closed && volume == 0)
    p.push_back("encloses no volume");
  if (nested_shells > 0)
    p.push_back(count_text(nested_shells, "shell lies", "shells lie") +
                " inside a shell of the same orientation (an inner shell inside-out, or overlapping solids)");
  if (duplicate_vertices > 0)
    p.push_back(count_text(duplicate_vertices, "duplicate vertex", "duplicate vertices") + " (merged)" +
                at_text(duplicate_at));
  return p;
}

std::string MeshReport::why_not_solid() const {
  std::string s;
  for (const auto& p : problems()) {
    if (p.find("duplicate vert") != std::string::npos) continue;  // merged, not a defect
    s += (s.empty() ? "" : "; ") + p;
  }
  return s;
}

std::string MeshReport::summary() const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%zu vertices, %zu triangles: %s, %s, %s, %llu self-intersecting pairs, %zu boundary loops, "
                "%zu duplicate vertices, %zu degenerate triangles, volume %.9g",
                vertices, triangles, closed ? "closed" : "not closed", manifold ? "manifold" : "not manifold",
                oriented ? "oriented" : "not oriented", static_cast<unsigned long long>(self_intersections),
                boundary_loops, duplicate_vertices, degenerate_triangles, volume);
  return buf;
}

namespace {

// Keeps the first `locations` places of a kind of defect.
void note_at(std::vector<Point3>& at, const Point3& p, std::size_t locations) {
  if (at.size() < locations) at.push_back(p);
}

// Degenerate triangles, boundary, non-manifold and misoriented edges, boundary loops;
// the corners (3t + k) around one vertex joined across edges shared by exactly two
// triangles (one fan per vertex on a manifold).
UnionFind edge_topology(const TriangleMesh& mesh, const AdaptivePredicates& pred, std::size_t locations,
                        MeshReport& r) {
  auto note = [&](std::vector<Point3>& at, const Point3& p) { note_at(at, p, locations); };
  auto mid = [&](std::uint32_t a, std::uint32_t b) { return 0.5 * (mesh.vertices[a] + mesh.vertices[b]); };
  // Every directed edge as (min, max, forward?, triangle) sorted: the uses of one
  // undirected edge become a contiguous run.
  struct HalfEdge {
    std::uint32_t lo, hi;
    bool forward;
    std::uint32_t tri;
    bool operator<(const HalfEdge& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
  };
  std::vector<HalfEdge> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const bool repeated = tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
    if (repeated || detail::collinear(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2), pred)) {
      ++r.degenerate_triangles;
      note(r.degenerate_at, (1.0 / 3) * (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)));
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = tri[k], v = tri[(k + 1) % 3];
      if (u != v) edges.push_back({std::min(u, v), std::max(u, v), u < v, static_cast<std::uint32_t>(t)});
    }
  }
  std::sort(edges.begin(), edges.end());
  // Corners (3t + k) around one vertex joined across edges shared by exactly two
  // triangles: one fan per vertex on a manifold.
  UnionFind corners(3 * mesh.triangles.size());
  UnionFind boundary(mesh.vertices.size());
  std::vector<char> on_boundary(mesh.vertices.size(), 0);
  auto corner_of = [&](std::uint32_t t, std::uint32_t v) {
    const auto& tri = mesh.triangles[t];
    return 3 * t + (tri[0] == v ? 0u : tri[1] == v ? 1u : 2u);
  };
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const std::size_t uses = j - i;
    const std::uint32_t a = edges[i].lo, b = edges[i].hi;
    if (uses == 1) {
      ++r.boundary_edges;
      note(r.boundary_at, mid(a, b));
      boundary.unite(a, b);
      on_boundary[a] = on_boundary[b] = 1;
    }
    if (uses > 2) {
      ++r.nonmanifold_edges;
      note(r.nonmanifold_at, mid(a, b));
    }
    if (uses == 2) {
      if (edges[i].forward == edges[i + 1].forward) {
        ++r.misoriented_edges;
        note(r.misoriented_at, mid(a, b));
      }
      const std::uint32_t s = edges[i].tri, t = edges[i + 1].tri;
      corners.unite(corner_of(s, a), corner_of(t, a));
      corners.unite(corner_of(s, b), corner_of(t, b));
    }
    i = j;
  }
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v)
    if (on_boundary[v] && boundary.find(v) == v) ++r.boundary_loops;
  return corners;
}

// Pinched vertices: more than one fan of corners around them.
void count_pinched_vertices(const TriangleMesh& mesh, UnionFind& corners, std::size_t locations, MeshReport& r) {
  auto note = [&](std::vector<Point3>& at, const Point3& p) { note_at(at, p, locations); };
  // Fans: distinct corner roots per vertex.
  std::vector<std::uint32_t> fan_root(mesh.vertices.size(), kNone);
  std::vector<char> pinched(mesh.vertices.size(), 0);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t v = tri[k], root = corners.find(3 * t + k);
      if (fan_root[v] == kNone) fan_root[v] = root;
      else if (fan_root[v] != root && !pinched[v]) {
        pinched[v] = 1;
        ++r.nonmanifold_vertices;
        note(r.nonmanifold_at, mesh.vertices[v]);
      }
    }
  }
}

// Closed, manifold and oriented from the counts; area, volume, box, overflow; the
// self-intersecting pairs (up to `limit`) and, for a clean closed mesh, nested shells.
void measure_geometry(const TriangleMesh& mesh, const AdaptivePredicates& pred, std::size_t locations,
                      std::uint64_t self_intersection_limit, MeshReport& r) {
  auto note = [&](std::vector<Point3>& at, const Point3& p) { note_at(at, p, locations); };
  r.manifold = r.nonmanifold_edges == 0 && r.nonmanifold_vertices == 0;
  r.closed = r.boundary_edges == 0 && r.nonmanifold_edges == 0 && !mesh.triangles.empty();
  r.oriented = r.misoriented_edges == 0 && r.nonmanifold_edges == 0;
  r.area = surface_area(mesh);
  r.volume = signed_volume(mesh);
  r.box = bounding_box(mesh);
  r.magnitude = measure_magnitude(mesh, r.area, r.volume);
  const Bvh bvh(mesh);
  const std::uint64_t limit = self_intersection_limit == 0 ? UINT64_MAX : self_intersection_limit;
  bvh.for_each_overlapping_pair([&](std::uint32_t s, std::uint32_t t) {
    if (r.self_intersections >= limit || !triangles_intersect(mesh, s, t, pred)) return;
    ++r.self_intersections;
    note(r.self_intersection_at, (1.0 / 3) * (mesh.corner(s, 0) + mesh.corner(s, 1) + mesh.corner(s, 2)));
  });
  if (r.closed && r.oriented && r.self_intersections == 0 && r.measurable())
    r.nested_shells = count_nested_shells(mesh);
}

}  // namespace

MeshReport analyze_mesh(const TriangleMesh& input, std::size_t locations, std::uint64_t self_intersection_limit) {
  MeshReport r;
  r.vertices = input.vertices.size();
  r.triangles = input.triangles.size();
  MergedMesh merged = merge_duplicate_vertices(input, locations);
  r.duplicate_vertices = merged.duplicates;
  r.duplicate_at = std::move(merged.duplicate_at);
  const TriangleMesh& mesh = merged.mesh;
  const AdaptivePredicates pred;
  UnionFind corners = edge_topology(mesh, pred, locations, r);
  count_pinched_vertices(mesh, corners, locations, r);
  measure_geometry(mesh, pred, locations, self_intersection_limit, r);
  return r;
}

}  // namespace dtlab
