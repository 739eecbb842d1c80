#include "voronoi_check/tet_spheres.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/parallel_for.hpp"
#include "voronoi_check/vertex_filter.hpp"

// Compiled with -ffp-contract=off, as vertex_filter.cpp.

namespace dtlab {

std::vector<TetSphere> tet_spheres(std::span<const Point3> p, std::span<const Tet> tets, unsigned threads) {
  std::vector<TetSphere> out(tets.size());
  const vor::Box no_walls{};  // the planes are bisectors only
  parallel_chunks(tets.size(), threads, 4096, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t t = b; t < e; ++t) {
      const Tet& q = tets[t];
      const Point3& o = p[q[0]];
      TetSphere& s = out[t];
      s.error = INFINITY;
      FilterPlane pl[3];
      bool ok = true;
      for (int k = 0; k < 3; ++k)  // an id beyond int32 would read as a wall: left uncertified
        ok = ok && q[k + 1] <= 0x7FFFFFFFu && filter_plane(static_cast<std::int32_t>(q[k + 1]), p, o, no_walls, pl[k]);
      PlanesMeet m;
      if (!ok || !planes_meet(pl[0], pl[1], pl[2], m)) continue;
      // The centre o + x: one rounding more per coordinate.
      double err = 0;
      const double oc[3] = {o.x, o.y, o.z};
      for (int j = 0; j < 3; ++j) {
        s.c[j] = oc[j] + m.x[j];
        err = std::max(err, m.error[j] + 0x1.02p-53 * std::abs(s.c[j]));
      }
      if (std::isfinite(err)) s.error = err;
    }
  });
  return out;
}

bool surely_apart(const TetSphere& a, const TetSphere& b) {
  // |fl(a - b)| <= |a - b| (1 + u); the sum of the bounds is rounded up by the factor.
  const double bound = (a.error + b.error) * (1 + 0x1p-50);
  for (int j = 0; j < 3; ++j)
    if (std::abs(a.c[j] - b.c[j]) * (1 - 0x1p-50) > bound) return true;
  return false;
}

}  // namespace dtlab
