#include "oracle/check/boundary.hpp"

#include <algorithm>
#include <numeric>

namespace dtlab {
namespace {

std::vector<std::uint64_t> csr_offsets(const std::vector<std::uint32_t>& keys, std::size_t n) {
  std::vector<std::uint64_t> off(n + 1, 0);
  for (auto k : keys) ++off[k + 1];
  for (std::size_t i = 0; i < n; ++i) off[i + 1] += off[i];
  return off;
}

struct HalfEdge {
  std::uint32_t other, facet;
  std::uint8_t edge, reversed;  // reversed: runs from `other` to the bucket's vertex
};

void match_edges(BoundarySurface& s, std::size_t n) {
  const std::size_t nf = s.facets.size();
  std::vector<std::uint32_t> key(3 * nf);
  for (std::size_t i = 0; i < nf; ++i)
    for (int e = 0; e < 3; ++e) key[3 * i + e] = std::min(s.facets[i][e], s.facets[i][(e + 1) % 3]);
  const auto off = csr_offsets(key, n);
  std::vector<HalfEdge> he(3 * nf);
  {
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    for (std::size_t i = 0; i < nf; ++i)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t u = s.facets[i][e], v = s.facets[i][(e + 1) % 3];
        he[pos[std::min(u, v)]++] = {std::max(u, v), static_cast<std::uint32_t>(i), static_cast<std::uint8_t>(e),
                                     static_cast<std::uint8_t>(u > v)};
      }
  }
  s.across.assign(nf, {kNone, kNone, kNone});
  for (std::size_t a = 0; a < n; ++a) {
    auto first = he.begin() + static_cast<std::ptrdiff_t>(off[a]);
    auto last = he.begin() + static_cast<std::ptrdiff_t>(off[a + 1]);
    std::sort(first, last, [](const HalfEdge& x, const HalfEdge& y) {
      return x.other != y.other ? x.other < y.other : x.reversed < y.reversed;
    });
    for (auto i = first; i != last;) {
      auto j = i + 1;
      while (j != last && j->other == i->other) ++j;
      ++s.edges;
      if (j - i == 2 && i->reversed != (i + 1)->reversed) {
        s.across[i->facet][i->edge] = (i + 1)->facet;
        s.across[(i + 1)->facet][(i + 1)->edge] = i->facet;
      } else {
        s.bad_edges.push_back({static_cast<std::uint32_t>(a), i->other});
      }
      i = j;
    }
  }
}

// Each corner (v; x, y) of a facet (v, x, y) contributes the link edge x -> y of v;
// the link of a manifold vertex is a single cycle.
void check_links(BoundarySurface& s, std::size_t n) {
  const std::size_t nf = s.facets.size();
  std::vector<std::uint32_t> key(3 * nf);
  for (std::size_t i = 0; i < nf; ++i)
    for (int c = 0; c < 3; ++c) key[3 * i + c] = s.facets[i][c];
  const auto off = csr_offsets(key, n);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> link(3 * nf);
  {
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    for (std::size_t i = 0; i < nf; ++i)
      for (int c = 0; c < 3; ++c) link[pos[s.facets[i][c]]++] = {s.facets[i][(c + 1) % 3], s.facets[i][(c + 2) % 3]};
  }
  for (std::size_t v = 0; v < n; ++v) {
    auto first = link.begin() + static_cast<std::ptrdiff_t>(off[v]);
    auto last = link.begin() + static_cast<std::ptrdiff_t>(off[v + 1]);
    if (first == last) continue;
    ++s.vertices;
    std::sort(first, last);
    bool ok = std::adjacent_find(first, last, [](auto& x, auto& y) { return x.first == y.first; }) == last;
    if (ok) {
      const std::uint32_t start = first->first;
      std::uint32_t cur = start;
      std::ptrdiff_t steps = 0;
      do {
        auto it = std::lower_bound(first, last, std::make_pair(cur, std::uint32_t{0}));
        if (it == last || it->first != cur) {
          ok = false;
          break;
        }
        cur = it->second;
        ++steps;
      } while (cur != start && steps <= last - first);
      ok = ok && cur == start && steps == last - first;
    }
    if (!ok) s.bad_vertices.push_back(static_cast<std::uint32_t>(v));
  }
}

void label_components(BoundarySurface& s) {
  const std::size_t nf = s.facets.size();
  s.component.assign(nf, kNone);
  std::vector<std::uint32_t> stack;
  for (std::size_t i = 0; i < nf; ++i) {
    if (s.component[i] != kNone) continue;
    const std::uint32_t c = s.components++;
    s.component[i] = c;
    stack.push_back(static_cast<std::uint32_t>(i));
    while (!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      for (std::uint32_t g : s.across[f])
        if (g != kNone && s.component[g] == kNone) {
          s.component[g] = c;
          stack.push_back(g);
        }
    }
  }
}

}  // namespace

BoundarySurface build_boundary(std::span<const Tet> tets, const FacetTable& table, std::size_t point_count) {
  BoundarySurface s;
  s.facets.reserve(table.boundary_refs.size());
  s.tet_of.reserve(table.boundary_refs.size());
  for (const std::uint32_t r : table.boundary_refs) {
    s.facets.push_back(facet_vertices(tets[r / 4], static_cast<int>(r % 4)));
    s.tet_of.push_back(r / 4);
  }
  match_edges(s, point_count);
  check_links(s, point_count);
  label_components(s);
  return s;
}

}  // namespace dtlab
