#include "voronoi_check/tet_spheres.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/parallel_for.hpp"
#include "voronoi_check/vertex_filter.hpp"

// Compiled with -ffp-contract=off, as vertex_filter.cpp.

namespace dtlab {

std::vector<TetSphere> tet_spheres(std::span<const Point3> p, std::span<const Tet> tets, unsigned threads) {
  std::vector<TetSphere> out(tets.size());
  constexpr std::size_t kLanes = BoundBatch::kLanes;
  parallel_chunks(tets.size(), threads, 4096, [&](std::size_t b, std::size_t e, unsigned) {
    // The planes of kLanes tets at a time into one batch; where they meet, all at once.
    thread_local BoundBatch batch;
    thread_local std::vector<std::uint32_t> lane_tet;
    thread_local std::vector<PlanesMeet> meet;
    thread_local std::vector<char> found;
    for (std::size_t t0 = b; t0 < e; t0 += kLanes) {
      const std::size_t t1 = std::min(e, t0 + kLanes);
      batch.start();
      lane_tet.clear();
      for (std::size_t t = t0; t < t1; ++t) {
        const Tet& q = tets[t];
        out[t].error = INFINITY;
        if (q[0] >= p.size() || q[1] >= p.size() || q[2] >= p.size() || q[3] >= p.size()) continue;
        const Point3& o = p[q[0]];
        FilterPlane pl[3];
        for (int k = 0; k < 3; ++k) bisector_plane(p[q[k + 1]], o, pl[k]);
        batch.add(o, o, pl[0], pl[1], pl[2]);
        lane_tet.push_back(static_cast<std::uint32_t>(t));
      }
      meet.resize(lane_tet.size());
      found.resize(lane_tet.size());
      batch.meets(meet, found);
      for (std::size_t k = 0; k < lane_tet.size(); ++k) {
        if (!found[k]) continue;
        TetSphere& s = out[lane_tet[k]];
        const Point3& o = p[tets[lane_tet[k]][0]];
        // The centre o + x: one rounding more per coordinate.
        double err = 0;
        const double oc[3] = {o.x, o.y, o.z};
        for (int j = 0; j < 3; ++j) {
          s.c[j] = oc[j] + meet[k].x[j];
          err = std::max(err, meet[k].error[j] + 0x1.02p-53 * std::abs(s.c[j]));
        }
        if (std::isfinite(err)) s.error = err;
      }
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
