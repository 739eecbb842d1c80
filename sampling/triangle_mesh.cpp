#include "sampling/triangle_mesh.hpp"

#include <algorithm>
#include <map>

namespace dtlab {

Box3 bounding_box(const TriangleMesh& mesh) {
  Box3 b;
  for (const auto& t : mesh.triangles)
    for (auto v : t) b.add(mesh.vertices[v]);
  return b;
}

double surface_area(const TriangleMesh& mesh) {
  double a = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) a += mesh.triangle_area(t);
  return a;
}

double signed_volume(const TriangleMesh& mesh) {
  // Sum of signed tetrahedra (origin shifted to the box centre for accuracy).
  const Point3 o = bounding_box(mesh).center();
  double v = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    v += dot(mesh.corner(t, 0) - o, cross(mesh.corner(t, 1) - o, mesh.corner(t, 2) - o));
  return v / 6.0;
}

std::vector<TriangleMesh> connected_shells(const TriangleMesh& m) {
  std::vector<std::uint32_t> parent(m.triangles.size());
  for (std::uint32_t t = 0; t < parent.size(); ++t) parent[t] = t;
  auto find = [&](std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> first;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto u = m.triangles[t][k], v = m.triangles[t][(k + 1) % 3];
      const auto [it, fresh] = first.emplace(std::minmax(u, v), t);
      if (!fresh) parent[find(t)] = find(it->second);
    }
  std::map<std::uint32_t, std::size_t> index;
  std::vector<TriangleMesh> out;
  std::vector<std::map<std::uint32_t, std::uint32_t>> ids;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    const auto [it, fresh] = index.emplace(find(t), out.size());
    if (fresh) out.emplace_back(), ids.emplace_back();
    TriangleMesh& c = out[it->second];
    auto& id = ids[it->second];
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const auto [jt, added] = id.emplace(m.triangles[t][k], static_cast<std::uint32_t>(c.vertices.size()));
      if (added) c.vertices.push_back(m.vertices[m.triangles[t][k]]);
      tri[k] = jt->second;
    }
    c.triangles.push_back(tri);
  }
  return out;
}


}  // namespace dtlab
