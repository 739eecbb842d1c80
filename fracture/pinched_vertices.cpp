#include "fracture/pinched_vertices.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "sampling/merge_vertices.hpp"

namespace dtlab {

std::size_t separate_pinched_vertices(TriangleMesh& mesh, double fraction) {
  TriangleMesh m = merge_duplicate_vertices(mesh).mesh;
  const std::size_t nv = m.vertices.size();
  std::vector<std::vector<std::uint32_t>> around(nv);
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) around[m.triangles[t][k]].push_back(t);

  std::size_t separated = 0;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const auto& tris = around[v];
    if (tris.size() < 2) continue;
    // Fans: triangles around v joined across their edges from v.
    std::vector<std::uint32_t> parent(tris.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t a) {
      while (parent[a] != a) a = parent[a] = parent[parent[a]];
      return a;
    };
    std::map<std::uint32_t, std::vector<std::uint32_t>> by_neighbour;  // u -> triangles with edge (v, u)
    for (std::uint32_t i = 0; i < tris.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = m.triangles[tris[i]][k];
        if (u != v) by_neighbour[u].push_back(i);
      }
    bool nonmanifold_edge = false;
    for (const auto& [u, list] : by_neighbour) {
      nonmanifold_edge |= list.size() > 2;
      for (std::size_t j = 1; j < list.size(); ++j) parent[find(list[j])] = find(list[0]);
    }
    if (nonmanifold_edge) continue;
    std::map<std::uint32_t, std::vector<std::uint32_t>> fans;  // root -> positions in tris
    for (std::uint32_t i = 0; i < tris.size(); ++i) fans[find(i)].push_back(i);
    if (fans.size() < 2) continue;
    ++separated;
    const Point3 p = m.vertices[v];
    bool first = true;
    for (const auto& [root, members] : fans) {
      Point3 mean{0, 0, 0};
      double n = 0;
      for (auto i : members)
        for (int k = 0; k < 3; ++k)
          if (m.triangles[tris[i]][k] != v) mean += m.vertices[m.triangles[tris[i]][k]], n += 1;
      const Point3 moved = p + fraction * ((1.0 / n) * mean - p);
      std::uint32_t id = v;
      if (first) {
        m.vertices[v] = moved;
        first = false;
      } else {
        id = static_cast<std::uint32_t>(m.vertices.size());
        m.vertices.push_back(moved);
      }
      for (auto i : members)
        for (auto& c : m.triangles[tris[i]])
          if (c == v) c = id;
    }
  }
  if (separated > 0) mesh = std::move(m);
  return separated;
}

}  // namespace dtlab
