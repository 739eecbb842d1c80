#include "fracture/islands.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "sampling/triangle_geometry.hpp"
#include "sampling/winding_number.hpp"

namespace dtlab {

namespace {
// Triangles of each component, components joined through shared (undirected) edges.
std::vector<std::vector<std::uint32_t>> edge_components(const TriangleMesh& m) {
  std::vector<std::uint32_t> parent(m.triangles.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<std::uint64_t, std::uint32_t> first;  // edge -> a triangle holding it
  first.reserve(2 * m.triangles.size());
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      auto [it, fresh] = first.emplace(key, t);
      if (!fresh) parent[find(t)] = find(it->second);
    }
  std::unordered_map<std::uint32_t, std::size_t> index;
  std::vector<std::vector<std::uint32_t>> comps;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    auto [it, fresh] = index.emplace(find(t), comps.size());
    if (fresh) comps.emplace_back();
    comps[it->second].push_back(t);
  }
  return comps;
}

// The triangles `tris` of `piece` as a piece of their own (vertices renumbered).
PieceMesh sub_piece(const PieceMesh& piece, const std::vector<std::uint32_t>& tris) {
  PieceMesh out;
  out.boolean_skipped = piece.boolean_skipped;
  std::unordered_map<std::uint32_t, std::uint32_t> renum;
  for (auto t : tris) {
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = piece.mesh.triangles[t][k];
      auto [it, fresh] = renum.emplace(v, static_cast<std::uint32_t>(out.mesh.vertices.size()));
      if (fresh) out.mesh.vertices.push_back(piece.mesh.vertices[v]);
      tri[k] = it->second;
    }
    out.mesh.triangles.push_back(tri);
    out.cut.push_back(piece.cut[t]);
    out.cut_tag.push_back(piece.cut_tag[t]);
  }
  return out;
}

// Each component's shell index: itself for a positive shell, the smallest positive
// shell enclosing it for a cavity (the largest shell if none seems to).
std::vector<std::size_t> shell_of(const std::vector<PieceMesh>& comps, const std::vector<double>& vol) {
  std::vector<std::size_t> shell(comps.size());
  std::size_t largest = 0;
  for (std::size_t c = 0; c < comps.size(); ++c)
    if (vol[c] > vol[largest]) largest = c;
  for (std::size_t c = 0; c < comps.size(); ++c) {
    shell[c] = c;
    if (vol[c] > 0) continue;
    shell[c] = largest;
    double best = std::numeric_limits<double>::infinity();
    const Point3& q = comps[c].mesh.vertices[0];
    for (std::size_t s = 0; s < comps.size(); ++s)
      if (vol[s] > 0 && vol[s] < best && winding_number_exact(comps[s].mesh, q) > 0.5) best = vol[s], shell[c] = s;
  }
  return shell;
}
}  // namespace

std::vector<PieceMesh> split_islands(const PieceMesh& piece) {
  const auto comps = edge_components(piece.mesh);
  if (comps.size() <= 1) return {piece};
  std::vector<PieceMesh> parts;
  std::vector<double> vol;
  for (const auto& tris : comps) {
    parts.push_back(sub_piece(piece, tris));
    vol.push_back(signed_volume(parts.back().mesh));
  }
  const std::vector<std::size_t> shell = shell_of(parts, vol);
  std::vector<std::vector<std::uint32_t>> merged(parts.size());
  for (std::size_t c = 0; c < comps.size(); ++c)
    merged[shell[c]].insert(merged[shell[c]].end(), comps[c].begin(), comps[c].end());
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t c = 0; c < comps.size(); ++c)
    if (!merged[c].empty()) order.push_back({-vol[c], c});
  std::sort(order.begin(), order.end());
  std::vector<PieceMesh> out;
  for (const auto& [neg, c] : order) {
    std::sort(merged[c].begin(), merged[c].end());
    out.push_back(sub_piece(piece, merged[c]));
  }
  return out;
}

namespace {
Point3 centroid_of(const TriangleMesh& m, std::size_t t) {
  return (1.0 / 3) * (m.corner(t, 0) + m.corner(t, 1) + m.corner(t, 2));
}

// Squared distance from q to the nearest triangle of `m` tagged `tag`.
double distance2_to_tagged(const PieceMesh& p, std::int32_t tag, const Point3& q) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < p.mesh.triangles.size(); ++t) {
    if (!p.cut[t] || p.cut_tag[t] != tag) continue;
    const Point3 c = closest_on_triangle(q, p.mesh.corner(t, 0), p.mesh.corner(t, 1), p.mesh.corner(t, 2)).point;
    best = std::min(best, norm2(c - q));
  }
  return best;
}
}  // namespace

void retag_to_islands(std::vector<PieceMesh>& islands, const std::vector<IslandRef>& refs, std::size_t sites) {
  std::vector<std::vector<std::int32_t>> by_site(sites);
  for (std::size_t k = 0; k < islands.size(); ++k) by_site[refs[k].site].push_back(static_cast<std::int32_t>(k));
  std::vector<std::vector<std::int32_t>> tags(islands.size());
  for (std::size_t k = 0; k < islands.size(); ++k) {
    const PieceMesh& p = islands[k];
    const auto self = static_cast<std::int32_t>(refs[k].site);
    tags[k] = p.cut_tag;
    for (std::size_t t = 0; t < p.mesh.triangles.size(); ++t) {
      const std::int32_t j = p.cut_tag[t];
      if (!p.cut[t] || j < 0) continue;
      const auto& cand = by_site[static_cast<std::size_t>(j)];
      if (cand.size() <= 1) {
        tags[k][t] = cand.empty() ? -1 : cand[0];
        continue;
      }
      const Point3 q = centroid_of(p.mesh, t);
      double best = std::numeric_limits<double>::infinity();
      for (auto b : cand)
        if (const double d = distance2_to_tagged(islands[b], self, q); d < best) best = d, tags[k][t] = b;
    }
  }
  for (std::size_t k = 0; k < islands.size(); ++k) islands[k].cut_tag = std::move(tags[k]);
}

}  // namespace dtlab
