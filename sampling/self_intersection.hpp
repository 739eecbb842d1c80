#pragma once
// Pairs of triangles of a mesh that intersect other than along the features they
// share (a common vertex or edge). Decided by orient3d signs only, on the template
// backend, so that an exact backend gives an exact count.
#include <cstdint>

#include "predicates/backend.hpp"
#include "sampling/bvh.hpp"

namespace dtlab {

// Counts intersecting pairs with the BVH; stops counting at `limit`.
template <PredicateBackend P>
std::uint64_t count_self_intersections(const Bvh& bvh, const P& pred, std::uint64_t limit = UINT64_MAX);

// The pair test itself, exposed for tests: do triangles s and t of `mesh` intersect
// beyond their shared vertices?
template <PredicateBackend P>
bool triangles_intersect(const TriangleMesh& mesh, std::uint32_t s, std::uint32_t t, const P& pred);

}  // namespace dtlab

#include "sampling/self_intersection_impl.hpp"
