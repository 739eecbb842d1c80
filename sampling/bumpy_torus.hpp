#pragma once
// The built-in mesh: a torus whose tube radius is modulated by bumps,
//   r(u, v) = minor * (1 + bump * sin(ku u) sin(kv v)),
// around the z axis, closed, consistently oriented outward, and non-convex twice over
// (the hole and the bumps). Used when no mesh file is given.
#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct BumpyTorusParams {
  double major = 1.0;   // centre of the tube to the z axis
  double minor = 0.4;   // mean tube radius; minor * (1 + bump) < major keeps it embedded
  double bump = 0.25;   // relative bump height, in [0, 1)
  int ku = 5, kv = 3;   // bump frequencies around the ring and around the tube
  int nu = 96, nv = 48; // grid resolution around the ring and around the tube
};

TriangleMesh make_bumpy_torus(const BumpyTorusParams& p = {});

// Volume of the smooth surface: integrating rho (major + rho cos v) over the tube gives
//   major * minor^2 * pi^2 * (2 + bump^2 / 2), since the cross terms integrate to zero.
double bumpy_torus_volume(const BumpyTorusParams& p = {});

}  // namespace dtlab
