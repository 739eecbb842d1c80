#pragma once
// The compact result every producer (our inserter, CGAL, TetGen) is reduced to,
// and every consumer (checker, oracles, writers, Voronoi) reads.
#include <array>
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab {

using Tet = std::array<std::uint32_t, 4>;

struct Tetrahedralization {
  std::vector<Point3> points;  // every input point, in input order
  std::vector<Tet> tets;       // finite tets; orient3d(p[t0],p[t1],p[t2],p[t3]) > 0
};

}  // namespace dtlab
