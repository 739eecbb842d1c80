#include "oracle/facet_table.hpp"

#include <algorithm>

namespace dtlab {
namespace {

struct Entry {
  std::uint32_t b, c, ref;
};

// Sorts (x,y,z) ascending; returns the parity of the permutation (1 = odd).
int sort3(std::array<std::uint32_t, 3>& v) {
  int parity = 0;
  if (v[0] > v[1]) std::swap(v[0], v[1]), parity ^= 1;
  if (v[1] > v[2]) std::swap(v[1], v[2]), parity ^= 1;
  if (v[0] > v[1]) std::swap(v[0], v[1]), parity ^= 1;
  return parity;
}

// Offsets of a counting sort by key (CSR).
std::vector<std::uint64_t> offsets_from_counts(std::vector<std::uint64_t> counts) {
  std::uint64_t sum = 0;
  for (auto& c : counts) {
    const std::uint64_t n = c;
    c = sum;
    sum += n;
  }
  counts.push_back(sum);
  return counts;
}

}  // namespace

FacetTable build_facet_table(std::span<const Tet> tets, std::size_t point_count) {
  FacetTable out;
  const std::size_t nf = 4 * tets.size();
  out.adj.assign(nf, FacetTable::kBoundary);
  std::vector<std::uint64_t> counts(point_count, 0);
  for (const Tet& k : tets)
    for (int f = 0; f < 4; ++f) {
      auto v = facet_vertices(k, f);
      ++counts[std::min({v[0], v[1], v[2]})];
    }
  std::vector<std::uint64_t> off = offsets_from_counts(std::move(counts));
  std::vector<Entry> entries(nf);
  {
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    for (std::size_t t = 0; t < tets.size(); ++t)
      for (int f = 0; f < 4; ++f) {
        auto v = facet_vertices(tets[t], f);
        sort3(v);
        entries[pos[v[0]]++] = {v[1], v[2], static_cast<std::uint32_t>(4 * t + f)};
      }
  }
  auto parity_of = [&](std::uint32_t ref) {
    auto v = facet_vertices(tets[ref / 4], static_cast<int>(ref % 4));
    return sort3(v);
  };
  for (std::size_t a = 0; a < point_count; ++a) {
    Entry* first = entries.data() + off[a];
    Entry* last = entries.data() + off[a + 1];
    std::sort(first, last, [](const Entry& x, const Entry& y) {
      return x.b != y.b ? x.b < y.b : (x.c != y.c ? x.c < y.c : x.ref < y.ref);
    });
    for (Entry* i = first; i != last;) {
      Entry* j = i + 1;
      while (j != last && j->b == i->b && j->c == i->c) ++j;
      const auto n = j - i;
      if (n == 1) {
        ++out.boundary;
      } else if (n == 2) {
        ++out.interior;
        out.adj[i->ref] = (i + 1)->ref;
        out.adj[(i + 1)->ref] = i->ref;
        if (parity_of(i->ref) == parity_of((i + 1)->ref)) out.same_side.emplace_back(i->ref, (i + 1)->ref);
      } else {
        std::vector<std::uint32_t> refs;
        for (Entry* k = i; k != j; ++k) {
          out.adj[k->ref] = FacetTable::kOvershared;
          refs.push_back(k->ref);
        }
        out.overshared.push_back(std::move(refs));
      }
      i = j;
    }
  }
  return out;
}

std::uint64_t count_edges(std::span<const Tet> tets, std::size_t point_count) {
  static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::vector<std::uint64_t> counts(point_count, 0);
  for (const Tet& k : tets)
    for (const auto& e : kEdge) ++counts[std::min(k[e[0]], k[e[1]])];
  std::vector<std::uint64_t> off = offsets_from_counts(std::move(counts));
  std::vector<std::uint32_t> other(off.back());
  {
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    for (const Tet& k : tets)
      for (const auto& e : kEdge) {
        const auto [lo, hi] = std::minmax(k[e[0]], k[e[1]]);
        other[pos[lo]++] = hi;
      }
  }
  std::uint64_t edges = 0;
  for (std::size_t a = 0; a < point_count; ++a) {
    auto first = other.begin() + static_cast<std::ptrdiff_t>(off[a]);
    auto last = other.begin() + static_cast<std::ptrdiff_t>(off[a + 1]);
    std::sort(first, last);
    edges += static_cast<std::uint64_t>(std::unique(first, last) - first);
  }
  return edges;
}

}  // namespace dtlab
