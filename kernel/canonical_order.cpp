#include "kernel/canonical_order.hpp"

#include <algorithm>
#include <utility>

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
