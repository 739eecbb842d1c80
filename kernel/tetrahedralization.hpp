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
  // Empty, or 4 per tet: at 4t+f the facet opposite tets[t][f] seen from the tet across
  // it, as 4u+g (tets[u][g] is u's vertex opposite the facet), kNone on the boundary. Only
  // our build fills it, when asked (BuildOptions::keep_adjacency).
  std::vector<std::uint32_t> adjacency;
};

}  // namespace dtlab
