#include "fracture/cell_weld.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "predicates/vec3.hpp"

namespace dtlab {

namespace {
struct Corner {
  std::uint32_t cell, index;
};

std::uint64_t grid_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  const auto m = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1fffff; };
  return m(x) | m(y) << 21 | m(z) << 42;
}

std::size_t find(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}
}  // namespace

std::size_t weld_shared_corners(ScaledCells& cells, double tolerance) {
  auto& cs = cells.diagram.cells;
  if (cells.vertices.empty()) {
    cells.vertices.resize(cs.size());
    for (std::size_t i = 0; i < cs.size(); ++i) {
      cells.vertices[i].assign(cs[i].vertices.begin(), cs[i].vertices.end());
      cs[i].vertices = cells.vertices[i];
    }
  }
  std::vector<Corner> corners;
  for (std::uint32_t i = 0; i < cs.size(); ++i)
    for (std::uint32_t k = 0; k < cells.vertices[i].size(); ++k) corners.push_back({i, k});
  if (!(tolerance > 0) || corners.empty()) return 0;
  auto at = [&](const Corner& c) -> Point3& { return cells.vertices[c.cell][c.index]; };
  // Grid of cell size `tolerance`: corners that close fall in neighbouring grid cells.
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  auto cell_of = [&](const Point3& p, int axis) {
    return static_cast<std::int64_t>(std::floor((axis == 0 ? p.x : axis == 1 ? p.y : p.z) / tolerance));
  };
  for (std::size_t n = 0; n < corners.size(); ++n) {
    const Point3& p = at(corners[n]);
    grid[grid_key(cell_of(p, 0), cell_of(p, 1), cell_of(p, 2))].push_back(n);
  }
  std::vector<std::size_t> parent(corners.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t n = 0; n < corners.size(); ++n) {
    const Point3& p = at(corners[n]);
    const std::int64_t gx = cell_of(p, 0), gy = cell_of(p, 1), gz = cell_of(p, 2);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(grid_key(gx + dx, gy + dy, gz + dz));
          if (it == grid.end()) continue;
          for (std::size_t m : it->second)
            if (m > n && corners[m].cell != corners[n].cell && norm(at(corners[m]) - p) <= tolerance)
              parent[find(parent, m)] = find(parent, n);
        }
  }
  // Per cluster: the lowest cell's corner, unless one cell has two corners in it.
  std::unordered_map<std::size_t, std::vector<std::size_t>> clusters;
  for (std::size_t n = 0; n < corners.size(); ++n) clusters[find(parent, n)].push_back(n);
  std::size_t moved = 0;
  for (auto& [root, members] : clusters) {
    if (members.size() < 2) continue;
    std::vector<std::uint32_t> owners;
    for (auto n : members) owners.push_back(corners[n].cell);
    std::sort(owners.begin(), owners.end());
    if (std::adjacent_find(owners.begin(), owners.end()) != owners.end()) continue;
    std::size_t best = members[0];
    for (auto n : members)
      if (corners[n].cell < corners[best].cell) best = n;
    const Point3 v = at(corners[best]);
    for (auto n : members) {
      Point3& q = at(corners[n]);
      if (q.x != v.x || q.y != v.y || q.z != v.z) ++moved, q = v;
    }
  }
  return moved;
}

}  // namespace dtlab
