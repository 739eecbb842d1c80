#pragma once
// The peers the dtlab_peer helper runs in its own process (oracle/peer_main.cpp):
// each takes the input points and returns its answer in the exchange format
// (oracle/peer_exchange.hpp), input indices 0-based. A refusal (the peer reports an
// error) throws PeerRefusal; a peer built without its library throws
// PeerNotInstalled. A crash or a hang is not caught: the parent sees it.
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "oracle/peer_exchange.hpp"

namespace dtlab {

struct PeerRefusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct PeerNotInstalled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A helper program's `--version`: the version on stdout and exit 0; exit 4 when the peer
// is not installed, `error_exit` on any other error (the message on stderr).
template <class Version>
int print_peer_version(Version&& version, int error_exit) {
  try {
    std::printf("%s\n", version().c_str());
    return 0;
  } catch (const PeerNotInstalled& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return error_exit;
  }
}

// A helper's THREADS argument: 1..1024, else std::invalid_argument (exit 2).
inline unsigned peer_thread_count(const std::string& text) {
  std::size_t used = 0;
  const unsigned long n = text.empty() || text.size() > 4 || text[0] < '0' || text[0] > '9' ? 0 : std::stoul(text, &used);
  if (used != text.size() || n < 1 || n > 1024) throw std::invalid_argument("bad thread count '" + text + "'");
  return static_cast<unsigned>(n);
}

// CGAL Delaunay_triangulation_3 over Simple_cartesian<double>; cells in CGAL's
// order (its positive orientation: swap two vertices for dtlab's).
PeerAnswer peer_cgal_inexact(const std::vector<Point3>& points);

// CGAL Delaunay_triangulation_3 with Parallel_tag (oneTBB) on `threads` threads;
// cells in CGAL's order. PeerNotInstalled when built without TBB.
PeerAnswer peer_cgal_parallel(const std::vector<Point3>& points, unsigned threads);

// libqhull_r: "d Qbb Qc Qz Q12 Qt" (scipy's defaults), or "d QJ" when `joggle`.
// Lower-Delaunay facets, vertices as input indices (the point at infinity of Qz,
// should it appear, as an extra vertex); orientation as qhull leaves it.
PeerAnswer peer_qhull(const std::vector<Point3>& points, bool joggle);
std::string qhull_version();

// gmsh::model::mesh::tetrahedralize; `hxt` sets Mesh.Algorithm3D = 10 first. gmsh
// numbers nodes from 1: the adapter makes them 0-based.
// `threads`: gmsh's General.NumThreads and Mesh.MaxNumThreads3D (HXT is the parallel one).
PeerAnswer peer_gmsh(const std::vector<Point3>& points, bool hxt, unsigned threads = 1);
std::string gmsh_version();

}  // namespace dtlab
