#pragma once
// A Voronoi cell built directly from the Delaunay star of its site, without clipping.
//
// The tets around site v, each with v removed, form v's link: a closed triangulated
// sphere when v is interior (an open one on the hull). Link triangle t is dual to the
// Voronoi vertex cc[t] (its tet's circumcentre, computed once per tet and shared by
// the four cells around it); link vertex w is dual to the cell face on the bisector of
// v and w, whose corners are the circumcentres of the link triangles around w, in ring
// order. Cospherical tets (lattices) share one circumcentre: neighbouring link
// triangles whose centres lie within `band` are merged (union-find), rings are
// collapsed, a face left with one distinct corner is dropped (a Delaunay edge inside a
// cospherical cluster: no Voronoi face). Anything doubtful (an open link, a badly
// conditioned centre, a merge that does not leave a polytope with V - E + F = 2, an
// edge shorter than `min_edge`) returns false, and the caller clips the cell instead.
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/ids.hpp"
#include "kernel/tetrahedralization.hpp"
#include "voronoi/cell_buffer.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab::vor {

class DualCellBuilder {
 public:
  explicit DualCellBuilder(std::size_t sites) : local_(sites, kNone) {}

  // `star`: the tets containing v; `cc`: circumcentre per tet; `bad[t]`: centre too
  // badly conditioned to trust. On success `out` holds the unclipped cell (vertices,
  // faces counter-clockwise from outside, face_neighbor = site ids); volume and
  // centroid are left to the caller.
  bool build(std::uint32_t v, std::span<const std::uint32_t> star, std::span<const Tet> tets,
             std::span<const Point3> cc, std::span<const char> bad, double band, double min_edge,
             CellBuffer& out);

  // Only collects the link of v (for `neighbors`); false if a centre is bad.
  bool gather(std::uint32_t v, std::span<const std::uint32_t> star, std::span<const Tet> tets,
              std::span<const char> bad);

  // Global ids of the link vertices of the last build or gather (v's Delaunay neighbours).
  std::span<const std::uint32_t> neighbors() const { return global_; }

 private:
  std::uint32_t find(std::uint32_t t);
  // The stages of build, after gather. Walks each link vertex's ring of link triangles
  // (ring_, roff_); false when the link is no closed sphere (a hull site).
  bool link_rings(std::size_t nl, std::size_t nt);
  // Unites the link triangles whose centres `c` lie within `band` along a ring edge
  // (parent_); failed: a ring of fewer than 3 or, unmerged, an edge within min_edge.
  enum class Merge { none, merged, failed };
  Merge merge_close_centres(std::size_t nl, std::size_t nt, const Point3* c, double band, double min_edge);
  // The faces of an unmerged cell: each ring backwards (counter-clockwise from outside).
  void emit_rings(std::size_t nl, CellBuffer& out) const;
  // The faces of a merged cell over one vertex per merged group; false when a face
  // degenerates (fewer than 3 corners, a corner twice, an edge within min_edge).
  bool emit_merged_rings(std::size_t nl, std::size_t nt, double min_edge, CellBuffer& out);
  // Euler characteristic 2 and every directed edge once with its reverse.
  bool closed_and_oriented(const CellBuffer& out);

  std::vector<std::uint32_t> local_;   // global vertex id -> local id, kNone when unused
  std::vector<std::uint32_t> global_;  // local -> global
  std::vector<std::uint32_t> tri_;     // 3 local ids per link triangle (= star tet)
  std::vector<Point3> lcc_;            // link triangle -> circumcentre (cells with merges)
  std::vector<std::uint32_t> coff_, btri_, bnext_, bprev_;  // corners bucketed by link vertex
  std::vector<std::uint32_t> ring_, roff_;    // ring of link triangles per link vertex
  std::vector<std::uint32_t> by_prev_;        // link vertex -> corner, while walking one ring
  std::vector<std::uint32_t> parent_, vid_;
  const Point3* prefetch_ = nullptr;          // centres to prefetch while gathering
  std::vector<std::uint64_t> edges_;
};

}  // namespace dtlab::vor
