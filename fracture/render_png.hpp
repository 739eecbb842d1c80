#pragma once
// `fracture --png FILE`: the exploded view drawn without Python. Orthographic view from
// azimuth 35 degrees, elevation 25 degrees (z up), z-buffer, Lambert shading; mesh faces
// in the `outer` colour and cut faces in the `cut` colour of pieces.mtl; the exploded
// object fills the frame. The PNG is written with stored (uncompressed) deflate blocks.
#include <string>

#include "fracture/fracture.hpp"

namespace dtlab {

void write_exploded_png(const std::string& path, const FractureResult& r, double explode, int width = 900,
                        int height = 900);

}  // namespace dtlab
