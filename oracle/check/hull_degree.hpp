#pragma once
// How many times the boundary surface wraps around an interior point.
//
// Let o be a point strictly on the inner side of every boundary facet (the caller
// proves it: o is a positive combination of the vertices of one tet, each on the
// inner side or on the plane of every boundary facet, and a positive tet has a
// vertex strictly off every plane). Central projection from o then maps the closed
// boundary surface onto the unit sphere with positive orientation on every facet, a
// branched covering of some degree k, and k is the number of facets crossed by any
// ray from o that misses all edges. k == 1 makes the surface star-shaped around o,
// hence embedded; with every edge convex it is then the boundary of a convex
// polytope (Tietze-Nakajima), and since the tets cover each point with multiplicity
// equal to the surface's winding number, they tile it exactly once. k > 1 means the
// tets cover part of the hull k times.
//
// The ray runs from o (the centroid of the tet) towards q_e = q + e*x + e^2*y + e^3*z,
// q the centroid of facet f0 and e > 0 infinitesimal (a symbolic perturbation), so it
// never meets an edge and the count is always decided (see hull_degree.cpp). All
// crossing tests are exact rational arithmetic behind a float filter with a range guard.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct HullDegree {
  // False only if the precondition fails (o on the plane of a boundary facet's edge
  // and o, i.e. o collinear with an edge): the caller reports `unproven`.
  bool decided = false;
  std::vector<std::uint32_t> crossed;  // boundary facets the ray crosses (f0 first)
};

HullDegree hull_degree(std::span<const Point3> points, std::span<const std::array<std::uint32_t, 3>> boundary,
                       const Tet& inner_tet, std::uint32_t f0);

}  // namespace dtlab
