#pragma once
// An O(tets) audit of the working mesh, infinite tets included: adjacency mirrored
// and facets matching, every tet positively oriented, every facet locally Delaunay.
// For tests and debugging; returns an empty string when all holds.
#include <string>

#include "kernel/geometry.hpp"
#include "kernel/retriangulate.hpp"
#include "kernel/tet_mesh.hpp"

namespace dtlab {

template <PredicateBackend B>
std::string audit_mesh(const TetMesh& m, Geometry<B>& geo) {
  for (std::uint32_t t = 0; t < m.size(); ++t) {
    if (m.dead(t)) continue;
    const std::uint32_t* v = m.verts(t);
    const std::string id = "tet " + std::to_string(t) + " (" + std::to_string(v[0]) + "," +
                           std::to_string(v[1]) + "," + std::to_string(v[2]) + "," +
                           std::to_string(v[3]) + ")";
    if (geo.orientation(v[0], v[1], v[2], v[3]) <= 0) return id + " not positive";
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t nb = m.adj(4 * t + f);
      if (nb == TetMesh::kNoFacet) continue;
      if (m.dead(nb >> 2)) return id + " adjacent to a dead tet";
      if (m.adj(nb) != 4 * t + f) return id + " adjacency not mirrored";
      if (!(facet_key(v, f) == facet_key(m.verts(nb >> 2), nb & 3))) return id + " facet mismatch";
      // The Delaunay test is asked of a tet about a finite point.
      if (m.vertex(nb >> 2, nb & 3) != geo.infinite() && geo.conflict(v, m.vertex(nb >> 2, nb & 3)))
        return id + " facet " + std::to_string(f) + " not locally Delaunay (apex " +
               std::to_string(m.vertex(nb >> 2, nb & 3)) + ")";
    }
  }
  return "";
}

}  // namespace dtlab
