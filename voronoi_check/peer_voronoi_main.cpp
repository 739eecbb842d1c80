// dtlab_voronoi_peer: runs one Voronoi peer in this process so that dtlab does not
// have to.
//   dtlab_voronoi_peer PEER IN OUT XMIN YMIN ZMIN XMAX YMAX ZMAX
//       IN: sites (oracle/peers/peer_exchange.hpp), OUT: cells (voronoi_check/cell_exchange.hpp)
//   dtlab_voronoi_peer --version PEER
// PEER: voro++, cgal-dual, dtlab:BACKEND. Exit: 0 answered, 2 bad usage, 3 the peer
// refused (its message on the last line of stderr), 4 not built in.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <CGAL/version.h>

#include "voronoi/voronoi.hpp"
#include "voronoi/voronoi_range.hpp"
#include "voronoi_check/voronoi_peer_programs.hpp"

#ifndef DTLAB_VORO_VERSION
#define DTLAB_VORO_VERSION "unknown"
#endif

namespace {

using namespace dtlab;

PeerCells run_dtlab(const std::string& backend, const std::vector<Point3>& sites, const vor::Box& box) {
  VoronoiOptions o;
  o.box = box;
  o.predicates.backend = backend;
  o.threads = 1;
  // What `dtlab voronoi` refuses (voronoi/voronoi_range.hpp), this peer refuses too: its
  // cells are the command's, not cells the command would never print.
  if (const auto refusal = voronoi_refusal(sites, box, 0)) throw PeerRefusal(refusal->reason);
  VoronoiDiagram vd;
  try {
    vd = compute_voronoi(sites, o);
  } catch (const std::exception& e) {
    throw PeerRefusal(e.what());
  }
  if (const std::string why = lost_cells_problem(vd); !why.empty()) throw PeerRefusal(why);
  return {vd.seconds_dt + vd.seconds_cells, tool_cells_of(vd)};
}

PeerCells run(const std::string& name, const std::vector<Point3>& sites, const vor::Box& box) {
  if (name == "voro++") {
#ifdef DTLAB_HAVE_VORO
    return peer_voro(sites, box);
#else
    throw PeerNotInstalled("built without voro++ (Debian voro++-dev)");
#endif
  }
  if (name == "cgal-dual") return peer_cgal_dual(sites, box);
  if (name.rfind("dtlab:", 0) == 0) return run_dtlab(name.substr(6), sites, box);
  throw std::invalid_argument("unknown Voronoi peer '" + name + "'");
}

std::string version(const std::string& name) {
  if (name == "voro++") {
#ifdef DTLAB_HAVE_VORO
    return std::string("voro++ ") + DTLAB_VORO_VERSION;
#else
    throw PeerNotInstalled("built without voro++");
#endif
  }
  if (name == "cgal-dual") return std::string("CGAL ") + CGAL_VERSION_STR;
  if (name.rfind("dtlab:", 0) == 0) return "dtlab " + name.substr(6);
  throw std::invalid_argument("unknown Voronoi peer '" + name + "'");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--version") == 0)
    return print_peer_version([&] { return version(argv[2]); }, 2);
  if (argc != 10) {
    std::fprintf(stderr, "usage: dtlab_voronoi_peer PEER IN OUT XMIN YMIN ZMIN XMAX YMAX ZMAX\n");
    return 2;
  }
  return run_peer_main([&] {
    double b[6];
    for (int k = 0; k < 6; ++k) b[k] = std::strtod(argv[4 + k], nullptr);
    const vor::Box box{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
    const std::vector<Point3> sites = read_peer_points(argv[2]);
    const PeerCells cells = run(argv[1], sites, box);
    write_peer_cells(argv[3], cells.seconds, cells.cells);
  });
}
