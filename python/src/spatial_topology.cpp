#include "python/src/spatial_topology.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "kernel/spatial_order.hpp"
#include "oracle/check/facet_table.hpp"
#include "predicates/adaptive.hpp"

namespace dtlab::python {
namespace {

std::uint64_t next_random(std::uint64_t& s) {  // xorshift64: the walk's facet order
  s ^= s << 13;
  s ^= s >> 7;
  s ^= s << 17;
  return s;
}

// Union-find over the elements, joined where same(e, j) holds for neighbour nb[e][j];
// the components are numbered in order of their first element.
template <std::size_t K, class Same>
std::vector<std::int32_t> merge_neighbours(const std::vector<std::array<std::int32_t, K>>& nb, Same&& same) {
  std::vector<std::int32_t> parent(nb.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::int32_t e) {
    while (parent[e] != e) e = parent[e] = parent[parent[e]];
    return e;
  };
  for (std::size_t e = 0; e < nb.size(); ++e)
    for (std::size_t j = 0; j < K; ++j) {
      const std::int32_t o = nb[e][j];
      if (o <= static_cast<std::int32_t>(e) || !same(e, j)) continue;  // each pair once
      const std::int32_t r1 = find(o), r2 = find(static_cast<std::int32_t>(e));
      parent[std::max(r1, r2)] = std::min(r1, r2);
    }
  std::vector<std::int32_t> id(nb.size(), -1), root_id(nb.size(), -1);
  std::int32_t next = 0;
  for (std::size_t e = 0; e < nb.size(); ++e) {
    std::int32_t& r = root_id[find(static_cast<std::int32_t>(e))];
    if (r < 0) r = next++;
    id[e] = r;
  }
  return id;
}

// The tets around edge (a, b) of tet t in cyclic order; `open` when the ring meets the
// hull (the list then runs from one hull side to the other).
struct EdgeRing {
  std::vector<std::int32_t> tets;
  bool open = false;
};

// From `cur`, across the facet opposite one of its two vertices off the edge: the one
// that does not lead back to `prev`.
std::int32_t ring_step(const Tet& k, const std::array<std::int32_t, 4>& n, std::uint32_t a, std::uint32_t b,
                       std::int32_t prev) {
  for (int f = 0; f < 4; ++f)
    if (k[f] != a && k[f] != b && n[f] != prev) return n[f];
  return -1;
}

void walk_ring(std::span<const Tet> tets, const TetNeighbors& nb, std::uint32_t a, std::uint32_t b,
               std::int32_t t, std::int32_t first, EdgeRing& ring) {
  std::int32_t prev = t, cur = first;
  while (cur >= 0 && cur != t) {
    ring.tets.push_back(cur);
    const std::int32_t next = ring_step(tets[cur], nb[cur], a, b, prev);
    prev = cur;
    cur = next;
  }
  if (cur < 0) ring.open = true;
}

EdgeRing edge_ring(std::span<const Tet> tets, const TetNeighbors& nb, std::int32_t t, std::uint32_t a, std::uint32_t b) {
  const Tet& k = tets[t];
  int off[2], m = 0;
  for (int f = 0; f < 4; ++f)
    if (k[f] != a && k[f] != b) off[m++] = f;
  EdgeRing ring;
  ring.tets.push_back(t);
  walk_ring(tets, nb, a, b, t, nb[t][off[0]], ring);
  if (ring.open) {  // the other way round from t, prepended in reverse
    EdgeRing back;
    walk_ring(tets, nb, a, b, t, nb[t][off[1]], back);
    ring.tets.insert(ring.tets.begin(), back.tets.rbegin(), back.tets.rend());
  }
  return ring;
}

// The ring's Voronoi vertices: consecutive repeats (one cospherical cell) collapsed,
// -1 first for an open ring; empty when the edge bounds no ridge.
std::vector<std::int32_t> ridge_of(const EdgeRing& ring, std::span<const std::int32_t> group) {
  std::vector<std::int32_t> v;
  if (ring.open) v.push_back(-1);
  for (const std::int32_t t : ring.tets)
    if (v.empty() || v.back() != group[t]) v.push_back(group[t]);
  if (!ring.open)
    while (v.size() > 1 && v.back() == v.front()) v.pop_back();
  if (v.size() < 3) v.clear();  // Qhull's rule too: one finite vertex and infinity is no ridge
  return v;
}

}  // namespace

TetNeighbors tet_neighbors(std::span<const Tet> tets, std::size_t point_count) {
  TetNeighbors nb(tets.size(), {-1, -1, -1, -1});
  const std::vector<std::uint32_t> rank = first_appearance(tets, point_count);
  build_facet_table(tets, rank, [&](const FacetPair& p) {
    nb[p.r1 >> 2][p.r1 & 3] = static_cast<std::int32_t>(p.r2 >> 2);
    nb[p.r2 >> 2][p.r2 & 3] = static_cast<std::int32_t>(p.r1 >> 2);
  });
  return nb;
}

std::int32_t locate_point(std::span<const Point3> pts, std::span<const Tet> tets, const TetNeighbors& nb,
                          const Point3& q, std::int32_t start, std::uint64_t& rng) {
  const AdaptivePredicates pred;
  auto beyond = [&](const Tet& k, int f) {  // q strictly on the far side of facet f
    std::array<Point3, 4> p{pts[k[0]], pts[k[1]], pts[k[2]], pts[k[3]]};
    p[f] = q;
    return pred.orient3d(p[0], p[1], p[2], p[3]) < 0;
  };
  if (tets.empty()) return -1;
  std::int32_t t = start >= 0 && static_cast<std::size_t>(start) < tets.size() ? start : 0;
  // Exact signs on a Delaunay mesh: the visibility walk cannot cycle; the bound only guards.
  for (std::size_t step = 0; step < 4 * tets.size() + 1000; ++step) {
    const int first = static_cast<int>(next_random(rng) & 3);
    int leave = -1;
    for (int i = 0; i < 4 && leave < 0; ++i)
      if (beyond(tets[t], (first + i) & 3)) leave = (first + i) & 3;
    if (leave < 0) return t;
    t = nb[t][leave];
    if (t < 0) return -1;  // beyond a hull facet: the hull is convex, q is outside
  }
  for (std::size_t s = 0; s < tets.size(); ++s)
    if (!beyond(tets[s], 0) && !beyond(tets[s], 1) && !beyond(tets[s], 2) && !beyond(tets[s], 3))
      return static_cast<std::int32_t>(s);
  return -1;
}

std::vector<std::int32_t> locate_points(std::span<const Point3> pts, std::span<const Tet> tets,
                                        const TetNeighbors& nb, std::span<const Point3> queries) {
  Point3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Point3& q : queries) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  constexpr int kBits = 10;
  auto cell = [&](double v, double l, double h) {  // grid coordinate in [0, 2^kBits)
    const double t = h > l ? (v - l) / (h - l) : 0.0;
    return static_cast<std::uint32_t>(std::clamp(t * (1 << kBits), 0.0, (1 << kBits) - 1.0));
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Point3& q = queries[i];
    order[i] = {hilbert_index(cell(q.x, lo.x, hi.x), cell(q.y, lo.y, hi.y), cell(q.z, lo.z, hi.z), kBits),
                static_cast<std::uint32_t>(i)};
  }
  std::sort(order.begin(), order.end());
  std::vector<std::int32_t> out(queries.size());
  std::uint64_t rng = 0x9e3779b97f4a7c15ull;
  std::int32_t last = 0;
  for (const auto& [key, i] : order) {
    out[i] = locate_point(pts, tets, nb, queries[i], last, rng);
    if (out[i] >= 0) last = out[i];
  }
  return out;
}

