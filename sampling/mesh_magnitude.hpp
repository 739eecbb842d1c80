#pragma once
// Whether a double can measure a mesh: its area, volume and extent finite (not
// overflowing) and its area and volume not underflowing (a tet of side 1e-110 has a
// volume of 1e-330, below the doubles' normal range: no sampler can weigh it).
#include <string>

#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct MeshMagnitude {
  bool overflow = false;          // area, volume or extent beyond a double
  bool area_underflow = false;    // the area is below the normal doubles (or 0), the mesh's shape is not
  bool volume_underflow = false;  // the same for the signed volume
};

MeshMagnitude measure_magnitude(const TriangleMesh& mesh, double area, double volume);

// "" when the measures a sampler needs (the area for surface points, else the volume)
// are doubles, else the reason ("coordinates too large: ..." / "coordinates too small: ...").
std::string magnitude_problem(const MeshMagnitude& m, bool surface_only);

}  // namespace dtlab
