#pragma once
// One word for what a peer's answer is, judged by the exact checker against the
// input points (oracle/check/check.hpp), or why there is no answer.
#include <string>

#include "oracle/check/check.hpp"

namespace dtlab {

enum class Verdict {
  delaunay,        // proven the Delaunay tetrahedralization of the input (ties allowed)
  triangulation,   // valid, covers the hull once, some non-Delaunay facets
  flat_tets,       // zero-volume tets (maybe non-Delaunay facets), nothing else wrong
  invalid,         // overlaps, gaps, inverted tets, a non-convex or broken boundary
  unproven,        // no such defect found, but the checker could not prove that the tets
                   // cover the hull once (its `unproven` defect): not shown valid
  missing_points,  // else valid, but input points that are no vertex
  extra_points,    // tets on vertices that are not input points (box corners, ...)
  crashed,         // killed by a signal
  hung,            // killed at the time limit
  out_of_memory,   // ended for lack of memory: an allocation failed under the memory
                   // limit (std::bad_alloc, MemoryError, ...) or a SIGKILL not ours
  refused,         // ended with an error and no answer
  not_installed,   // the peer is not on this machine
};

const char* verdict_name(Verdict v);
// True for the verdicts that come with no mesh to judge.
bool no_answer(Verdict v);

// The verdict of an answer the checker judged: the worst class of defect decides
// (invalid before unproven before missing-points before flat-tets before triangulation).
Verdict verdict_of(const CheckReport& report);

// "overlap 3, gap 1, non-delaunay 211": the non-zero defect counts, by kind.
std::string defect_counts_text(const CheckReport& report);

}  // namespace dtlab
