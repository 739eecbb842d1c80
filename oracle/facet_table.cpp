#include "oracle/facet_table.hpp"

#include <algorithm>

namespace dtlab {
namespace {

// A facet (a, b, c), a < b < c, in the bucket of a: the apex of its tet, with the
// parity of the ascending order relative to the outward one in bit 31.
struct Entry {
  std::uint32_t b, c, apex_parity, ref;
};
constexpr std::uint32_t kOdd = 0x80000000u;

// Sorts (x,y,z) ascending; returns the parity of the permutation (1 = odd).
int sort3(std::array<std::uint32_t, 3>& v) {
  int parity = 0;
  if (v[0] > v[1]) std::swap(v[0], v[1]), parity ^= 1;
  if (v[1] > v[2]) std::swap(v[1], v[2]), parity ^= 1;
  if (v[0] > v[1]) std::swap(v[0], v[1]), parity ^= 1;
  return parity;
}

// The vertex ranges [lo, hi) processed in one pass each, so that one pass holds
// about `budget` entries (a bucket is never split).
std::vector<std::size_t> ranges(const std::vector<std::uint32_t>& count, std::uint64_t budget) {
  std::vector<std::size_t> cut{0};
  std::uint64_t sum = 0;
  for (std::size_t v = 0; v < count.size(); ++v) {
    if (sum > 0 && sum + count[v] > budget) cut.push_back(v), sum = 0;
    sum += count[v];
  }
  cut.push_back(count.size());
  return cut;
}

// Bucket-local sort by (b, c, ref), then groups of equal (b, c).
template <class Group>
void for_each_group(Entry* first, Entry* last, Group&& group) {
  std::sort(first, last, [](const Entry& x, const Entry& y) {
    return x.b != y.b ? x.b < y.b : (x.c != y.c ? x.c < y.c : x.ref < y.ref);
  });
  for (Entry* i = first; i != last;) {
    Entry* j = i + 1;
    while (j != last && j->b == i->b && j->c == i->c) ++j;
    group(i, j);
    i = j;
  }
}

// Smallest and second smallest vertex of a tet, and the slot of the smallest.
struct TwoSmallest {
  std::uint32_t m1, m2;
  int slot1;
};
TwoSmallest two_smallest(const Tet& k) {
  int s = 0;
  for (int i = 1; i < 4; ++i)
    if (k[i] < k[s]) s = i;
  std::uint32_t m2 = UINT32_MAX;
  for (int i = 0; i < 4; ++i)
    if (i != s) m2 = std::min(m2, k[i]);
  return {k[s], m2, s};
}

}  // namespace

FacetTable build_facet_table(std::span<const Tet> tets, std::size_t point_count, const FacetPairVisitor& on_pair) {
  FacetTable out;
  // A facet's smallest vertex is the tet's smallest (the three facets containing it)
  // or, for the facet opposite it, the tet's second smallest.
  std::vector<std::uint32_t> count(point_count, 0);
  for (const Tet& k : tets) {
    const TwoSmallest s = two_smallest(k);
    count[s.m1] += 3;
    ++count[s.m2];
  }
  // About 12 bytes per tet in one pass (an entry is 16 bytes).
  const std::uint64_t budget = std::max<std::uint64_t>(3 * tets.size() / 4, 1u << 20);
  const std::vector<std::size_t> cut = ranges(count, budget);
  std::vector<Entry> entries;
  std::vector<std::uint64_t> off;
  for (std::size_t part = 0; part + 1 < cut.size(); ++part) {
    const std::size_t lo = cut[part], hi = cut[part + 1];
    off.assign(hi - lo + 1, 0);
    for (std::size_t v = lo; v < hi; ++v) off[v - lo + 1] = off[v - lo] + count[v];
    entries.resize(off.back());
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    auto put = [&](std::size_t t, int f) {
      auto v = facet_vertices(tets[t], f);
      const std::uint32_t odd = sort3(v) ? kOdd : 0;
      entries[pos[v[0] - lo]++] = {v[1], v[2], tets[t][f] | odd, static_cast<std::uint32_t>(4 * t + f)};
    };
    for (std::size_t t = 0; t < tets.size(); ++t) {
      const TwoSmallest s = two_smallest(tets[t]);
      if (s.m1 >= lo && s.m1 < hi)
        for (int f = 0; f < 4; ++f)
          if (f != s.slot1) put(t, f);
      if (s.m2 >= lo && s.m2 < hi) put(t, s.slot1);
    }
    for (std::size_t a = lo; a < hi; ++a)
      for_each_group(entries.data() + off[a - lo], entries.data() + off[a - lo + 1], [&](Entry* i, Entry* j) {
        const auto n = j - i;
        if (n == 1) {
          ++out.boundary;
          out.boundary_refs.push_back(i->ref);
        } else if (n == 2) {
          ++out.interior;
          const Entry& x = *i;
          const Entry& y = *(i + 1);
          if ((x.apex_parity & kOdd) == (y.apex_parity & kOdd)) out.same_side.emplace_back(x.ref, y.ref);
          if (on_pair)
            on_pair({x.ref, y.ref, {static_cast<std::uint32_t>(a), x.b, x.c}, x.apex_parity & ~kOdd,
                     y.apex_parity & ~kOdd, (x.apex_parity & kOdd) != 0});
        } else {
          std::vector<std::uint32_t> refs;
          for (Entry* k = i; k != j; ++k) refs.push_back(k->ref);
          out.overshared.push_back(std::move(refs));
        }
      });
  }
  std::sort(out.boundary_refs.begin(), out.boundary_refs.end());
  return out;
}

std::uint64_t count_edges(std::span<const Tet> tets, std::size_t point_count) {
  // An edge's smallest vertex is the tet's i-th smallest for 3 - i of its edges.
  auto sorted = [](Tet s) {
    auto cs = [&](int i, int j) {
      if (s[i] > s[j]) std::swap(s[i], s[j]);
    };
    cs(0, 1), cs(2, 3), cs(0, 2), cs(1, 3), cs(1, 2);
    return s;
  };
  std::vector<std::uint32_t> count(point_count, 0);
  for (const Tet& k : tets) {
    const Tet s = sorted(k);
    count[s[0]] += 3, count[s[1]] += 2, count[s[2]] += 1;
  }
  const std::vector<std::size_t> cut = ranges(count, std::max<std::uint64_t>(3 * tets.size(), 1u << 20));
  std::vector<std::uint32_t> other;
  std::vector<std::uint64_t> off;
  std::uint64_t edges = 0;
  for (std::size_t part = 0; part + 1 < cut.size(); ++part) {
    const std::size_t lo = cut[part], hi = cut[part + 1];
    off.assign(hi - lo + 1, 0);
    for (std::size_t v = lo; v < hi; ++v) off[v - lo + 1] = off[v - lo] + count[v];
    other.resize(off.back());
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    for (const Tet& k : tets) {
      const Tet s = sorted(k);
      if (s[2] < lo || s[0] >= hi) continue;
      for (int i = 0; i < 3; ++i)
        if (s[i] >= lo && s[i] < hi)
          for (int j = i + 1; j < 4; ++j) other[pos[s[i] - lo]++] = s[j];
    }
    for (std::size_t a = lo; a < hi; ++a) {
      auto first = other.begin() + static_cast<std::ptrdiff_t>(off[a - lo]);
      auto last = other.begin() + static_cast<std::ptrdiff_t>(off[a - lo + 1]);
      std::sort(first, last);
      edges += static_cast<std::uint64_t>(std::unique(first, last) - first);
    }
  }
  return edges;
}

}  // namespace dtlab
