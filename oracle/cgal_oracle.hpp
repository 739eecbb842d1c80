#pragma once
// CGAL's Delaunay_triangulation_3 (exact predicates, inexact constructions) as an
// oracle. Kept in one translation unit: CGAL headers compile slowly.
#include <span>

#include "oracle/oracle_run.hpp"

namespace dtlab {

// Range insertion with the input index as vertex info; inputs that CGAL merged
// into an existing vertex are reported as duplicates. Cells come back as input
// indices with orient3d > 0 (CGAL's POSITIVE orientation is Shewchuk's negative,
// so the first two vertices of each cell are swapped).
OracleRun cgal_delaunay(std::span<const Point3> points);

}  // namespace dtlab
