#pragma once
// Exact volumes. With every coordinate written m * 2^k (m a 53-bit integer), all
// coordinates are scaled by one common power 2^-kmin into integers, so an
// orient3d value (6 times a signed volume) is an integer times 2^(3 kmin) and
// sums of them are exact GMP integer sums: no rational arithmetic, no rounding.
#include <array>
#include <span>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct VolumeSums {
  bool equal = false;         // exact comparison
  double tets = 0, hull = 0;  // the exact sums, rounded (volumes, not 6x)
};

// tets: sum of orient3d over tets. hull: sum over outward boundary facets (x,y,z)
// of orient3d(x,y,z,origin), the volume they enclose by the divergence theorem.
// With no tets, only the hull sum is computed (`equal` is then false).
VolumeSums exact_volume_sums(std::span<const Point3> points, std::span<const Tet> tets,
                             std::span<const std::array<std::uint32_t, 3>> boundary);

}  // namespace dtlab
