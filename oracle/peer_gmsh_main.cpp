// dtlab_peer_gmsh: the gmsh peers in their own helper (libgmsh loads OpenCASCADE and
// more, about a second per start, which the other peers should not pay).
//   dtlab_peer_gmsh gmsh|gmsh-hxt IN OUT     dtlab_peer_gmsh --version gmsh
// Exit codes as dtlab_peer's: 0 answered, 2 bad usage, 3 refused, 4 not built in.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "oracle/peer_programs.hpp"

int main(int argc, char** argv) {
  using namespace dtlab;
  try {
    if (argc == 3 && std::strcmp(argv[1], "--version") == 0) {
      std::printf("%s\n", gmsh_version().c_str());
      return 0;
    }
    const std::string name = argc == 4 ? argv[1] : "";
    if (name != "gmsh" && name != "gmsh-hxt") {
      std::fprintf(stderr, "usage: dtlab_peer_gmsh gmsh|gmsh-hxt IN OUT | dtlab_peer_gmsh --version gmsh\n");
      return 2;
    }
    write_peer_answer(argv[3], peer_gmsh(read_peer_points(argv[2]), name == "gmsh-hxt"));
    return 0;
  } catch (const PeerNotInstalled& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 3;
  }
}
