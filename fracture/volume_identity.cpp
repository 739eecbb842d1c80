#include "fracture/volume_identity.hpp"

#include "oracle/check/exact_volume.hpp"

namespace dtlab {

VolumeIdentity volume_identity(const FractureResult& r) {
  // One point list and one outward surface: every piece's triangles and the mesh's
  // reversed, so the enclosed signed volume is sum(pieces) - mesh, exactly.
  std::vector<Point3> points;
  std::vector<std::array<std::uint32_t, 3>> faces;
  double sum = 0;
  auto append = [&](const TriangleMesh& m, bool reversed) {
    const auto base = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), m.vertices.begin(), m.vertices.end());
    for (const auto& t : m.triangles)
      faces.push_back(reversed ? std::array<std::uint32_t, 3>{base + t[0], base + t[2], base + t[1]}
                               : std::array<std::uint32_t, 3>{base + t[0], base + t[1], base + t[2]});
  };
  for (const Piece& p : r.pieces) {
    append(p.geometry.mesh, false);
    sum += p.volume;
  }
  append(r.input, true);
  VolumeIdentity id;
  id.float_difference = sum - r.mesh_volume;
  id.exact_difference = exact_volume_sums(points, {}, faces).hull;
  // A nonzero exact sum rounds to zero only below the smallest double (coordinates
  // near 1e-100 or less); the fracture refuses no such mesh, so say so by the value.
  id.exact = id.exact_difference == 0;
  return id;
}

}  // namespace dtlab
