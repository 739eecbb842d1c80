#include "sampling/mesh_report.hpp"

#include <algorithm>
#include <cmath>

#include "predicates/adaptive.hpp"
#include "predicates/naive.hpp"
#include "sampling/bvh.hpp"
#include "sampling/self_intersection.hpp"

namespace dtlab {

MeshReport analyze_mesh(const TriangleMesh& mesh) {
  MeshReport r;
  r.vertices = mesh.vertices.size();
  r.triangles = mesh.triangles.size();
  // Every directed edge as (min, max, forward?) sorted: uses of one undirected edge
  // become a contiguous run.
  struct HalfEdge {
    std::uint32_t lo, hi;
    bool forward;
    bool operator<(const HalfEdge& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
  };
  std::vector<HalfEdge> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] || norm2(mesh.area_normal(t)) == 0)
      ++r.degenerate_triangles;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = tri[k], v = tri[(k + 1) % 3];
      if (u != v) edges.push_back({std::min(u, v), std::max(u, v), u < v});
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const std::size_t uses = j - i;
    if (uses == 1) ++r.boundary_edges;
    if (uses > 2) ++r.nonmanifold_edges;
    if (uses == 2 && edges[i].forward == edges[i + 1].forward) ++r.misoriented_edges;
    i = j;
  }
  r.manifold = r.nonmanifold_edges == 0;
  r.closed = r.manifold && r.boundary_edges == 0 && !mesh.triangles.empty();
  r.oriented = r.manifold && r.misoriented_edges == 0;
  r.area = surface_area(mesh);
  r.volume = signed_volume(mesh);
  r.box = bounding_box(mesh);
  const Point3 ext = r.box.hi - r.box.lo;
  r.overflow = !std::isfinite(r.area) || !std::isfinite(r.volume) || !std::isfinite(ext.x) ||
               !std::isfinite(ext.y) || !std::isfinite(ext.z);
  const double big = std::max({std::abs(r.box.lo.x), std::abs(r.box.lo.y), std::abs(r.box.lo.z),
                               std::abs(r.box.hi.x), std::abs(r.box.hi.y), std::abs(r.box.hi.z)});
  const Bvh bvh(mesh);
  r.self_intersections = big < 1e60 ? count_self_intersections(bvh, NaivePredicates{})
                                    : count_self_intersections(bvh, AdaptivePredicates{});
  return r;
}

}  // namespace dtlab
