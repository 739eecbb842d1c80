// voro++ (Debian voro++-dev) as a Voronoi peer: a non-periodic container of the box,
// about 5 sites per block, every cell with its neighbour ids (walls -1..-6, voro++'s
// own numbering, which is ours). voro++ leaves sites outside the box out.
#include <cmath>
#include <algorithm>

#include <voro++/voro++.hh>

#include "voronoi_check/voronoi_peer_programs.hpp"

namespace dtlab {

PeerCells peer_voro(const std::vector<Point3>& sites, const vor::Box& box) {
  const int blocks = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(sites.size()) / 5)));
  const auto t0 = std::chrono::steady_clock::now();
  voro::container con(box.lo.x, box.hi.x, box.lo.y, box.hi.y, box.lo.z, box.hi.z, blocks, blocks, blocks, false,
                      false, false, 8);
  for (std::size_t i = 0; i < sites.size(); ++i) con.put(static_cast<int>(i), sites[i].x, sites[i].y, sites[i].z);
  voro::c_loop_all loop(con);
  voro::voronoicell_neighbor c;
  PeerCells out;
  std::vector<double> xyz;
  std::vector<int> fv, nb;
  std::vector<Point3> v;
  std::vector<std::uint32_t> offsets, corners;
  std::vector<std::int32_t> neighbors;
  if (loop.start()) do {
      if (!con.compute_cell(c, loop)) continue;
      double x, y, z;
      loop.pos(x, y, z);
      c.vertices(x, y, z, xyz);
      c.face_vertices(fv);
      c.neighbors(nb);
      v.clear();
      for (std::size_t k = 0; k + 2 < xyz.size(); k += 3) v.push_back({xyz[k], xyz[k + 1], xyz[k + 2]});
      offsets.assign(1, 0);
      corners.clear();
      for (std::size_t k = 0; k < fv.size(); k += fv[k] + 1) {
        for (int j = 1; j <= fv[k]; ++j) corners.push_back(static_cast<std::uint32_t>(fv[k + j]));
        offsets.push_back(static_cast<std::uint32_t>(corners.size()));
      }
      neighbors.assign(nb.begin(), nb.end());
      add_outward_cell(out.cells, loop.pid(), v, offsets, corners, neighbors);
    } while (loop.inc());
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace dtlab
