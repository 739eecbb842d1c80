#pragma once
// Schedule-free orders of a tet list. canonical_order: every tet written from its smallest
// vertex by an even permutation (the orientation is kept), the other three rotated
// cyclically so that the smaller of them comes second; then the list sorted. The same tet
// set gives the same array, whatever order and rotations it came in (the canonical compare
// of tests and `fuzz --against serial`). compact_canonical: the parallel build's output,
// the same order taken on vertex ids (insertion ranks) instead of input indices, produced
// from the records in parallel.
#include <cstdint>
#include <vector>

#include "kernel/tet_mesh.hpp"
#include "kernel/tetrahedralization.hpp"

namespace dtlab {

// The tet rotated as above.
Tet canonical_tet(const Tet& t);

// In place, with 8 bytes per point of extra memory (a counting sort on the first vertex,
// every vertex below `points`, then each run sorted); threads as in parallel_for.
void canonical_order(std::vector<Tet>& tets, std::size_t points, unsigned threads);

// The finite live tets among records[0, size) (vertex ids below n are finite), each
// rotated and the list sorted as canonical_order does, on the vertex ids; then every id v
// translated to order[v]. A function of the tet set and the ids only, so a parallel build
// returns the same array at every thread count and in every run. The records are
// overwritten and their pages handed back (the caller frees the buffer). Three parallel
// passes, no copy beside the output: each chunk of records compacted in place (rotated,
// 16 bytes per tet at the chunk's start) and counted per bucket of first ids, the rest of
// its pages released; the output allocated and each chunk scattered into its buckets, its
// pages released; each bucket sorted (a counting sort on the first id, then each run) and
// translated. Peak: the records' pages, not the records plus the output.
void compact_canonical(TetRecord* records, std::size_t size, std::uint32_t n, const std::vector<std::uint32_t>& order,
                       std::vector<Tet>& out, unsigned threads);

// Tetrahedralization::adjacency of compact_canonical's output `out`, from a copy of the
// records it was made from (`records`, all `size` of them, read before compact_canonical
// overwrote them): every finite record found in `out` (the run of its first id, located
// through the inverse of `order`, scanned for its other three), then each of its facets'
// mirrors moved to the output's rotations. In parallel; 8 bytes per point and 4 per record
// beside the copy.
std::vector<std::uint32_t> canonical_adjacency(const TetRecord* records, std::size_t size, std::uint32_t n,
                                               const std::vector<std::uint32_t>& order, const std::vector<Tet>& out,
                                               unsigned threads);

}  // namespace dtlab
