#include "kernel/canonical_order.hpp"

#include <algorithm>
#include <utility>

#include "kernel/page_release.hpp"
#include "kernel/parallel_for.hpp"

namespace dtlab {

Tet canonical_tet(const Tet& t) {
  int m = 0;
  for (int i = 1; i < 4; ++i)
    if (t[i] < t[m]) m = i;
  // An even permutation taking position m to 0: (0 m) then a swap of the other two.
  Tet r = t;
  if (m != 0) {
    std::swap(r[0], r[m]);
    const int a = m == 1 ? 2 : 1, b = m == 3 ? 2 : 3;
    std::swap(r[a], r[b]);
  }
  // Cyclic rotations of the last three are even: the smallest of them to position 1.
  if (r[2] < r[1] && r[2] < r[3])
    r = {r[0], r[2], r[3], r[1]};
  else if (r[3] < r[1] && r[3] < r[2])
    r = {r[0], r[3], r[1], r[2]};
  return r;
}

void canonical_order(std::vector<Tet>& tets, std::size_t points, unsigned threads) {
  constexpr std::size_t kChunk = 1 << 16;
  parallel_chunks(tets.size(), threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t i = b; i < e; ++i) tets[i] = canonical_tet(tets[i]);
  });
  // Bucket b holds the tets whose first vertex is b: [start[b], start[b + 1]).
  std::vector<std::uint32_t> start(points + 1, 0);
  for (const Tet& t : tets) ++start[t[0] + 1];
  for (std::size_t b = 0; b < points; ++b) start[b + 1] += start[b];
  // In place (American flag sort): each tet is swapped into the next free slot of its bucket.
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (std::size_t b = 0; b < points; ++b)
    while (next[b] < start[b + 1]) {
      Tet t = tets[next[b]];
      while (t[0] != b) std::swap(t, tets[next[t[0]]++]);
      tets[next[b]++] = t;
    }
  std::vector<std::uint32_t>().swap(next);
  parallel_chunks(points, threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t v = b; v < e; ++v) std::sort(tets.begin() + start[v], tets.begin() + start[v + 1]);
  });
}

}  // namespace dtlab

namespace dtlab {

namespace {

bool finite(const TetRecord& r, std::uint32_t n) {
  return r.v[0] < n && r.v[1] < n && r.v[2] < n && r.v[3] < n;  // dead tets have v[0] == kNone
}

// Where each (chunk, bucket) writes: offsets[c * buckets + b], buckets in order, chunks in
// order within a bucket; bucket b's tets are [starts[b], starts[b + 1]).
struct Layout {
  std::size_t chunks, buckets;
  int shift;  // bucket of a tet: its first (smallest) id >> shift
  std::vector<std::size_t> offsets, starts;
};

// Counts per (chunk of `tets`, bucket), then their prefix sums.
Layout count_buckets(const std::vector<Tet>& tets, std::uint32_t n, unsigned threads) {
  Layout l;
  l.chunks = std::max<std::size_t>(1, std::min<std::size_t>(4 * std::size_t(threads), tets.size() / 4096 + 1));
  l.shift = 0;
  while ((std::size_t(n) >> l.shift) > 8192) ++l.shift;
  l.buckets = (std::size_t(n) >> l.shift) + 1;
  l.offsets.assign(l.chunks * l.buckets, 0);
  parallel_for(l.chunks, threads, 1, [&](std::size_t c, unsigned) {
    std::size_t* count = l.offsets.data() + c * l.buckets;
    for (std::size_t i = tets.size() * c / l.chunks, e = tets.size() * (c + 1) / l.chunks; i < e; ++i)
      ++count[tets[i][0] >> l.shift];
  });
  l.starts.assign(l.buckets + 1, 0);
  std::size_t at = 0;
  for (std::size_t b = 0; b < l.buckets; ++b) {
    l.starts[b] = at;
    for (std::size_t c = 0; c < l.chunks; ++c) {
      const std::size_t k = l.offsets[c * l.buckets + b];
      l.offsets[c * l.buckets + b] = at;
      at += k;
    }
  }
  l.starts[l.buckets] = at;
  return l;
}

// The finite live tets, rotated (canonical_tet on ids), in slot order; the records' pages
// handed back as they are read, so this copy never coexists with the whole mesh.
std::vector<Tet> rotated_tets(TetRecord* records, std::size_t size, std::uint32_t n) {
  std::size_t count = 0;
  for (std::size_t t = 0; t < size; ++t) count += finite(records[t], n);
  std::vector<Tet> tets;
  tets.reserve(count);
  constexpr std::size_t kChunk = 1 << 15;  // records between two releases (1 MiB)
  const char* unreleased = reinterpret_cast<const char*>(records);
  for (std::size_t start = 0; start < size; start += kChunk) {
    const std::size_t stop = std::min(size, start + kChunk);
    for (std::size_t t = start; t < stop; ++t)
      if (const TetRecord& r = records[t]; finite(r, n))
        tets.push_back(canonical_tet({r.v[0], r.v[1], r.v[2], r.v[3]}));
    unreleased = detail::release_pages(unreleased, reinterpret_cast<const char*>(records + stop));
  }
  return tets;
}

}  // namespace

void compact_canonical(TetRecord* records, std::size_t size, std::uint32_t n, const std::vector<std::uint32_t>& order,
                       std::vector<Tet>& out, unsigned threads) {
  std::vector<Tet> tets = rotated_tets(records, size, n);  // grows while the records shrink
  const Layout l = count_buckets(tets, n, threads);
  out.resize(tets.size());  // with `tets`: 32 bytes per tet, no more than the records took
  parallel_for(l.chunks, threads, 1, [&](std::size_t c, unsigned) {
    std::vector<std::size_t> at(l.offsets.begin() + static_cast<std::ptrdiff_t>(c * l.buckets),
                                l.offsets.begin() + static_cast<std::ptrdiff_t>((c + 1) * l.buckets));
    for (std::size_t i = tets.size() * c / l.chunks, e = tets.size() * (c + 1) / l.chunks; i < e; ++i)
      out[at[tets[i][0] >> l.shift]++] = tets[i];
  });
  std::vector<Tet>().swap(tets);
  // Each bucket sorted, then its ids translated (a bucket holds neighbouring ids).
  parallel_for(l.buckets, threads, 16, [&](std::size_t k, unsigned) {
    const auto first = out.begin() + static_cast<std::ptrdiff_t>(l.starts[k]);
    const auto last = out.begin() + static_cast<std::ptrdiff_t>(l.starts[k + 1]);
    std::sort(first, last);
    for (auto it = first; it != last; ++it)
      for (std::uint32_t& v : *it) v = order[v];
  });
}

}  // namespace dtlab
