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
// returns the same array at every thread count and in every run. The records' pages are
// handed back as they are read (the caller frees the buffer). A serial compaction of the
// rotated tets (the records' pages released as it goes, so the peak stays the mesh's), then
// three parallel passes: count per (chunk, bucket of first ids), scatter into the buckets
// (a second array: with the first, 32 bytes per tet, no more than the records took), sort
// and translate each bucket.
void compact_canonical(TetRecord* records, std::size_t size, std::uint32_t n, const std::vector<std::uint32_t>& order,
                       std::vector<Tet>& out, unsigned threads);

}  // namespace dtlab
