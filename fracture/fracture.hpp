#pragma once
// Voronoi fracture: sites sampled inside a closed mesh, their Voronoi cells (clipped
// to the mesh's box), each cell intersected with the mesh into one closed piece.
#include <array>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "fracture/cell_boolean.hpp"
#include "fracture/mesh_repair.hpp"
#include "fracture/site_sources.hpp"
#include "sampling/mesh_sampler.hpp"

namespace dtlab {

struct FractureOptions {
  std::size_t pieces = 20;
  SiteOptions sites;                 // where the top-level sites come from (recursion samples)
  bool island_split = true;          // each connected chunk of a cell's piece is a piece
  Point3 cell_scale{1, 1, 1};        // anisotropic cells: distances measured after dividing by this
  SampleMethod sampler = SampleMethod::winding;
  bool blue_noise = false;
  std::uint64_t seed = 1;
  double margin = 0;                 // gap between neighbouring pieces (absolute length)
  std::string_view margin_name = "--gap";  // how the caller names `margin` in messages (Python: margin)
  unsigned threads = 0;              // 0: all hardware threads
  std::vector<std::size_t> recurse;  // top-level pieces to fracture again
  std::size_t recurse_pieces = 4;    // pieces each of those is split into
  bool repair = false;               // repair_mesh first (else a mesh that is not solid is refused)
  bool exact_tiling = false;         // prove the tiling exactly (not with a gap): FractureResult::exact_tiling
  double boolean_seconds = 30;       // time budget of one corefinement (0: none); past it, a named failure
  std::function<void(std::size_t, std::size_t)> progress;  // booleans done, in all (per level)
};

struct Piece {
  PieceMesh geometry;
  double volume = 0;
  Point3 centroid{0, 0, 0};
  // Inertia tensor about the centroid for unit density, row-major 3x3 (symmetric).
  std::array<double, 9> inertia{};
  double interior_area = 0;              // area of the cut faces
  std::vector<std::uint32_t> neighbors;  // pieces sharing a cut face with this one
  Point3 site{0, 0, 0};
  int parent = -1;                       // top-level piece it was split from (recursion)
  std::int64_t site_index = -1;          // its site among its level's sites
  std::int64_t island = 0;               // its place among its site's islands (largest first)
  std::size_t site_islands = 1;          // how many islands its site's cell cut off
};

struct FractureResult {
  MeshReport report;                // the input's diagnosis (before any repair)
  std::vector<RepairStep> repairs;  // what --repair changed (empty without it)
  TriangleMesh input;        // merged, outward-oriented (repaired) input
  double mesh_volume = 0;
  std::vector<Piece> pieces;
  std::size_t booleans = 0, skipped = 0;
  // Every site of every level is accounted for: it gave pieces, repeats an earlier site of
  // its level (its cell is empty: one piece for the two), or its cell misses the mesh.
  std::size_t sites = 0, duplicate_sites = 0, sites_without_piece = 0;
  double seconds_sampling = 0, seconds_voronoi = 0, seconds_boolean = 0;
  // The exact tiling, at every level: the pieces' exact volumes as the corefinement
  // built them (before rounding to doubles) sum to their solid's exact volume.
  bool exact_tiling_checked = false, exact_tiling = false;
  double exact_tiling_difference = 0;  // the largest difference of a level, rounded
  double seconds_exact = 0;
};

// Throws std::invalid_argument naming the problems (MeshReport::why_not_solid) when the
// mesh is not a solid, or with options.repair when the repair cannot make it one;
// std::runtime_error for a named failure of a boolean (time budget).
FractureResult fracture_mesh(const TriangleMesh& mesh, const FractureOptions& options);

// Signed volume, centroid, inertia tensor and interior (cut) area of a piece.
void measure_piece(Piece& p);

}  // namespace dtlab
