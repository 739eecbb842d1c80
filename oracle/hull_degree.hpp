#pragma once
// How many times the boundary surface wraps around an interior point.
//
// Let o be a point strictly on the inner side of every boundary facet (the caller
// proves it: o is a positive combination of the vertices of one tet, each on the
// inner side or on the plane of every boundary facet). Central projection from o
// then maps the closed boundary surface onto the unit sphere with positive
// orientation on every facet, a branched covering of some degree k, and k is the
// number of facets crossed by any ray from o that misses all edges. k == 1 makes
// the surface star-shaped around o, hence embedded; with every edge convex it is
// then the boundary of a convex polytope (Tietze-Nakajima), and since the tets
// cover each point with multiplicity equal to the surface's winding number, they
// tile it exactly once. k > 1 means the tets cover part of the hull twice.
//
// The ray runs from o through a point q inside facet f0; o and q are rational
// (weighted vertex averages), the crossing tests are exact rational orient3d
// behind a float filter with a generous margin. When the ray grazes an edge the
// weights change and the test is repeated.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct HullDegree {
  bool decided = false;
  std::vector<std::uint32_t> crossed;  // boundary facets the ray crosses (f0 first)
};

HullDegree hull_degree(std::span<const Point3> points,
                       std::span<const std::array<std::uint32_t, 3>> boundary,
                       const Tet& inner_tet, std::uint32_t f0);

}  // namespace dtlab
