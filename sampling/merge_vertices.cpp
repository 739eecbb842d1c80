#include "sampling/merge_vertices.hpp"

#include <algorithm>
#include <numeric>

namespace dtlab {

MergedMesh merge_duplicate_vertices(const TriangleMesh& mesh, std::size_t keep_locations) {
  MergedMesh r;
  const std::size_t n = mesh.vertices.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Point3 &p = mesh.vertices[a], &q = mesh.vertices[b];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    if (p.z != q.z) return p.z < q.z;
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  // first[v]: the smallest input index at v's coordinates.
  std::vector<std::uint32_t> first(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    const Point3& p = mesh.vertices[order[i]];
    while (j < n && mesh.vertices[order[j]].x == p.x && mesh.vertices[order[j]].y == p.y &&
           mesh.vertices[order[j]].z == p.z)
      first[order[j++]] = order[i];
    i = j;
  }
  std::vector<std::uint32_t> id(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (first[v] == v) {
      id[v] = static_cast<std::uint32_t>(r.mesh.vertices.size());
      r.mesh.vertices.push_back(mesh.vertices[v]);
      r.original.push_back(v);
    } else {
      id[v] = id[first[v]];
      ++r.duplicates;
      if (r.duplicate_at.size() < keep_locations) r.duplicate_at.push_back(mesh.vertices[v]);
    }
  }
  r.mesh.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) r.mesh.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
  return r;
}

}  // namespace dtlab
