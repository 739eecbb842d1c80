#pragma once
// The Voronoi diagram of a point set, every cell clipped to a box.
//
// Method: an interior site's cell is read off the DT directly (voronoi/dual_cell.hpp:
// circumcentres computed once per tet, faces from the rings of tets around each
// Delaunay edge, coincident centres of cospherical tets merged), then clipped by the
// box walls it crosses. Hull sites (unbounded cells), doubtful duals (badly
// conditioned centres, merges that do not give a polytope, tiny edges) and `shrink`
// use the general engine instead: the box clipped by the bisector half-spaces of the
// site's Delaunay neighbours, nearest first (voronoi/convex_cell.hpp), where
// cospherical planes collapse inside one tolerance band. Cells run in parallel.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/build.hpp"
#include "voronoi/cell_arena.hpp"
#include "voronoi/convex_cell.hpp"

namespace dtlab {

struct VoronoiOptions {
  std::optional<vor::Box> box;      // default: the bounding box grown by `margin` per side
  double margin = 0.1;              // relative to the box extent
  double tolerance = 1e-12;         // relative to cell_scale (the box diagonal, or the sites')
  double shrink = 0;                // move each bisector this far towards its site
  PredicateSpec predicates{"adaptive", 1e-12, false, true};
  BuildOptions build;               // insertion order and seed of the Delaunay build
  unsigned threads = 0;             // cells in parallel; 0: all hardware threads
  // Keep the Delaunay tetrahedralization in VoronoiDiagram::dt when the predicates are
  // exact with symbolic perturbation (adaptive or exact, perturb): the exact Voronoi
  // checker (voronoi_check/) then reads the relation from it instead of building it.
  bool keep_dt = false;
};

// One cell: views into arrays owned by its diagram (VoronoiDiagram::storage), valid
// while the diagram or a copy of it lives. All cells' arrays lie in a few flat blocks
// (no allocation per cell).
struct VoronoiCell {
  std::span<const Point3> vertices;
  std::span<const std::uint32_t> face_offsets;   // face f: face_vertices[off[f] .. off[f+1])
  std::span<const std::uint32_t> face_vertices;  // counter-clockwise seen from outside
  std::span<const std::int32_t> face_neighbor;   // site id, or -1..-6 for the box walls
  double volume = 0;
  Point3 centroid{0, 0, 0};
  std::int64_t duplicate_of = -1;                // a repeated site gets an empty cell

  std::size_t face_count() const { return face_neighbor.size(); }
  std::size_t edge_count() const { return face_vertices.size() / 2; }
  std::vector<std::uint32_t> neighbors() const;  // sorted site ids (walls left out)
};

// A VoronoiCell over arrays owned elsewhere (no volume, centroid or duplicate set), for
// the cell checks and cell_volume.
VoronoiCell cell_view(std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
                      std::span<const std::uint32_t> face_vertices, std::span<const std::int32_t> face_neighbor);
inline VoronoiCell cell_view(const vor::ConvexCell& c) {
  return cell_view(c.vertices(), c.face_offsets(), c.face_vertices(), c.face_tags());
}

struct VoronoiDiagram {
  vor::Box box;
  double scale = 0;  // cell_scale(box, sites): what VoronoiOptions::tolerance and the cell checks are relative to
  std::vector<Point3> sites;
  std::vector<VoronoiCell> cells;
  std::shared_ptr<const std::vector<vor::CellArena>> storage;  // owns the cells' arrays
  std::shared_ptr<const Tetrahedralization> dt;                // with VoronoiOptions::keep_dt (exact predicates only)
  std::size_t tets = 0;
  std::size_t clipped = 0;          // cells built by clipping (hull sites, doubtful duals, shrink)
  std::size_t box_clipped = 0;      // dual cells then clipped by the box walls
  std::size_t exact_clipped = 0;    // clipped cells redone exactly (vor::exact_clip_cell)
  double seconds_dt = 0, seconds_cells = 0;  // wall time
  double cpu_seconds_cells = 0;              // process CPU time of the cell phase (all threads)

  // Cell i may be empty without a defect: its site lies outside the closed box (its cell
  // need not meet the box); one inside always has volume.
  bool may_be_empty(std::size_t i) const { return i < sites.size() && !box.contains(sites[i]); }
};

// Delaunay neighbours per vertex in compressed rows: neighbours of v are
// adj[off[v] .. off[v+1]), sorted by distance to v.
struct Adjacency {
  std::vector<std::uint32_t> off, adj;
};
Adjacency delaunay_neighbors(const Tetrahedralization& dt);
// The tets around each vertex in compressed rows: tets containing v are
// star[off[v] .. off[v+1]), ascending.
void vertex_stars(std::size_t n, std::span<const Tet> tets, std::vector<std::uint32_t>& off,
                  std::vector<std::uint32_t>& star);

vor::Box default_box(std::span<const Point3> sites, double margin);

// compute_voronoi's refusal of sites whose cells doubles cannot hold (a face far below
// the cells' scale squared lost in rounding, so no rounded cell is closed and convex):
// bad input for these sites (the CLI: FILE:0: reason, exit 2; Python: ValueError), not
// a crash nor a wrong cell.
class UnrepresentableCell : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The length the cells' relative tolerances are of (the clip band, choose_cell's and
// `dtlab voronoi --check`'s cell checks): the box's diagonal, or the diagonal of the
// sites' default box (margin 0.1) where that is shorter. The cells' vertices, edges and
// faces lie at the sites' spacing; a box far larger than the sites only stretches the
// hull cells, and tolerances of its diagonal merge real vertices (a band of 1e-12 of a
// box of +-1e10 around the unit cube is 0.035) or call real edges zero-length (1e-9 at
// --margin 1e6: 3.5e-3). The rounding bounds stay the box's (voronoi/rounding_bound.hpp):
// a vertex far out is as far off as its coordinates' ulps, which the clip's error bounds
// send to the exact fallback.
double cell_scale(const vor::Box& box, std::span<const Point3> sites);

// The cell of site i: `cell` is reset to the box and clipped (in coordinates
// relative to the site, then translated back), in a band of `tol` times `scale` (a
// length: cell_scale, or the box diagonal). `shrink` > 0 moves every bisector
// plane that distance towards the site (a gap of 2*shrink between neighbours).
// Without shrink, a cell whose double clip was ambiguous is redone with exact signs
// (voronoi/exact_cell.hpp); returns whether it was.
bool compute_cell(vor::ConvexCell& cell, std::span<const Point3> sites, std::uint32_t i,
                  std::span<const std::uint32_t> neighbors, const vor::Box& box, double tol, double scale,
                  double shrink = 0);

// Throws std::invalid_argument on an empty input; fewer than four
// or coplanar sites fall back to all-pairs clipping (quadratic, fine for small inputs).
VoronoiDiagram compute_voronoi(std::span<const Point3> sites, const VoronoiOptions& options = {});

}  // namespace dtlab
