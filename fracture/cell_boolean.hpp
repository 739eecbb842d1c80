#pragma once
// The boolean engine of the fracture: a closed triangle mesh intersected with one
// convex cell at a time by CGAL's corefinement (Polygon Mesh Processing), exact
// predicates and constructions (EPECK). CGAL stays inside cell_boolean.cpp (one translation unit).
#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sampling/triangle_mesh.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

// A closed piece: triangles oriented outward; cut[t] = 1 for triangles on the cell's
// boundary (interior faces of the fractured object), with the neighbour site (or wall)
// whose bisector they lie on in cut_tag[t].
struct PieceMesh {
  TriangleMesh mesh;
  std::vector<char> cut;
  std::vector<std::int32_t> cut_tag;
  bool boolean_skipped = false;  // the cell lies inside the mesh: no corefinement ran
};

// A corefinement that ran past its time budget (a named failure, never a hang).
struct BooleanTimeout : std::runtime_error {
  explicit BooleanTimeout(double seconds)
      : std::runtime_error("boolean exceeded its time budget of " + std::to_string(seconds) + " s"), seconds(seconds) {}
  double seconds;
};

class MeshClipper {
 public:
  // Throws std::invalid_argument with a reason if `mesh` is not a closed, manifold
  // triangle mesh (duplicate vertices are merged first; an inward orientation is
  // flipped). Self-intersections are not tested here: check with analyze_mesh first.
  // With MeshCheck::solid the caller has proven the mesh a solid (analyze_mesh: closed,
  // manifold, oriented), and CGAL's own soup test, ~9% of a bunny00 run, is skipped.
  enum class MeshCheck { full, solid };
  explicit MeshClipper(const TriangleMesh& mesh, MeshCheck check = MeshCheck::full);
  ~MeshClipper();
  MeshClipper(const MeshClipper&) = delete;
  MeshClipper& operator=(const MeshClipper&) = delete;

  // Seconds one corefinement may take before it throws BooleanTimeout (0: no limit).
  void set_time_budget(double seconds);
  // Called after each boolean of intersect_all (cells done, cells in all), one call at
  // a time whatever the threads: the progress of a long fracture.
  void set_progress(std::function<void(std::size_t, std::size_t)> progress);

  // Exact tiling: intersect_all also sums the exact signed volumes of the pieces as
  // the corefinement built them (exact constructions, before rounding to doubles).
  void set_exact_tally(bool on);
  struct ExactTally {
    bool holds = false;     // sum of the exact piece volumes == the mesh's exact volume
    double difference = 0;  // that difference, rounded
  };
  // After intersect_all with the tally on (every cell's piece, cells with no piece add 0).
  ExactTally exact_tally() const;

  // The repaired input (merged vertices, outward orientation).
  const TriangleMesh& mesh() const;
  double volume() const;
  // Mesh ∩ cell; thread-safe (each call copies what it modifies).
  PieceMesh intersect(const VoronoiCell& cell) const;
  // Mesh ∩ cell for every cell, the same pieces as `intersect` but far fewer mesh
  // triangles per corefinement: the cells are split in two halves recursively (along
  // the longest axis of their sites' spread) and each half first cuts the mesh down to
  // the box around its cells, so a cell meets only the mesh near it. Halves run on
  // up to `threads` threads (0: all hardware threads).
  // Each cell is first tried alone against the band of mesh triangles near its surface
  // (those strictly inside it copied, the rest left out: a corefinement of a few
  // thousand triangles instead of the whole mesh), cells on up to `threads` threads;
  // where a patch touches the other surface in a face (coplanar contact) or the result
  // is not closed, the cell goes to the box splits above. The pieces do not depend on
  // the thread count.
  std::vector<PieceMesh> intersect_all(const std::vector<VoronoiCell>& cells, unsigned threads = 0) const;
  // Off: every cell through the box splits (the comparison of the tests).
  void set_band_booleans(bool on);
  struct ClipStats {
    std::size_t band = 0, boxes = 0;  // cells of the last intersect_all done each way
  };
  ClipStats last_stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dtlab
