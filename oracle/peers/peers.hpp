#pragma once
// The field of Delaunay codes dtlab judges ("peers"), each run in its own process
// under a time and memory limit (oracle/peers/child_process.hpp), its answer normalised
// by an adapter (orientation, index base, duplicates, extra vertices) into a
// Tetrahedralization over the input points and judged by the exact checker.
//
//   cgal          CGAL Delaunay_triangulation_3, EPICK          dtlab_peer
//   cgal-inexact  the same with Simple_cartesian<double>        dtlab_peer
//   cgal-parallel the same as cgal with Parallel_tag (oneTBB)   dtlab_peer
//   tetgen        TetGen -QzJNF (Bowyer-Watson)                 the tetgen binary
//   tetgen-flip   TetGen -QzJNFl (flip-based insertion)         the tetgen binary
//   qhull         libqhull_r "d Qbb Qc Qz Q12 Qt" (scipy's)     dtlab_peer
//   qhull-qj      libqhull_r "d QJ" (joggled input)             dtlab_peer
//   scipy         scipy.spatial.Delaunay                        python3
//   gmsh          gmsh::model::mesh::tetrahedralize             dtlab_peer_gmsh
//   gmsh-hxt      the same with Mesh.Algorithm3D = 10 (HXT)     dtlab_peer_gmsh
//   dtlab:B       dtlab's inserter, backend B (naive, epsilon, adaptive, exact),
//                 symbolic perturbation on; dtlab:B+none without  dtlab_peer
//   NAME          a command given by --peer NAME=COMMAND (oracle/peers/peer_command.hpp)
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "oracle/check/check.hpp"
#include "oracle/peers/verdict.hpp"

namespace dtlab {

class ServedChildren;

struct PeerOptions {
  double timeout_s = 600;
  // RLIMIT_AS of the peer's process. 0: half of the machine's memory (a runaway peer
  // cannot take the machine); kNoMemoryLimit: none (a timed whole run, `dtlab bench`).
  static constexpr std::uint64_t kNoMemoryLimit = ~std::uint64_t{0};
  std::uint64_t memory_bytes = 0;
  std::string tetgen = "tetgen";
  std::string python = "/usr/bin/python3";  // Debian's, with python3-scipy
  std::string peer_binary;                  // the helper for every helper peer (tests); "": $DTLAB_PEER,
                                            // $DTLAB_PEER_GMSH (gmsh peers), else those built with dtlab
  bool check = true;                        // judge the answer with the exact checker
  // Threads of the parallel peers (cgal-parallel, gmsh-hxt; 0: all hardware threads),
  // and of the checker that judges every answer.
  unsigned threads = 1;
  // When set, the peers whose start costs most of a small run (gmsh, gmsh-hxt: their
  // libraries; scipy: its import) run in a helper kept from one call to the next
  // (oracle/peers/served_child.hpp), under the same limits; a crash or hang ends that
  // helper and the next call starts a fresh one. For shrinking, where hundreds of
  // small runs would each pay the start; verdicts a report counts come from a fresh
  // process per run (nullptr). Not thread-safe: one per thread.
  ServedChildren* servers = nullptr;
};

struct PeerRun {
  std::string name;
  Verdict verdict = Verdict::not_installed;
  std::string message;      // a refusal's message, a signal's name, the peer's note
  double seconds = 0;       // the triangulation as the peer times it (else the process)
  double wall_seconds = 0;  // the whole child process, file I/O included
  std::uint64_t peak_rss_bytes = 0;
  std::optional<Tetrahedralization> mesh;  // normalised answer (when there is one)
  std::vector<std::uint32_t> unused;       // inputs in no tet (duplicates, or missing)
  std::uint64_t extra_vertices = 0;        // answer vertices that are no input point
  std::uint64_t extra_tets = 0;            // tets on them, left out of `mesh`
  std::uint64_t collapsed_tets = 0;        // tets on two copies of one point, left out
  std::optional<CheckReport> report;       // the checker's report on `mesh`
};

// Every peer name, in the order of the table above (dtlab:B+none not listed).
const std::vector<std::string>& peer_names();
// A built-in peer or one registered by command (oracle/peers/peer_command.hpp).
bool is_peer_name(const std::string& name);
bool is_builtin_peer_name(const std::string& name);
// "all" expands to peer_names() and the command peers; throws std::invalid_argument naming an unknown peer.
std::vector<std::string> expand_peer_names(const std::vector<std::string>& names);

// Runs one peer on `points` and judges its answer. Never throws for what the peer
// does (crash, hang, refusal, garbage output); throws std::invalid_argument for an
// unknown name or bad options.
PeerRun run_peer(const std::string& name, std::span<const Point3> points, const PeerOptions& options = {});

// The peer's version ("CGAL 5.5.1", "qhull 2020.2", ...), or "not installed".
std::string peer_version(const std::string& name, const PeerOptions& options = {});

// The helper binary that runs `name` (dtlab_peer, or dtlab_peer_gmsh for the gmsh peers).
std::string peer_binary(const PeerOptions& options, const std::string& name);

}  // namespace dtlab
