#pragma once
// Turning a broken triangle mesh into a solid a boolean accepts (`fracture --repair`,
// `dtlab mesh repair`): merge duplicate vertices, drop degenerate and repeated
// triangles, split non-manifold vertices and orient the faces consistently, stitch
// borders, fill holes, resolve self-intersections (autorefinement keeping the outer
// surface), orient every shell to bound a volume. CGAL (PMP) lives in mesh_repair.cpp.
#include <string>
#include <vector>

#include "sampling/mesh_report.hpp"

namespace dtlab {

struct RepairStep {
  std::string what;     // "merged duplicate vertices", "filled holes", ...
  std::size_t count = 0;  // vertices merged, holes filled, ...
  std::string detail;   // e.g. "added 37 triangles"
};

struct RepairResult {
  TriangleMesh mesh;              // the repaired mesh (or the last state reached)
  MeshReport before, after;       // the one diagnosis, before and after
  std::vector<RepairStep> steps;  // only the steps that changed something
  bool solid() const { return after.solid(); }
};

// Never throws for a bad mesh: what cannot become a solid has after.solid() == false
// and after.why_not_solid() names what remains.
RepairResult repair_mesh(const TriangleMesh& mesh);

}  // namespace dtlab
