#pragma once
// CGAL's Delaunay_triangulation_3 (exact predicates, inexact constructions) as an
// oracle. Kept in one translation unit: CGAL headers compile slowly.
#include <cstdint>
#include <span>
#include <vector>

#include "oracle/peers/oracle_run.hpp"

namespace dtlab {

// Range insertion with the input index as vertex info; inputs that CGAL merged
// into an existing vertex are reported as duplicates. Cells come back as input
// indices with orient3d > 0 (CGAL's POSITIVE orientation is Shewchuk's negative,
// so the first two vertices of each cell are swapped).
OracleRun cgal_delaunay(std::span<const Point3> points);

// The insertion order CGAL's range insertion uses: CGAL::spatial_sort (biased
// randomized rounds, each sorted along a Hilbert curve split at medians), as input
// indices. For measuring our BRIO (a Hilbert curve on a fixed 2^10 grid) against it.
std::vector<std::uint32_t> cgal_spatial_sort_order(std::span<const Point3> points);

}  // namespace dtlab
