#include "kernel/canonical_order.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <utility>

#include "kernel/page_release.hpp"
#include "kernel/parallel_for.hpp"

namespace dtlab {

namespace {

// canonical_tet by its definition, for any ids (equal ones included).
[[gnu::noinline]] constexpr Tet rotate_by_definition(const Tet& t) {
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

// The six comparisons t[j] < t[i] (i < j) as bits: which of the 24 orders the ids are in.
constexpr int comparison_index(const Tet& t) {
  return int(t[1] < t[0]) | int(t[2] < t[0]) << 1 | int(t[3] < t[0]) << 2 | int(t[2] < t[1]) << 3 |
         int(t[3] < t[1]) << 4 | int(t[3] < t[2]) << 5;
}

// For distinct ids, by comparison_index: the position each output id comes from, taken from
// the definition on the 24 orders (a lookup instead of the definition's unpredictable branches).
using Rotations = std::array<std::array<std::uint8_t, 4>, 64>;
constexpr Rotations make_rotations() {
  Rotations from{};
  Tet rank = {0, 1, 2, 3};
  do {
    const Tet r = rotate_by_definition(rank);
    for (int i = 0; i < 4; ++i)
      for (int p = 0; p < 4; ++p)
        if (rank[p] == r[i]) from[comparison_index(rank)][i] = static_cast<std::uint8_t>(p);
  } while (std::next_permutation(rank.begin(), rank.end()));
  return from;
}
constexpr Rotations kRotations = make_rotations();

// Branch-free (integer &, not &&): the test runs on every tet and is almost always true.
bool distinct(const Tet& t) {
  const auto ne = [&](int a, int b) { return static_cast<unsigned>(t[a] != t[b]); };
  return (ne(0, 1) & ne(0, 2) & ne(0, 3) & ne(1, 2) & ne(1, 3) & ne(2, 3)) != 0;
}

inline Tet rotate(const Tet& t) {
  if (!distinct(t)) [[unlikely]]
    return rotate_by_definition(t);
  const std::array<std::uint8_t, 4>& from = kRotations[comparison_index(t)];
  return {t[from[0]], t[from[1]], t[from[2]], t[from[3]]};
}

}  // namespace

Tet canonical_tet(const Tet& t) { return rotate(t); }

void canonical_order(std::vector<Tet>& tets, std::size_t points, unsigned threads) {
  constexpr std::size_t kChunk = 1 << 16;
  parallel_chunks(tets.size(), threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t i = b; i < e; ++i) tets[i] = rotate(tets[i]);
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

// The records are cut into chunks, each compacted in place (its finite tets, rotated, at the
// start of its own bytes); the tets are distributed into buckets of neighbouring first ids.
// Chunk c's tets of bucket b go to out[offsets[c * buckets + b]...], buckets in order, chunks
// in order within a bucket; bucket b's tets are out[starts[b], starts[b + 1]).
struct Layout {
  std::size_t size = 0, chunks = 1, buckets = 1;
  int shift = 0;                  // bucket of a tet: its first (smallest) id >> shift
  std::vector<std::size_t> kept;  // finite tets per chunk
  std::vector<std::size_t> offsets, starts;
  std::size_t chunk_begin(std::size_t c) const { return size * c / chunks; }
};

// Buckets of at most 1024 ids (a bucket's tets and their sorted copy stay in a core's L2),
// at least 16 per thread; chunks of at least 2^15 records, at most 32 per thread (few
// chunks in flight: the output's pages are committed as the records' are released).
Layout plan_layout(std::size_t size, std::uint32_t n, unsigned threads) {
  Layout l;
  l.size = size;
  l.chunks = std::clamp<std::size_t>(size >> 15, 1, 32 * std::size_t(threads));
  while (l.shift < 10 && (std::size_t(n) >> (l.shift + 1)) >= 16 * std::size_t(threads)) ++l.shift;
  l.buckets = (std::size_t(n) >> l.shift) + 1;
  l.kept.assign(l.chunks, 0);
  l.offsets.assign(l.chunks * l.buckets, 0);
  return l;
}

std::byte* chunk_bytes(TetRecord* records, const Layout& l, std::size_t c) {
  return reinterpret_cast<std::byte*>(records + l.chunk_begin(c));
}

// Stage 1, in parallel: each chunk's finite tets rotated (canonical_tet on ids) and written
// over its own records from its start (16 bytes per tet over 32 per record: a write never
// reaches a record not yet read), counted per bucket; the rest of the chunk's pages handed
// back, so that the output allocated next does not coexist with the whole mesh.
void compact_chunks(TetRecord* records, std::uint32_t n, Layout& l, unsigned threads) {
  parallel_for(l.chunks, threads, 1, [&](std::size_t c, unsigned) {
    std::byte* to = chunk_bytes(records, l, c);
    std::size_t* count = l.offsets.data() + c * l.buckets;
    std::size_t kept = 0;
    for (std::size_t t = l.chunk_begin(c), e = l.chunk_begin(c + 1); t < e; ++t) {
      const TetRecord& r = records[t];
      if (!finite(r, n)) continue;
      const Tet tet = rotate({r.v[0], r.v[1], r.v[2], r.v[3]});  // read before the write below
      std::memcpy(to + kept++ * sizeof(Tet), &tet, sizeof(Tet));
      ++count[tet[0] >> l.shift];
    }
    l.kept[c] = kept;
    detail::release_pages(reinterpret_cast<const char*>(to + kept * sizeof(Tet)),
                          reinterpret_cast<const char*>(records + l.chunk_begin(c + 1)));
  });
}

// The counts per (chunk, bucket) turned into their places in the output; the total.
std::size_t place_buckets(Layout& l) {
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
  return at;
}

// The output sized, its page faults taken in parallel first (a single-threaded resize would
// take them all on one thread: 37 ms of 107 MB at 10^6 points, 20 ms on two threads).
void allocate_output(std::vector<Tet>& out, std::size_t size, unsigned threads) {
  out.clear();
  out.reserve(size);
  char* const bytes = reinterpret_cast<char*>(out.data());
  constexpr std::size_t kSlice = std::size_t(1) << 21;
  parallel_chunks(size * sizeof(Tet), threads, kSlice,
                  [&](std::size_t b, std::size_t e, unsigned) { detail::populate_pages(bytes + b, bytes + e); });
  out.resize(size);
}

// Stage 2, in parallel: each chunk's compacted tets into their buckets; the chunk's pages
// handed back once read.
void scatter_chunks(TetRecord* records, const Layout& l, std::vector<Tet>& out, unsigned threads) {
  parallel_for(l.chunks, threads, 1, [&](std::size_t c, unsigned) {
    const std::byte* from = chunk_bytes(records, l, c);
    std::vector<std::size_t> at(l.offsets.begin() + static_cast<std::ptrdiff_t>(c * l.buckets),
                                l.offsets.begin() + static_cast<std::ptrdiff_t>((c + 1) * l.buckets));
    for (std::size_t i = 0; i < l.kept[c]; ++i) {
      Tet tet;
      std::memcpy(&tet, from + i * sizeof(Tet), sizeof(Tet));
      out[at[tet[0] >> l.shift]++] = tet;
    }
    detail::release_pages(reinterpret_cast<const char*>(from),
                          reinterpret_cast<const char*>(from + l.kept[c] * sizeof(Tet)));
  });
}

// Tets with the same first id, ordered by the other three: (second, third) as one 64-bit key,
// the fourth only on a tie (never in a valid mesh: one tet on each side of an oriented face).
std::uint64_t tail_key(const Tet& t) { return std::uint64_t(t[1]) << 32 | t[2]; }

bool tail_less(const Tet& a, const Tet& b) {
  const std::uint64_t ka = tail_key(a), kb = tail_key(b);
  return ka < kb || (ka == kb && a[3] < b[3]);
}

void insertion_sort(Tet* first, Tet* last) {
  for (Tet* i = first + 1; i < last; ++i) {
    const Tet t = *i;
    Tet* j = i;
    for (; j > first && tail_less(t, j[-1]); --j) *j = j[-1];
    *j = t;
  }
}

// Runs hold 6.7 tets on average for uniform points, up to ~80 (the low ids' runs are the
// long ones): insertion sort up to 32, std::sort above. (A sorting network on packed keys,
// tried instead of the insertion sort's mispredicted exits, was slower.)
void sort_run(Tet* first, Tet* last) {
  if (last - first > 32)
    std::sort(first, last, [](const Tet& a, const Tet& b) { return tail_less(a, b); });
  else
    insertion_sort(first, last);
}

// A worker's copy of the bucket it sorts, and the runs' starts.
struct BucketScratch {
  std::vector<Tet> tets;
  std::vector<std::size_t> start;
};

// One bucket sorted (a counting sort on the first id into the scratch, then each run of one
// first id by the other three) and its ids translated back into place. A bucket too big for
// a scratch copy (degenerate input) is sorted in place.
void sort_bucket(Tet* first, Tet* last, std::uint32_t base, std::size_t width, const std::vector<std::uint32_t>& order,
                 BucketScratch& s) {
  const auto translate = [&](const Tet& t) { return Tet{order[t[0]], order[t[1]], order[t[2]], order[t[3]]}; };
  const std::size_t size = static_cast<std::size_t>(last - first);
  constexpr std::size_t kMaxScratch = std::size_t(1) << 20;
  if (size > kMaxScratch) {
    std::sort(first, last);
    std::transform(first, last, first, translate);
    return;
  }
  s.tets.resize(size);
  s.start.assign(width + 1, 0);
  for (const Tet* t = first; t < last; ++t) ++s.start[(*t)[0] - base + 1];
  for (std::size_t v = 0; v < width; ++v) s.start[v + 1] += s.start[v];
  for (const Tet* t = first; t < last; ++t) s.tets[s.start[(*t)[0] - base]++] = *t;
  // start[v] is now the end of run v (the start of run v + 1).
  for (std::size_t v = 0, b = 0; v < width; b = s.start[v++]) sort_run(s.tets.data() + b, s.tets.data() + s.start[v]);
  std::transform(s.tets.begin(), s.tets.end(), first, translate);
}

// Stage 3, in parallel: every bucket sorted and translated.
void sort_buckets(std::vector<Tet>& out, std::uint32_t n, const std::vector<std::uint32_t>& order, const Layout& l,
                  unsigned threads) {
  std::vector<BucketScratch> scratch(thread_count(threads));
  parallel_for(l.buckets, threads, 4, [&](std::size_t b, unsigned w) {
    const std::size_t base = b << l.shift;
    const std::size_t width = std::min(std::size_t(1) << l.shift, std::size_t(n) - std::min<std::size_t>(base, n));
    sort_bucket(out.data() + l.starts[b], out.data() + l.starts[b + 1], static_cast<std::uint32_t>(base), width, order,
                scratch[w]);
  });
}

}  // namespace

void compact_canonical(TetRecord* records, std::size_t size, std::uint32_t n, const std::vector<std::uint32_t>& order,
                       std::vector<Tet>& out, unsigned threads) {
  Layout l = plan_layout(size, n, threads);
  compact_chunks(records, n, l, threads);
  allocate_output(out, place_buckets(l),
                  threads);  // the records' unused pages are back: 32 bytes per tet with the compacted ones
  scatter_chunks(records, l, out, threads);
  sort_buckets(out, n, order, l, threads);
}

std::vector<std::uint32_t> canonical_adjacency(const TetRecord* records, std::size_t size, std::uint32_t n,
                                               const std::vector<std::uint32_t>& order, const std::vector<Tet>& out,
                                               unsigned threads) {
  constexpr std::size_t kChunk = 1 << 14;
  // Vertex id of each input index, and where each vertex id's run of tets starts in `out`
  // (out is sorted on vertex ids, then translated to input indices).
  std::vector<std::uint32_t> id(order.size(), kNone), run(n, kNone);
  for (std::uint32_t v = 0; v < n; ++v) id[order[v]] = v;
  parallel_chunks(out.size(), threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t j = b; j < e; ++j)
      if (j == 0 || out[j - 1][0] != out[j][0]) run[id[out[j][0]]] = static_cast<std::uint32_t>(j);
  });
  // Each finite record's place in `out`.
  std::vector<std::uint32_t> at(size, kNone);
  parallel_chunks(size, threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t r = b; r < e; ++r) {
      if (!finite(records[r], n)) continue;
      const Tet t = rotate({records[r].v[0], records[r].v[1], records[r].v[2], records[r].v[3]});
      const Tet want{order[t[0]], order[t[1]], order[t[2]], order[t[3]]};
      for (std::size_t j = run[t[0]]; j < out.size() && out[j][0] == want[0]; ++j)
        if (out[j] == want) {
          at[r] = static_cast<std::uint32_t>(j);
          break;
        }
    }
  });
  // Output slot k of a record's tet holds input index out[at][k]; its facet's mirror is
  // the record's adj at the slot with that vertex, moved the same way on the other side.
  const auto slot_of = [&](const Tet& t, std::uint32_t input) {
    return static_cast<std::uint32_t>(std::find(t.begin(), t.end(), input) - t.begin());
  };
  std::vector<std::uint32_t> adjacency(4 * out.size(), kNone);
  parallel_chunks(size, threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t r = b; r < e; ++r) {
      if (at[r] == kNone) continue;
      const TetRecord& rec = records[r];
      for (int s = 0; s < 4; ++s) {
        const Facet m = rec.adj[s];
        if (m.none() || at[m.tet()] == kNone) continue;
        const std::uint32_t u = at[m.tet()];
        const std::uint32_t k = slot_of(out[at[r]], order[rec.v[s]]);
        const std::uint32_t g = slot_of(out[u], order[records[m.tet()].v[m.face()]]);
        adjacency[4 * std::size_t(at[r]) + k] = 4 * u + g;
      }
    }
  });
  return adjacency;
}

}  // namespace dtlab
