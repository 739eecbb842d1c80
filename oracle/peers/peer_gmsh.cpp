#include <chrono>
#include <limits>
#include <string>

#include "oracle/peers/peer_programs.hpp"

#if DTLAB_HAVE_GMSH
#include <gmsh.h>
#endif

namespace dtlab {

#if DTLAB_HAVE_GMSH

PeerAnswer peer_gmsh(const std::vector<Point3>& points, bool hxt, unsigned threads) {
  std::vector<double> coord(points.size() * 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    coord[3 * i] = points[i].x;
    coord[3 * i + 1] = points[i].y;
    coord[3 * i + 2] = points[i].z;
  }
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 1);
  gmsh::option::setNumber("General.Verbosity", 1);  // errors only
  if (hxt) gmsh::option::setNumber("Mesh.Algorithm3D", 10);
  gmsh::option::setNumber("General.NumThreads", threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", threads);
  std::vector<std::size_t> tetra;
  PeerAnswer a;
  const auto start = std::chrono::steady_clock::now();
  try {
    gmsh::model::mesh::tetrahedralize(coord, tetra);
  } catch (const std::exception& e) {
    gmsh::finalize();
    throw PeerRefusal(std::string("gmsh: ") + e.what());
  } catch (...) {
    gmsh::finalize();
    throw PeerRefusal("gmsh threw an exception");
  }
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string last_error;
  gmsh::logger::getLastError(last_error);
  gmsh::finalize();
  if (tetra.empty() && !last_error.empty()) throw PeerRefusal("gmsh: " + last_error);
  // Node tags count from 1 (gmsh.h); a tag outside 1..n becomes index n, which the
  // adapter counts as a vertex that is no input point.
  const std::size_t n = points.size();
  a.tets.reserve(tetra.size() / 4);
  for (std::size_t i = 0; i + 3 < tetra.size(); i += 4) {
    Tet t;
    for (int k = 0; k < 4; ++k) {
      const std::size_t tag = tetra[i + k];
      t[k] = tag >= 1 && tag <= n ? static_cast<std::uint32_t>(tag - 1) : static_cast<std::uint32_t>(n);
    }
    a.tets.push_back(t);
  }
  a.extra.push_back({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  return a;
}

std::string gmsh_version() {
  gmsh::initialize();
  std::string version;
  gmsh::option::getString("General.Version", version);
  gmsh::finalize();
  return "gmsh " + version;
}

#else

PeerAnswer peer_gmsh(const std::vector<Point3>&, bool, unsigned) {
  throw PeerNotInstalled("built without gmsh (Debian libgmsh-dev)");
}
std::string gmsh_version() { throw PeerNotInstalled("built without gmsh (Debian libgmsh-dev)"); }

#endif

}  // namespace dtlab
