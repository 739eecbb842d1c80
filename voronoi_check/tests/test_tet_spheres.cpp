// The tables' circumcentre filter (voronoi_check/tet_spheres.hpp): every certified
// centre lies within its bound of the exact (GMP) centre, so centres called apart are
// apart, on uniform sites and on the cospherical, lattice and badly conditioned
// families where many tets share one exact centre.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "fuzz/families.hpp"
#include "kernel/build.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/exact_centre.hpp"
#include "voronoi_check/tet_spheres.hpp"
#include "voronoi_check/vertex_filter.hpp"

using namespace dtlab;

TEST_CASE("tet spheres: certified centres hold the exact ones; apart means apart", "[tet-spheres]") {
  std::size_t certified = 0, shared = 0;
  for (const char* name : {"uniform", "lattice", "cospherical", "lattice_subset", "clustered", "near_degenerate",
                           "extreme_scale", "moment_curve"}) {
    const fuzz::Family* f = fuzz::find_family(name);
    REQUIRE(f);
    const auto pts = f->generate(200, 3);
    BuildOptions bo;
    bo.count_stages = false;
    BuildResult r = build_delaunay(pts, PredicateSpec{"adaptive", 0, false, true}, bo);
    if (r.failure) continue;
    const auto& tets = r.mesh.tets;
    const std::vector<TetSphere> s = tet_spheres(pts, tets, 2);
    std::vector<ExactPoint> exact(tets.size());
    for (std::size_t t = 0; t < tets.size(); ++t) {
      const Tet& q = tets[t];
      if (!std::isfinite(s[t].error)) continue;
      ++certified;
      exact[t] = exact_circumcentre(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]]);
      INFO(name << " tet " << t);
      for (int j = 0; j < 3; ++j) REQUIRE(abs(mpq_class(s[t].c[j]) - exact[t][j]) <= mpq_class(s[t].error));
    }
    // Pairs of tets around one vertex: apart only when the exact centres differ.
    std::vector<std::uint32_t> off, star;
    vertex_stars(pts.size(), tets, off, star);
    for (std::size_t v = 0; v + 1 < off.size(); ++v)
      for (auto i = off[v]; i < off[v + 1]; ++i)
        for (auto j = i + 1; j < off[v + 1]; ++j) {
          const auto a = star[i], b = star[j];
          if (!std::isfinite(s[a].error) || !std::isfinite(s[b].error)) continue;
          const bool same = exact[a] == exact[b];
          shared += same;
          INFO(name << " tets " << a << ", " << b);
          if (same) REQUIRE_FALSE(surely_apart(s[a], s[b]));
        }
  }
  CHECK(certified > 1000);
  CHECK(shared > 100);  // the lattices and spheres do test coincident centres
}

TEST_CASE("tet spheres: the batched centres are the scalar filter's, bit for bit", "[tet-spheres]") {
  const vor::Box no_walls{};
  std::size_t compared = 0, certified = 0;
  for (const char* name : {"uniform", "lattice", "cospherical", "near_degenerate", "extreme_scale", "moment_curve"}) {
    const auto pts = fuzz::find_family(name)->generate(700, 5);
    BuildOptions bo;
    bo.count_stages = false;
    BuildResult r = build_delaunay(pts, PredicateSpec{"adaptive", 0, false, true}, bo);
    if (r.failure) continue;
    const auto& tets = r.mesh.tets;
    for (unsigned threads : {1u, 3u}) {
      const std::vector<TetSphere> s = tet_spheres(pts, tets, threads);
      REQUIRE(s.size() == tets.size());
      for (std::size_t t = 0; t < tets.size(); ++t) {
        // The definition: the three bisectors of the first vertex, planes_meet, the centre o + x.
        const Tet& q = tets[t];
        const Point3& o = pts[q[0]];
        FilterPlane pl[3];
        bool ok = true;
        for (int k = 0; k < 3; ++k)
          ok = ok && filter_plane(static_cast<std::int32_t>(q[k + 1]), pts, o, no_walls, pl[k]);
        PlanesMeet m;
        double c[3] = {0, 0, 0}, error = INFINITY;
        if (ok && planes_meet(pl[0], pl[1], pl[2], m)) {
          const double oc[3] = {o.x, o.y, o.z};
          double err = 0;
          for (int j = 0; j < 3; ++j) {
            c[j] = oc[j] + m.x[j];
            err = std::max(err, m.error[j] + 0x1.02p-53 * std::abs(c[j]));
          }
          if (std::isfinite(err)) error = err;
        }
        INFO(name << " tet " << t << ", " << threads << " threads");
        REQUIRE(s[t].error == error);
        if (std::isfinite(error)) {
          ++certified;
          for (int j = 0; j < 3; ++j) REQUIRE(s[t].c[j] == c[j]);
        }
        ++compared;
      }
    }
  }
  CHECK(compared > 10000);
  CHECK(certified > compared / 2);
}
