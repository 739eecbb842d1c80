#pragma once
// Facet adjacency rebuilt from the tets alone (the checker trusts no adjacency
// given by a producer). Facets are matched by their vertex triple, bucketed by the
// vertex that appears first in the tets (a counting sort; see facet_table.cpp for
// why first appearance) with the few facets of one bucket sorted. To bound memory
// the buckets are processed in ranges, each one pass over the tets: about 10 bytes
// per tet beyond the tets themselves.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

// Facet f of a tet (the one opposite vertex f), ordered so that its normal by the
// right-hand rule points out of the tet when the tet has orient3d > 0: seen from
// outside, the three vertices turn counter-clockwise.
inline std::array<std::uint32_t, 3> facet_vertices(const Tet& k, int f) {
  switch (f) {
    case 0: return {k[1], k[3], k[2]};
    case 1: return {k[0], k[2], k[3]};
    case 2: return {k[0], k[3], k[1]};
    default: return {k[0], k[1], k[2]};
  }
}

struct FacetTable {
  // Facets in one tet only, as refs 4t+f, ascending.
  std::vector<std::uint32_t> boundary_refs;
  std::vector<std::vector<std::uint32_t>> overshared;  // the 4t+f refs of each facet in 3+ tets
  // Pairs (4t+f, 4t'+f') sharing a facet with the same orientation: both tets lie
  // on the same side of it.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> same_side;
  std::uint64_t interior = 0, boundary = 0;
};

// A facet in exactly two tets, as the table finds it: the refs 4t+f of its two sides,
// its vertices in the table's canonical order, and the apex of each side. When tet r1/4 has
// orient3d > 0, so does (v[0], v[1], v[2], apex1), or (v[1], v[0], v[2], apex1) when
// `odd1` (the canonical order is an odd permutation of the facet's outward order).
struct FacetPair {
  std::uint32_t r1, r2;
  std::array<std::uint32_t, 3> v;
  std::uint32_t apex1, apex2;
  bool odd1;
};
using FacetPairVisitor = std::function<void(const FacetPair&)>;

// Vertices ranked by first appearance in the tets (kNone for a point in no tet): the
// bucket order of the two functions below, and the checker's renumbering (check.cpp).
std::vector<std::uint32_t> first_appearance(std::span<const Tet> tets, std::size_t point_count);

// Tets must have four distinct vertices below rank.size(), tets.size() < 2^30 and
// rank.size() < 2^31; rank = first_appearance(tets, point count).
FacetTable build_facet_table(std::span<const Tet> tets, std::span<const std::uint32_t> rank,
                             const FacetPairVisitor& on_pair = {});

// The same table built on `threads` threads (0: all). `classify` sees every facet in
// two tets, from any worker at once (it must be thread-safe, e.g. an exact sign), and
// returns 0 or a code; `record(pair, code)` then sees the pairs with a nonzero code on
// the calling thread, in the order one thread finds them, so the table and the
// recorded pairs are the same for every thread count.
using FacetPairClassifier = std::function<int(const FacetPair&)>;
using FacetPairRecorder = std::function<void(const FacetPair&, int)>;
FacetTable build_facet_table(std::span<const Tet> tets, std::span<const std::uint32_t> rank,
                             const FacetPairClassifier& classify, const FacetPairRecorder& record, unsigned threads);

// Number of distinct edges of the tets (rank as above), on `threads` threads (0: all).
std::uint64_t count_edges(std::span<const Tet> tets, std::span<const std::uint32_t> rank, unsigned threads = 1);

}  // namespace dtlab
