#pragma once
// The geometry of a tool's cell against exact positions: where each vertex should be
// (the point where the planes of its faces meet: bisectors of the site and its
// neighbours, box walls), and face areas.
#include <cstdint>
#include <span>

#include "voronoi/box.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

// Area of face f of a cell (Newell's formula).
double face_area(const VoronoiCell& c, std::size_t f);

// Asks the cache for the sites across the cell's faces (vertex_errors reads them; at
// 10^5 sites in input order they are misses): called early, the loads overlap other work.
void prefetch_face_sites(const VoronoiCell& c, std::span<const Point3> sites);

struct VertexError {
  double distance = 0;   // max-norm distance to the intersection of its faces' planes
  bool decided = false;  // false: the planes do not fix a point (fewer than 3, parallel)
  bool below = false;    // decided, distance not computed: certified at most `below`
};

// Per vertex of the cell of `site` (sites: all sites; neighbour ids index them,
// -1..-6 are the walls of `box`): the intersection of the three best-conditioned
// planes of its faces, solved in long double relative to the site, and the vertex's
// distance to it. `out` gets one entry per vertex. With `below` >= 0, a vertex on three
// planes whose distance the certified double filter (vertex_filter.hpp) bounds by
// `below` is not solved: `below` set, the distance left 0; every distance computed is
// the long double solve's, whatever `below`.
void vertex_errors(const VoronoiCell& c, std::span<const Point3> sites, std::uint32_t site, const vor::Box& box,
                   std::span<VertexError> out, double below = -1);
// The same with the cell's incidence already built (cell_incidence): each vertex's
// faces in the order the cell lists them.
void vertex_errors(const VoronoiCell& c, const CellIncidence& in, std::span<const Point3> sites, std::uint32_t site,
                   const vor::Box& box, std::span<VertexError> out, double below = -1);

}  // namespace dtlab
