#pragma once
// The winding-number solid of a closed, self-intersecting triangle mesh: the region
// where its generalized winding number is at least 1/2 (Jacobson et al. 2013), as a
// surface. The mesh is autorefined with exact constructions (CGAL, EPECK) so that
// triangles meet only along shared edges; the self-intersection curves cut it into
// patches; each patch is kept when the winding number is >= 1/2 on exactly one of its
// sides, oriented with that side behind. Overlapping lobes become their union; inner
// sheets, inverted flaps and the insides of folds are dropped.
#include <cstddef>
#include <string>

#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct WindingSolid {
  TriangleMesh mesh;          // the kept faces, outward, vertices rounded to doubles
  std::size_t patches = 0;    // patches between self-intersection curves
  std::size_t kept = 0;       // patches kept as they were
  std::size_t reversed = 0;   // patches kept with their orientation reversed
  bool ok = false;            // false: see why
  std::string why;            // "autorefinement exceeded its time budget of 30 s", ...
};

// `mesh` must be closed and oriented per component (as after the repair's hole
// filling); the winding number is then an integer off the surface. `seconds` bounds the
// autorefinement.
WindingSolid winding_number_solid(const TriangleMesh& mesh, double seconds);

}  // namespace dtlab
