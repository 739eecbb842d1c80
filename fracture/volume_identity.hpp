#pragma once
// The volume identity of a fracture, sum(piece volumes) = mesh volume, in floating
// point and exactly: the signed volumes of the written (double) coordinates summed in
// integer arithmetic (oracle/check/exact_volume.hpp), no rounding anywhere.
#include "fracture/fracture.hpp"

namespace dtlab {

struct VolumeIdentity {
  double float_difference = 0;  // sum of the pieces' double volumes - the mesh's
  double exact_difference = 0;  // the same difference computed exactly, then rounded
  bool exact = false;           // the exact difference is zero
  double relative(double d, double mesh_volume) const { return mesh_volume != 0 ? d / mesh_volume : d; }
};

// Pieces of r against r.input. Only meaningful without a gap (which removes volume).
VolumeIdentity volume_identity(const FractureResult& r);

}  // namespace dtlab
