#pragma once
// The exact Voronoi checker: judges any tool's cells (voronoi_check/tool_cells.hpp)
// against the exact Voronoi neighbour relation of the sites
// (voronoi_check/voronoi_neighbors.hpp), clipped to a box. Proves or refutes, with
// witnesses: one cell per site (duplicated sites: one cell per set of copies, on any
// copy; neighbour ids of any copy count for the first), every face with positive area
// on the bisector of a Voronoi (Delaunay-complex) edge, no such edge whose face meets
// the box missing, cell vertices near the exact intersection of their faces' planes,
// cells closed and convex, volumes summing to the box volume.
//
// Floating-point tools cannot represent faces far below their rounding, so a missing
// or spurious face is `small` when its area is at most `small_face` times the sites'
// extent squared (its area: the exact face's clipped to the box in doubles when
// missing, the tool's when spurious), or when it is no wider than twice the ulp floor
// (area <= 2 e diameter, e below). Topology: exact (the exact neighbour sets),
// rounded (only small faces wrong), wrong (a larger face, or a cell, wrong).
//
// Every tolerance has an ulp floor (VoronoiCheckOptions::ulps): where the box is so
// narrow against its coordinates' magnitude that the relative bound lies below what
// doubles can hold (sites at 2.4e11 a few 1e-3 apart, or 2^-53 apart near 0.5), the
// bound is the one K ulps of the box's largest coordinate allow; the report says which
// one applied (VoronoiCheckReport::tolerances). Topology is exact either way.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "kernel/tetrahedralization.hpp"
#include "voronoi/box.hpp"
#include "voronoi/rounding_bound.hpp"
#include "voronoi_check/tool_cells.hpp"

