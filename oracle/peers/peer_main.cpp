// dtlab_peer: runs one peer in this process so that dtlab does not have to (gmsh has
// its own helper, dtlab_peer_gmsh: loading its libraries costs about a second).
//   dtlab_peer PEER IN OUT [THREADS]   IN, OUT: oracle/peers/peer_exchange.hpp files;
//                                      THREADS for cgal-parallel (default 1)
//   dtlab_peer --version PEER
// Exit: 0 answered (a note, if any, on the last line of stderr), 2 bad usage,
// 3 the peer refused (its message on the last line of stderr), 4 not built in.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "kernel/build.hpp"
#include "oracle/peers/cgal_oracle.hpp"
#include "oracle/peers/peer_programs.hpp"

#include <CGAL/version.h>

namespace {

using namespace dtlab;

// dtlab:BACKEND or dtlab:BACKEND+none.
PeerAnswer run_dtlab(const std::string& name, const std::vector<Point3>& points) {
  std::string backend = name.substr(6);
  PredicateSpec spec;
  if (backend.size() > 5 && backend.substr(backend.size() - 5) == "+none") {
    spec.perturb = false;
    backend.resize(backend.size() - 5);
  }
  spec.backend = backend;
  const BuildResult r = build_delaunay(points, spec, BuildOptions{});
  PeerAnswer a;
  a.seconds = r.stats.seconds;
  a.tets = r.mesh.tets;
  if (r.failure)
    std::fprintf(stderr, "build failed: %s %s\n", failure_name(r.failure->kind), r.failure->detail.c_str());
  return a;
}

PeerAnswer run(const std::string& name, const std::vector<Point3>& points, unsigned threads) {
  if (name == "cgal") {
    // cgal_delaunay already gives dtlab's orientation and input indices.
    const OracleRun r = cgal_delaunay(points);
    PeerAnswer a;
    a.seconds = r.seconds;
    if (r.mesh) a.tets = r.mesh->tets;
    return a;
  }
  if (name == "cgal-inexact") return peer_cgal_inexact(points);
  if (name == "cgal-parallel") return peer_cgal_parallel(points, threads);
  if (name == "qhull" || name == "qhull-qj") return peer_qhull(points, name == "qhull-qj");
  if (name.rfind("dtlab:", 0) == 0) return run_dtlab(name, points);
  throw std::invalid_argument("unknown peer '" + name + "'");
}

std::string version(const std::string& name) {
  if (name == "cgal" || name == "cgal-inexact") return std::string("CGAL ") + CGAL_VERSION_STR;
  if (name == "cgal-parallel") {
    peer_cgal_parallel({}, 1);  // throws PeerNotInstalled without TBB
    return std::string("CGAL ") + CGAL_VERSION_STR + " Parallel_tag";
  }
  if (name == "qhull" || name == "qhull-qj") return qhull_version();
  if (name.rfind("dtlab:", 0) == 0) return "dtlab " + name.substr(6);
  throw std::invalid_argument("unknown peer '" + name + "'");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--version") == 0)
    return print_peer_version([&] { return version(argv[2]); }, 2);
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: dtlab_peer PEER IN OUT [THREADS] | dtlab_peer --version PEER\n");
    return 2;
  }
  return run_peer_main([&] {
    const unsigned threads = argc == 5 ? peer_thread_count(argv[4]) : 1;
    const std::vector<Point3> points = read_peer_points(argv[2]);
    write_peer_answer(argv[3], run(argv[1], points, threads));
  });
}