std::vector<std::int32_t> cospherical_groups(std::span<const Point3> pts, std::span<const Tet> tets,
                                             const TetNeighbors& nb) {
  const AdaptivePredicates pred;
  return merge_neighbours(nb, [&](std::size_t t, std::size_t f) {
    const std::int32_t o = nb[t][f];
    const Tet& k = tets[t];
    std::uint32_t apex = 0;
    for (int j = 0; j < 4; ++j)
      if (nb[o][j] == static_cast<std::int32_t>(t)) apex = tets[o][j];
    return pred.insphere(pts[k[0]], pts[k[1]], pts[k[2]], pts[k[3]], pts[apex]) == 0;
  });
}

std::vector<std::int32_t> coplanar_groups(std::span<const Point3> pts,
                                          std::span<const std::array<std::uint32_t, 3>> tris,
                                          const std::vector<std::array<std::int32_t, 3>>& tnb) {
  const AdaptivePredicates pred;
  return merge_neighbours(tnb, [&](std::size_t i, std::size_t j) {
    const auto& t = tris[i];
    const auto& o = tris[tnb[i][j]];
    std::uint32_t apex = o[0];
    for (const std::uint32_t v : o)
      if (v != t[0] && v != t[1] && v != t[2]) apex = v;
    return pred.orient3d(pts[t[0]], pts[t[1]], pts[t[2]], pts[apex]) == 0;
  });
}

VoronoiRidges voronoi_ridges(std::span<const Tet> tets, const TetNeighbors& nb, std::span<const std::int32_t> group) {
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  VoronoiRidges out;
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (const auto& e : kEdges) {
      const std::uint32_t a = tets[t][e[0]], b = tets[t][e[1]];
      const EdgeRing ring = edge_ring(tets, nb, static_cast<std::int32_t>(t), a, b);
      // Each edge once: from the lowest-numbered tet of its ring.
      if (*std::min_element(ring.tets.begin(), ring.tets.end()) != static_cast<std::int32_t>(t)) continue;
      const std::vector<std::int32_t> v = ridge_of(ring, group);
      if (v.empty()) continue;
      out.points.push_back({std::min(a, b), std::max(a, b)});
      out.vertices.insert(out.vertices.end(), v.begin(), v.end());
      out.offsets.push_back(static_cast<std::int64_t>(out.vertices.size()));
    }
  return out;
}

}  // namespace dtlab::python
