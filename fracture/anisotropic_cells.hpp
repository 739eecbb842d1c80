#pragma once
// Anisotropic Voronoi cells (`--cell-scale SX,SY,SZ`, e.g. wood grain): the cells of
// the distance |diag(1/s) (x - y)|, i.e. the ordinary Voronoi diagram of the sites
// divided by s, mapped back by s. An affine map keeps cells convex and neighbours'
// shared faces shared (the same vertices mapped the same way), so the cells still
// tile the box and the pieces the mesh.
#include <vector>

#include "voronoi/voronoi.hpp"

namespace dtlab {

struct ScaledCells {
  VoronoiDiagram diagram;  // its cells' vertices point into `vertices`
  std::vector<std::vector<Point3>> vertices;
};

// `options.box` (required) and `options.shrink` are in mesh units; the shrink applies
// in the scaled space. Throws std::invalid_argument unless every scale is positive.
ScaledCells anisotropic_voronoi(const std::vector<Point3>& sites, VoronoiOptions options, const Point3& scale);

}  // namespace dtlab
