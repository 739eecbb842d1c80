#include "oracle/check/compare.hpp"

#include <algorithm>
#include <numeric>

namespace dtlab {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// canon[i]: the smallest input index with the coordinates of point i, so that
// producers keeping different copies of a duplicated point compare equal.
std::vector<std::uint32_t> canonical_ids(const std::vector<Point3>& p) {
  std::vector<std::uint32_t> order(p.size()), canon(p.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](auto a, auto b) { return lex_less(p[a], p[b]) || (p[a] == p[b] && a < b); });
  for (std::size_t i = 0; i < order.size(); ++i)
    canon[order[i]] = (i > 0 && p[order[i]] == p[order[i - 1]]) ? canon[order[i - 1]] : order[i];
  return canon;
}

Tetrahedralization canonical(const Tetrahedralization& t) {
  const auto canon = canonical_ids(t.points);
  Tetrahedralization c;
  c.tets = t.tets;
  for (Tet& k : c.tets)
    for (auto& v : k) v = canon[v];
  return c;
}

std::vector<Tet> sorted_tets(const std::vector<Tet>& tets) {
  std::vector<Tet> s = tets;
  for (Tet& k : s) std::sort(k.begin(), k.end());
  std::sort(s.begin(), s.end());
  return s;
}

// Lexicographic order of cells i (of x) and j (of y).
int compare_cells(const Cells& x, std::size_t i, const Cells& y, std::size_t j) {
  const auto* a = x.vertices.data() + x.offsets[i];
  const auto* ae = x.vertices.data() + x.offsets[i + 1];
  const auto* b = y.vertices.data() + y.offsets[j];
  const auto* be = y.vertices.data() + y.offsets[j + 1];
  if (std::lexicographical_compare(a, ae, b, be)) return -1;
  if (std::lexicographical_compare(b, be, a, ae)) return 1;
  return 0;
}

}  // namespace

Cells delaunay_complex(const Tetrahedralization& t, const CheckReport& report) {
  const std::size_t nt = t.tets.size();
  std::vector<std::uint32_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& [a, b] : report.cospherical_pairs) {
    const auto ra = find_root(parent, a), rb = find_root(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  for (std::size_t i = 0; i < nt; ++i) parent[i] = find_root(parent, static_cast<std::uint32_t>(i));
  // Tets grouped by root (a counting sort: roots are tet ids).
  std::vector<std::uint64_t> start(nt + 1, 0);
  for (auto r : parent) ++start[r + 1];
  for (std::size_t i = 0; i < nt; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> order(nt);
  for (std::size_t i = 0; i < nt; ++i) order[start[parent[i]]++] = static_cast<std::uint32_t>(i);
  Cells unsorted;
  unsorted.offsets.push_back(0);
  std::vector<std::uint32_t> verts;
  for (std::size_t i = 0; i < nt;) {
    std::size_t j = i;
    verts.clear();
    while (j < nt && parent[order[j]] == parent[order[i]]) {
      const Tet& k = t.tets[order[j]];
      verts.insert(verts.end(), k.begin(), k.end());
      ++j;
    }
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    unsorted.vertices.insert(unsorted.vertices.end(), verts.begin(), verts.end());
    unsorted.offsets.push_back(unsorted.vertices.size());
    i = j;
  }
  std::vector<std::size_t> idx(unsorted.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::sort(idx.begin(), idx.end(),
            [&](std::size_t x, std::size_t y) { return compare_cells(unsorted, x, unsorted, y) < 0; });
  Cells out;
  out.offsets.push_back(0);
  for (std::size_t i : idx) {
    out.vertices.insert(out.vertices.end(),
                        unsorted.vertices.begin() + static_cast<std::ptrdiff_t>(unsorted.offsets[i]),
                        unsorted.vertices.begin() + static_cast<std::ptrdiff_t>(unsorted.offsets[i + 1]));
    out.offsets.push_back(out.vertices.size());
  }
  return out;
}

Comparison compare_canonical(const Tetrahedralization& a_in, const CheckReport& ra, const Tetrahedralization& b_in,
                             const CheckReport& rb, std::size_t witnesses) {
  const Tetrahedralization a = canonical(a_in), b = canonical(b_in);
  Comparison c;
  c.general_position = ra.cospherical_pairs.empty() && rb.cospherical_pairs.empty();
  const std::vector<Tet> ta = sorted_tets(a.tets), tb = sorted_tets(b.tets);
  c.tets_equal = ta == tb;
  if (c.general_position) {
    // Every cell is a single tet: compare the sorted quadruples directly.
    c.cells_a = ta.size();
    c.cells_b = tb.size();
    std::size_t i = 0, j = 0;
    while (i < ta.size() || j < tb.size()) {
      if (j == tb.size() || (i < ta.size() && ta[i] < tb[j])) {
        if (c.only_a_count++ < witnesses) c.only_a.emplace_back(ta[i].begin(), ta[i].end());
        ++i;
      } else if (i == ta.size() || tb[j] < ta[i]) {
        if (c.only_b_count++ < witnesses) c.only_b.emplace_back(tb[j].begin(), tb[j].end());
        ++j;
      } else {
        ++i, ++j;
      }
    }
    c.complexes_equal = c.only_a_count == 0 && c.only_b_count == 0;
    return c;
  }
  const Cells ca = delaunay_complex(a, ra), cb = delaunay_complex(b, rb);
  c.cells_a = ca.size();
  c.cells_b = cb.size();
  std::size_t i = 0, j = 0;
  while (i < ca.size() || j < cb.size()) {
    const int cmp = i == ca.size() ? 1 : j == cb.size() ? -1 : compare_cells(ca, i, cb, j);
    if (cmp == 0) {
      ++i, ++j;
    } else if (cmp < 0) {
      if (c.only_a_count++ < witnesses) c.only_a.push_back(ca.cell(i));
      ++i;
    } else {
      if (c.only_b_count++ < witnesses) c.only_b.push_back(cb.cell(j));
      ++j;
    }
  }
  c.complexes_equal = c.only_a_count == 0 && c.only_b_count == 0;
  return c;
}

}  // namespace dtlab
