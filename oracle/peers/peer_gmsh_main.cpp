// dtlab_peer_gmsh: the gmsh peers in their own helper (libgmsh loads OpenCASCADE and
// more, about half a second per start, which the other peers should not pay).
//   dtlab_peer_gmsh gmsh|gmsh-hxt IN OUT [THREADS]     dtlab_peer_gmsh --version gmsh
//   dtlab_peer_gmsh --serve gmsh|gmsh-hxt [THREADS]    many runs in one process (oracle/peers/peer_serve.hpp)
// THREADS: gmsh's thread count (default 1).
// Exit codes as dtlab_peer's: 0 answered, 2 bad usage, 3 refused, 4 not built in.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "oracle/peers/peer_programs.hpp"
#include "oracle/peers/peer_serve.hpp"

int main(int argc, char** argv) {
  using namespace dtlab;
  const auto usage = [] {
    std::fprintf(
        stderr,
        "usage: dtlab_peer_gmsh gmsh|gmsh-hxt IN OUT [THREADS] | dtlab_peer_gmsh --serve gmsh|gmsh-hxt [THREADS] | "
        "dtlab_peer_gmsh --version gmsh\n");
    return 2;
  };
  if (argc == 3 && std::strcmp(argv[1], "--version") == 0) return print_peer_version(gmsh_version, 3);
  const bool serve = (argc == 3 || argc == 4) && std::strcmp(argv[1], "--serve") == 0;
  if (!serve && argc != 4 && argc != 5) return usage();
  const std::string name = argv[serve ? 2 : 1];
  if (name != "gmsh" && name != "gmsh-hxt") return usage();
  const int threads_at = serve ? 3 : 4;
  unsigned threads = 1;
  try {
    if (argc > threads_at) threads = peer_thread_count(argv[threads_at]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return usage();
  }
  const PeerRequest run = [hxt = name == "gmsh-hxt", threads](const std::string& in, const std::string& out) {
    write_peer_answer(out, peer_gmsh(read_peer_points(in), hxt, threads));
  };
  if (serve) return serve_peer_requests(run);
  std::string message;
  const int code = run_peer_request(run, argv[2], argv[3], message);
  if (!message.empty()) std::fprintf(stderr, "%s\n", message.c_str());
  return code;
}
