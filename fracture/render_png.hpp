#pragma once
// PNG views drawn without Python: orthographic from azimuth 35 degrees, elevation 25
// degrees (z up), z-buffer, Lambert shading, back faces culled (closed, outward
// surfaces), the object filling the frame; stored (uncompressed) deflate blocks.
//  - `fracture --png FILE`: the exploded pieces, mesh faces in the `outer` colour and
//    cut faces in the `cut` colour of pieces.mtl;
//  - `voronoi --png FILE` (and `make demo`): the cells, each shrunk towards its
//    centroid and in its own colour.
#include <array>
#include <string>
#include <vector>

#include "fracture/fracture.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

inline constexpr std::array<double, 3> kOuterColour{0.70, 0.72, 0.78};
inline constexpr std::array<double, 3> kCutColour{0.85, 0.35, 0.20};

struct ViewTriangle {
  std::array<Point3, 3> corners;  // counter-clockwise seen from outside
  std::array<double, 3> colour;   // RGB in [0, 1] before shading
};

void write_view_png(const std::string& path, const std::vector<ViewTriangle>& triangles, int width = 900,
                    int height = 900);
void write_exploded_png(const std::string& path, const FractureResult& r, double explode, int width = 900,
                        int height = 900);
// Every non-empty cell scaled by `shrink` about its centroid (gaps between neighbours).
void write_cells_png(const std::string& path, const VoronoiDiagram& vd, double shrink = 0.8, int width = 900,
                     int height = 900);

}  // namespace dtlab
