#pragma once
// Bringing another tool's tets into dtlab's orientation (orient3d > 0) before the check.
//
//   positive    as given (dtlab in memory; CGAL's cells as the oracle returns them)
//   negative    every tet swapped (TetGen's .ele order)
//   consistent  one handedness for all, whichever the exact signs show more often; the
//               minority then shows up as `inverted`
//   any         each tet by its own exact sign: the tets as an unoriented set, as
//               scipy.spatial.Delaunay / Qhull give them (their 3D simplices come in
//               both orders); flat tets stay flat and are reported as such
#include <cstdint>
#include <string>

#include "kernel/tetrahedralization.hpp"

namespace dtlab::python {

struct Orientation {
  std::string handedness;     // "positive" or "negative" (consistent); the mode otherwise
  std::uint64_t swapped = 0;  // tets whose first two vertices were swapped
};

// `mode` must have passed check_orientation_mode. Signs are exact (FilteredExact).
Orientation orient_tets(Tetrahedralization& t, const std::string& mode);
// Throws ValueError unless mode is one of the four above (call it with the GIL held).
void check_orientation_mode(const std::string& mode);

}  // namespace dtlab::python
