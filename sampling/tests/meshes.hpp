#pragma once
// Small meshes the sampler tests share.
#include "sampling/bumpy_torus.hpp"

namespace dtlab::test {

// An L-shaped prism (concave), outward oriented: the L of unit squares
// {[0,2]x[0,1]} + {[0,1]x[1,2]} extruded along z over [0,1]. Most of its faces lie on
// its bounding box, where the ray method's rays start.
inline TriangleMesh l_prism() {
  TriangleMesh m;
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (double z : {0.0, 1.0})
    for (const auto& p : xy) m.vertices.push_back({p[0], p[1], z});
  // Bottom (z = 0, seen from below) and top, as fans of the two convex pieces.
  const std::uint32_t bottom[4][3] = {{0, 2, 1}, {0, 3, 2}, {0, 5, 4}, {0, 4, 3}};
  for (const auto& t : bottom) {
    m.triangles.push_back({t[0], t[1], t[2]});
    m.triangles.push_back({t[0] + 6, t[2] + 6, t[1] + 6});
  }
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    m.triangles.push_back({i, j, j + 6});
    m.triangles.push_back({i, j + 6, i + 6});
  }
  return m;
}

// The bumpy torus with every 7th triangle removed (14% of the faces).
inline TriangleMesh holey_torus() {
  TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  TriangleMesh h = m;
  h.triangles.clear();
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (t % 7 != 3) h.triangles.push_back(m.triangles[t]);
  return h;
}

}  // namespace dtlab::test
