#pragma once
// The kernel's ids: 32-bit indices of points (vertices), tets, and facets (4t + f, the
// facet of tet t opposite its vertex f). One value means "none" for all three: no
// vertex (no infinite vertex with a bigtet), no tet, no facet (the outside of a bigtet),
// and it marks a dead tet's first vertex.
#include <cstdint>

namespace dtlab {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

}  // namespace dtlab
