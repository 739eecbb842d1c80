#pragma once
// Each tet's circumcentre in doubles with a certified error bound (the double filter
// of vertex_filter.hpp on the three bisectors of its first vertex): two tets sharing a
// facet have the same circumsphere exactly when their exact centres coincide, so
// centres farther apart than their bounds prove the facet not cospherical without an
// insphere, and a finite bound proves the tet not flat without an orient3d.
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct TetSphere {
  double c[3];   // the centre, rounded
  double error;  // max-norm bound on its error; infinite when not certified (flat, ill-conditioned)
};

// One per tet, on `threads` threads.
std::vector<TetSphere> tet_spheres(std::span<const Point3> points, std::span<const Tet> tets, unsigned threads);

// True only when the two exact centres differ (false: not known).
bool surely_apart(const TetSphere& a, const TetSphere& b);

}  // namespace dtlab