namespace dtlab {

class VoronoiNeighbors;  // voronoi_check/voronoi_neighbors.hpp

enum class VoronoiDefect {
  missing_cell,        // a site (inside the box) with no cell
  extra_cell,          // a second cell for one site (or its copies), or a cell of no site
  missing_face,        // a Voronoi face meeting the box that the cell lacks (large)
  spurious_face,       // a face towards a site that is no Voronoi neighbour (large)
  small_missing_face,  // the same, at most small_face * extent^2
  small_spurious_face,
  degenerate_face,  // a face of a DT edge whose exact face has zero area (not wrong)
  bad_neighbor,     // a neighbour id that is no site
  vertex_off,       // a vertex farther than vertex_tolerance from its exact position
  not_convex,       // not closed, Euler != 2, or a vertex outside a face plane
  volume_mismatch,  // the cells' volumes do not sum to the box volume
};
inline constexpr int kVoronoiDefects = 11;
const char* voronoi_defect_name(VoronoiDefect d);

enum class Topology { exact, rounded, wrong };
const char* topology_name(Topology t);

// The whole answer: wrong-topology before volume-mismatch before bad-geometry (vertices
// off, cells not convex) before rounded-topology before exact-topology; crashed to
// out_of_memory are a peer's "no answer" verdicts (voronoi_check/voronoi_peers.hpp).
enum class VoronoiVerdict {
  exact_topology,
  rounded_topology,
  bad_geometry,
  volume_mismatch,
  wrong_topology,
  crashed,
  hung,
  refused,
  not_installed,
  out_of_memory,  // ended for lack of memory (oracle/peers/child_process.hpp's out_of_memory)
};
const char* voronoi_verdict_name(VoronoiVerdict v);

struct VoronoiWitness {
  VoronoiDefect kind;
  std::int64_t site = -1, neighbor = -1;  // input ids (neighbor: -1 when none)
  double size = 0;                        // face area / extent^2, vertex error / scale, ...
  std::string detail;
};

struct VoronoiCheckOptions {
  double small_face = 1e-9;        // of the sites' extent squared
  double vertex_tolerance = 1e-9;  // of the cells' scale (cell_scale, voronoi/voronoi.hpp)
  double convex_tolerance = 1e-9;  // of the cells' scale
  double volume_tolerance = 1e-9;  // relative to the box volume
  // The ulp floor K (0: none), in ulps u of the box's largest coordinate: a vertex is
  // off beyond max(vertex_tolerance * scale, K u) (max-norm); a vertex outside a face
  // plane beyond max(convex_tolerance * scale, what vertices within e = sqrt(3) K u
  // of a convex cell allow for that face's plane: rounded_plane_tolerance,
  // voronoi/cell_check.hpp); the volumes' sum off beyond max(volume_tolerance * box
  // volume, the sum over cells of volume_rounding_bound at e), the most the volumes can
  // move when every vertex is within e.
  double ulps = kRoundingUlps;
  std::size_t witnesses_per_kind = 16;
  // Threads (0: all hardware threads) of every stage: the DT, its tables, the relation
  // and the geometry, which with 2+ threads and a DT to build runs on half of them beside
  // the build. The report is the same for any count.
  unsigned threads = 1;
  // The sites' Delaunay tetrahedralization by exact predicates with symbolic
  // perturbation (compute_voronoi's with keep_dt), read instead of built: the same
  // tets (the perturbed DT is unique), so the same report. Null: built here.
  std::shared_ptr<const Tetrahedralization> dt;
  // The sites' exact relation (DT and its tables, voronoi_relation below), built once and
  // shared by the checks of several tools' cells of the same sites: then neither is
  // built (seconds_dt and seconds_tables 0). Null: built here (from `dt` when given).
  std::shared_ptr<const VoronoiNeighbors> relation;
};

// A tolerance as applied: its value (in the unit of the number it bounds, see each use)
// and whether the ulp floor was the larger bound.
struct AppliedTolerance {
  double value = 0;
  bool ulps = false;
};

struct VoronoiTolerances {
  double ulp = 0;                   // one ulp u of the box's largest coordinate magnitude
  double floor_distance = 0;        // e = sqrt(3) K u: the ulp floor as a Euclidean distance
  AppliedTolerance vertex;          // of the cells' scale (as max_vertex_error)
  AppliedTolerance convex;          // of the cells' scale (ulps: some face's was the floor's, larger)
  AppliedTolerance small_face;      // of the extent squared (as largest_small_face; ulps: a face no wider than 2 e was small only by that)
  AppliedTolerance volume;          // relative to the box volume (as volume_error)
  double surface = 0;               // the fan triangles' area of all cells, when the volume floor was computed
};

struct VoronoiCheckReport {
  std::array<std::uint64_t, kVoronoiDefects> counts{};
  std::vector<VoronoiWitness> witnesses;
  Topology topology = Topology::exact;
  VoronoiVerdict verdict = VoronoiVerdict::exact_topology;
  double largest_wrong_face = 0;                            // / extent^2, over missing_face and spurious_face
  double largest_small_face = 0;                            // / extent^2, over the small ones
  double max_vertex_ulps = 0;                               // ulps of the box's largest coordinate
  double max_vertex_error = 0;                              // / the cells' scale
  double volume_sum = 0, box_volume = 0, volume_error = 0;  // error relative to the box volume
  VoronoiTolerances tolerances;
  std::uint64_t sites = 0, distinct_sites = 0, cells = 0, faces = 0, vertices = 0;
  std::uint64_t voronoi_edges = 0;     // directed Voronoi neighbour pairs (positive faces)
  std::uint64_t degenerate_edges = 0;  // directed DT edges with a zero-area face
  // Wall time of the stages: the DT, its tables (flat and cospherical tets, hull
  // edges), the neighbour sets against the exact ones, the cells' shape and vertices;
  // and of the whole check. With the geometry beside the DT build (threads) the two
  // overlap: the stages may sum to more than `seconds`.
  double seconds_dt = 0, seconds_tables = 0, seconds_relation = 0, seconds_geometry = 0, seconds = 0;
  std::uint64_t count(VoronoiDefect d) const { return counts[static_cast<int>(d)]; }
};

// Throws std::invalid_argument for non-finite sites, fewer than 4 distinct or coplanar
// sites, or an empty or non-finite box. A cell of no site is an extra_cell, not an error.
VoronoiCheckReport check_voronoi(std::span<const Point3> sites, const vor::Box& box, const ToolCells& cells,
                                 const VoronoiCheckOptions& options = {});

// The exact relation check_voronoi reads (from options.dt when given), to be shared
// through VoronoiCheckOptions::relation. Throws as check_voronoi for the sites.
std::shared_ptr<const VoronoiNeighbors> voronoi_relation(std::span<const Point3> sites,
                                                         const VoronoiCheckOptions& options = {});

// "missing-face 3, small-missing-face 1": the non-zero counts.
std::string voronoi_counts_text(const VoronoiCheckReport& r);

}  // namespace dtlab
