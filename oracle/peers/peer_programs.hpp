#pragma once
// The peers the dtlab_peer helper runs in its own process (oracle/peers/peer_main.cpp):
// each takes the input points and returns its answer in the exchange format
// (oracle/peers/peer_exchange.hpp), input indices 0-based. A refusal (the peer reports an
// error) throws PeerRefusal; a peer built without its library throws
// PeerNotInstalled. A crash or a hang is not caught: the parent sees it.
#include <cstdio>
#include <exception>
#include <functional>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "oracle/peers/peer_exchange.hpp"

namespace dtlab {

struct PeerRefusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct PeerNotInstalled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A helper's exit codes (the parent grades them: oracle/peers/peer_child.hpp).
enum class PeerExit : int { answered = 0, bad_usage = 2, refused = 3, not_installed = 4 };

// One run of a helper's work (dtlab_peer, dtlab_peer_gmsh, dtlab_voronoi_peer, each
// request of --serve): its exit code, and `message` (the exception's text, for the last
// line of stderr or the reply). PeerNotInstalled: not_installed; std::invalid_argument:
// bad_usage; std::bad_alloc: refused with "out of memory: std::bad_alloc", which the
// parent grades out-of-memory; any other exception: refused.
inline int run_peer_work(const std::function<void()>& work, std::string& message) {
  PeerExit code = PeerExit::answered;
  message.clear();
  try {
    work();
  } catch (const PeerNotInstalled& e) {
    message = e.what(), code = PeerExit::not_installed;
  } catch (const std::invalid_argument& e) {
    message = e.what(), code = PeerExit::bad_usage;
  } catch (const std::bad_alloc& e) {
    message = std::string("out of memory: ") + e.what(), code = PeerExit::refused;
  } catch (const std::exception& e) {
    message = e.what(), code = PeerExit::refused;
  }
  return static_cast<int>(code);
}

// run_peer_work with its message on stderr: a one-shot helper's exit code.
inline int run_peer_main(const std::function<void()>& work) {
  std::string message;
  const int code = run_peer_work(work, message);
  if (!message.empty()) std::fprintf(stderr, "%s\n", message.c_str());
  return code;
}

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
  const unsigned long n =
      text.empty() || text.size() > 4 || text[0] < '0' || text[0] > '9' ? 0 : std::stoul(text, &used);
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
