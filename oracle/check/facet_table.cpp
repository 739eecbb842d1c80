#include "oracle/check/facet_table.hpp"

#include <algorithm>
#include <atomic>
#include <memory>

#include "kernel/ids.hpp"
#include "kernel/parallel_for.hpp"

namespace dtlab {
namespace {

// A facet (a, b, c), a < b < c, in the bucket of a: the apex of its tet, with the
// parity of the ascending order relative to the outward one in bit 31.
struct Entry {
  std::uint32_t b, c, apex_parity, ref;
};
constexpr std::uint32_t kOdd = 0x80000000u;

// Sorts (x,y,z) by rank; returns the parity of the permutation (1 = odd).
inline int sort3(std::array<std::uint32_t, 3>& v, std::span<const std::uint32_t> rank) {
  int parity = 0;
  std::array<std::uint32_t, 3> r = {rank[v[0]], rank[v[1]], rank[v[2]]};
  auto cs = [&](int i, int j) {
    if (r[i] > r[j]) std::swap(r[i], r[j]), std::swap(v[i], v[j]), parity ^= 1;
  };
  cs(0, 1), cs(1, 2), cs(0, 1);
  return parity;
}

// The rank ranges [lo, hi) processed in one pass each, so that one pass holds
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

// Which passes need each tet, so that a pass skips the others by reading one byte
// instead of ranking the tet's vertices again: the first and last pass of the tet
// (4 bits each; `lowest_highest(t)` gives the lowest and highest rank whose bucket
// receives something from tet t). Empty when there are more than 16 passes: every
// pass then looks at every tet.
template <class Span>
std::vector<std::uint8_t> passes_of_tets(std::size_t tet_count, const std::vector<std::size_t>& cut,
                                         Span&& lowest_highest) {
  const std::size_t parts = cut.size() - 1;
  if (parts > 16) return {};
  std::vector<std::uint8_t> part_of(cut.back());
  for (std::size_t p = 0; p < parts; ++p)
    std::fill(part_of.begin() + static_cast<std::ptrdiff_t>(cut[p]),
              part_of.begin() + static_cast<std::ptrdiff_t>(cut[p + 1]), static_cast<std::uint8_t>(p));
  std::vector<std::uint8_t> span(tet_count);
  for (std::size_t t = 0; t < tet_count; ++t) {
    const auto [lo, hi] = lowest_highest(t);
    span[t] = static_cast<std::uint8_t>(part_of[lo] << 4 | part_of[hi]);
  }
  return span;
}
inline bool in_pass(const std::vector<std::uint8_t>& span, std::size_t t, std::size_t part) {
  return span.empty() || ((span[t] >> 4) <= part && part <= (span[t] & 15u));
}

// Bucket-local sort by (b, c, ref), then groups of equal (b, c). A bucket holds about
// 27 entries (a vertex's facets in a Delaunay mesh): an insertion sort on the packed
// (b, c) key up to 48 entries, std::sort beyond.
template <class Group>
void for_each_group(Entry* first, Entry* last, Group&& group) {
  const auto key = [](const Entry& x) { return std::uint64_t{x.b} << 32 | x.c; };
  const auto before = [&](const Entry& x, const Entry& y) {
    const std::uint64_t kx = key(x), ky = key(y);
    return kx != ky ? kx < ky : x.ref < y.ref;
  };
  if (last - first <= 48) {
    for (Entry* i = first + 1; i < last; ++i) {
      const Entry e = *i;
      Entry* j = i;
      for (; j != first && before(e, *(j - 1)); --j) *j = *(j - 1);
      *j = e;
    }
  } else {
    std::sort(first, last, before);
  }
  for (Entry* i = first; i != last;) {
    Entry* j = i + 1;
    while (j != last && j->b == i->b && j->c == i->c) ++j;
    group(i, j);
    i = j;
  }
}

// The two lowest ranks of a tet's vertices, and the slot of the lowest.
struct TwoLowest {
  std::uint32_t r0, r1;
  int slot0;
};
inline TwoLowest two_lowest(const Tet& k, std::span<const std::uint32_t> rank) {
  const std::uint32_t a = rank[k[0]], b = rank[k[1]], c = rank[k[2]], d = rank[k[3]];
  const std::uint32_t ab = std::min(a, b), AB = std::max(a, b), cd = std::min(c, d), CD = std::max(c, d);
  const bool left = ab < cd;
  const std::uint32_t r0 = left ? ab : cd, r1 = left ? std::min(AB, cd) : std::min(ab, CD);
  const int slot0 = r0 == a ? 0 : r0 == b ? 1 : r0 == c ? 2 : 3;
  return {r0, r1, slot0};
}

// The ranks of a tet's vertices, ascending.
struct Ranked {
  std::array<std::uint32_t, 4> r;
};
inline Ranked ranked(const Tet& k, std::span<const std::uint32_t> rank) {
  Ranked out{{rank[k[0]], rank[k[1]], rank[k[2]], rank[k[3]]}};
  auto cs = [&](int i, int j) {
    if (out.r[i] > out.r[j]) std::swap(out.r[i], out.r[j]);
  };
  cs(0, 1), cs(2, 3), cs(0, 2), cs(1, 3), cs(1, 2);
  return out;
}

}  // namespace

// Producers store tets in a spatially coherent order (ours and CGAL's do), so
// consecutive tets have nearby ranks even when the vertex ids are in random input
// order: bucketing by rank keeps the counting sort's scattered writes and the point
// loads local.
std::vector<std::uint32_t> first_appearance(std::span<const Tet> tets, std::size_t point_count) {
  std::vector<std::uint32_t> rank(point_count, kNone);
  std::uint32_t next = 0;
  for (const Tet& k : tets)
    for (auto v : k)
      if (rank[v] == kNone) rank[v] = next++;
  return rank;
}

namespace {

// What the workers of one pass find in their buckets, merged in bucket order.
struct PartResult {
  std::vector<std::uint32_t> boundary_refs;
  std::vector<std::vector<std::uint32_t>> overshared;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> same_side;
  std::vector<std::pair<FacetPair, int>> flagged;  // (pair, classify's nonzero code)
  std::uint64_t interior = 0;
};

// Groups the entries of buckets [a0, a1) (ranks, relative offsets `off` from `lo`).
void scan_buckets(std::span<const Tet> tets, std::span<const std::uint32_t> rank, Entry* entries,
                  const std::vector<std::uint64_t>& off, std::size_t lo, std::size_t a0, std::size_t a1,
                  const FacetPairClassifier& classify, PartResult& out) {
  std::array<std::uint32_t, 3> byrank;
  for (std::size_t a = a0; a < a1; ++a) {
    if (off[a - lo] == off[a - lo + 1]) continue;
    // The bucket's vertex: the first vertex of any of its facets, by rank.
    const Entry& any = entries[off[a - lo]];
    byrank = facet_vertices(tets[any.ref / 4], static_cast<int>(any.ref % 4));
    sort3(byrank, rank);
    const std::uint32_t va = byrank[0];
    for_each_group(entries + off[a - lo], entries + off[a - lo + 1], [&](Entry* i, Entry* j) {
      const auto n = j - i;
      if (n == 1) {
        out.boundary_refs.push_back(i->ref);
      } else if (n == 2) {
        ++out.interior;
        const Entry& x = *i;
        const Entry& y = *(i + 1);
        if ((x.apex_parity & kOdd) == (y.apex_parity & kOdd)) out.same_side.emplace_back(x.ref, y.ref);
        if (classify) {
          const FacetPair pair{
              x.ref, y.ref, {va, x.b, x.c}, x.apex_parity & ~kOdd, y.apex_parity & ~kOdd, (x.apex_parity & kOdd) != 0};
          if (const int code = classify(pair)) out.flagged.emplace_back(pair, code);
        }
      } else {
        std::vector<std::uint32_t> refs;
        for (Entry* k = i; k != j; ++k) refs.push_back(k->ref);
        out.overshared.push_back(std::move(refs));
      }
    });
  }
}

// Buckets [lo, hi) cut into about `parts` ranges of similar entry counts.
std::vector<std::size_t> split_buckets(const std::vector<std::uint64_t>& off, std::size_t lo, std::size_t hi,
                                       std::size_t parts) {
  std::vector<std::size_t> cut{lo};
  const std::uint64_t total = off[hi - lo];
  for (std::size_t p = 1; p < parts; ++p) {
    const std::uint64_t want = total * p / parts;
    const auto at = std::lower_bound(off.begin(), off.begin() + static_cast<std::ptrdiff_t>(hi - lo), want);
    cut.push_back(std::max(cut.back(), lo + static_cast<std::size_t>(at - off.begin())));
  }
  cut.push_back(hi);
  return cut;
}

void merge_part(PartResult& part, FacetTable& out, const FacetPairRecorder& record) {
  out.interior += part.interior;
  out.boundary += part.boundary_refs.size();
  out.boundary_refs.insert(out.boundary_refs.end(), part.boundary_refs.begin(), part.boundary_refs.end());
  for (auto& refs : part.overshared) out.overshared.push_back(std::move(refs));
  out.same_side.insert(out.same_side.end(), part.same_side.begin(), part.same_side.end());
  if (record)
    for (const auto& [pair, code] : part.flagged) record(pair, code);
}

}  // namespace

FacetTable build_facet_table(std::span<const Tet> tets, std::span<const std::uint32_t> rank,
                             const FacetPairVisitor& on_pair) {
  if (!on_pair) return build_facet_table(tets, rank, {}, {}, 1);
  return build_facet_table(
      tets, rank, [&](const FacetPair& p) { return on_pair(p), 0; }, {}, 1);
}

FacetTable build_facet_table(std::span<const Tet> tets, std::span<const std::uint32_t> rank,
                             const FacetPairClassifier& classify, const FacetPairRecorder& record, unsigned threads) {
  FacetTable out;
  const std::size_t point_count = rank.size();
  // Buckets by the facet's lowest-ranked vertex: the tet's lowest (the three facets
  // containing it) or, for the facet opposite it, the tet's second lowest.
  std::vector<std::uint32_t> count(point_count, 0);
  for (const Tet& k : tets) {
    const TwoLowest s = two_lowest(k, rank);
    count[s.r0] += 3;
    ++count[s.r1];
  }
  // About 10 bytes per tet in one pass (an entry is 16 bytes): with the tets' own 16,
  // the checker stays below the builder's memory.
  const std::uint64_t budget = std::max<std::uint64_t>(3 * tets.size() / 5, 1u << 20);
  const std::vector<std::size_t> cut = ranges(count, budget);
  std::uint64_t most = 0;
  for (std::size_t part = 0; part + 1 < cut.size(); ++part) {
    std::uint64_t sum = 0;
    for (std::size_t v = cut[part]; v < cut[part + 1]; ++v) sum += count[v];
    most = std::max(most, sum);
  }
  const std::unique_ptr<Entry[]> entries(new Entry[most]);  // no zero fill
  const std::vector<std::uint8_t> span = passes_of_tets(tets.size(), cut, [&](std::size_t t) {
    const TwoLowest s = two_lowest(tets[t], rank);
    return std::pair{s.r0, s.r1};
  });
  const unsigned workers = thread_count(threads);
  std::vector<std::uint64_t> off;
  for (std::size_t part = 0; part + 1 < cut.size(); ++part) {
    const std::size_t lo = cut[part], hi = cut[part + 1];
    off.assign(hi - lo + 1, 0);
    for (std::size_t v = lo; v < hi; ++v) off[v - lo + 1] = off[v - lo] + count[v];
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    auto put = [&](std::size_t t, int f) {
      auto v = facet_vertices(tets[t], f);
      const std::uint32_t odd = sort3(v, rank) ? kOdd : 0;
      entries[pos[rank[v[0]] - lo]++] = {v[1], v[2], tets[t][f] | odd, static_cast<std::uint32_t>(4 * t + f)};
    };
    for (std::size_t t = 0; t < tets.size(); ++t) {
      if (!in_pass(span, t, part)) continue;
      const TwoLowest s = two_lowest(tets[t], rank);
      if (s.r1 < lo || s.r0 >= hi) continue;
      if (s.r0 >= lo)
        for (int f = 0; f < 4; ++f)
          if (f != s.slot0) put(t, f);
      if (s.r1 < hi) put(t, s.slot0);
    }
    // The buckets' groups in parallel (disjoint entry ranges), merged in bucket order:
    // the table and the recorded pairs are those of one thread.
    const std::vector<std::size_t> sub = split_buckets(off, lo, hi, workers == 1 ? 1 : 4 * workers);
    std::vector<PartResult> results(sub.size() - 1);
    parallel_chunks(results.size(), workers, 1, [&](std::size_t i, std::size_t, unsigned) {
      scan_buckets(tets, rank, entries.get(), off, lo, sub[i], sub[i + 1], classify, results[i]);
    });
    for (PartResult& r : results) merge_part(r, out, record);
  }
  std::sort(out.boundary_refs.begin(), out.boundary_refs.end());
  return out;
}

std::uint64_t count_edges(std::span<const Tet> tets, std::span<const std::uint32_t> rank, unsigned threads) {
  const unsigned workers = thread_count(threads);
  // An edge's lowest-ranked vertex is the tet's i-th lowest for 3 - i of its edges;
  // the edge is stored in that vertex's bucket as the other vertex's rank.
  const std::size_t point_count = rank.size();
  std::vector<std::uint32_t> count(point_count, 0);
  for (const Tet& k : tets) {
    const Ranked s = ranked(k, rank);
    count[s.r[0]] += 3, count[s.r[1]] += 2, count[s.r[2]] += 1;
  }
  // About 6.4 bytes per tet in one pass (an entry is 4 bytes), allocated once at the
  // largest pass's size: the checker's peak stays at the facet table's.
  const std::vector<std::size_t> cut = ranges(count, std::max<std::uint64_t>(8 * tets.size() / 5, 1u << 20));
  std::uint64_t most = 0;
  for (std::size_t part = 0; part + 1 < cut.size(); ++part) {
    std::uint64_t sum = 0;
    for (std::size_t v = cut[part]; v < cut[part + 1]; ++v) sum += count[v];
    most = std::max(most, sum);
  }
  const std::unique_ptr<std::uint32_t[]> other(new std::uint32_t[most]);  // no zero fill
  const std::vector<std::uint8_t> span = passes_of_tets(tets.size(), cut, [&](std::size_t t) {
    const Ranked s = ranked(tets[t], rank);
    return std::pair{s.r[0], s.r[2]};
  });
  std::vector<std::uint64_t> off;
  // Distinct other ends per bucket: seen[r] holds the last bucket that met rank r. A
  // bucket is visited once, by one worker, so a stale mark never equals the bucket being
  // counted and the marks never need a reset. One array per worker while they cost no
  // more than the entries (4 bytes per point each); else a parallel worker sorts its
  // buckets instead.
  const bool marks_per_worker = workers == 1 || std::uint64_t{workers} * point_count <= most;
  std::vector<std::vector<std::uint32_t>> seen(marks_per_worker ? workers : 0);
  std::uint64_t edges = 0;
  for (std::size_t part = 0; part + 1 < cut.size(); ++part) {
    const std::size_t lo = cut[part], hi = cut[part + 1];
    off.assign(hi - lo + 1, 0);
    for (std::size_t v = lo; v < hi; ++v) off[v - lo + 1] = off[v - lo] + count[v];
    std::vector<std::uint64_t> pos(off.begin(), off.end() - 1);
    for (std::size_t t = 0; t < tets.size(); ++t) {
      if (!in_pass(span, t, part)) continue;
      const Ranked s = ranked(tets[t], rank);
      if (s.r[2] < lo || s.r[0] >= hi) continue;
      for (int i = 0; i < 3; ++i)
        if (s.r[i] >= lo && s.r[i] < hi)
          for (int j = i + 1; j < 4; ++j) other[pos[s.r[i] - lo]++] = s.r[j];
    }
    std::atomic<std::uint64_t> found{0};
    parallel_chunks(hi - lo, workers, 4096, [&](std::size_t b, std::size_t e, unsigned w) {
      std::uint64_t local = 0;
      if (marks_per_worker) {
        std::vector<std::uint32_t>& mark = seen[w];
        if (mark.empty()) mark.assign(point_count, kNone);
        for (std::size_t a = b; a < e; ++a) {
          const auto bucket = static_cast<std::uint32_t>(lo + a);
          for (std::uint64_t i = off[a]; i < off[a + 1]; ++i)
            if (mark[other[i]] != bucket) mark[other[i]] = bucket, ++local;
        }
      } else {
        for (std::size_t a = b; a < e; ++a) {
          std::uint32_t* first = other.get() + off[a];
          std::uint32_t* last = other.get() + off[a + 1];
          std::sort(first, last);
          local += static_cast<std::uint64_t>(std::unique(first, last) - first);
        }
      }
      found += local;
    });
    edges += found;
  }
  return edges;
}

}  // namespace dtlab
