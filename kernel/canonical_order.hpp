#pragma once
// A schedule-free order of a tet list (the parallel build's output): every tet written
// from its smallest vertex by an even permutation (the orientation is kept), the other
// three rotated cyclically so that the smaller of them comes second; then the list sorted.
// The same tet set gives the same array, whatever order and rotations it came in.
#include <cstdint>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

// The tet rotated as above.
Tet canonical_tet(const Tet& t);

// In place, with 8 bytes per point of extra memory (a counting sort on the first vertex,
// every vertex below `points`, then each run sorted); threads as in parallel_for.
void canonical_order(std::vector<Tet>& tets, std::size_t points, unsigned threads);

}  // namespace dtlab
