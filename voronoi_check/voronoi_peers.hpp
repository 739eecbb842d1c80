#pragma once
// The field's Voronoi codes dtlab judges, each run in its own process under a time
// and memory limit (oracle/peers/child_process.hpp), its cells clipped to the box dtlab's
// are clipped to, and judged by the exact Voronoi checker (voronoi_check.hpp):
//
//   voro++          voro++ 0.4.6 (Debian voro++-dev), linked        dtlab_voronoi_peer
//   scipy-voronoi   scipy.spatial.Voronoi, regions clipped          voronoi_peer.py
//   qvoronoi        qhull-bin's `qvoronoi o Fv`, regions clipped    voronoi_peer.py
//   cgal-dual       CGAL Delaunay_triangulation_3's dual, clipped   dtlab_voronoi_peer
//   dtlab:B         dtlab's cells, backend B (naive .. exact)       dtlab_voronoi_peer
//
// How each adapter clips is documented in its source and in voronoi_check/README.md.
// Peers given by a command (voronoi_peer_command.hpp), once registered, are names here
// too: listed by "all", run and versioned by the functions below.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "voronoi_check/voronoi_check.hpp"

namespace dtlab {

struct VoronoiPeerOptions {
  double timeout_s = 600;
  std::uint64_t memory_bytes = 0;           // 0: half of the machine's memory
  std::string python = "/usr/bin/python3";  // Debian's, with python3-scipy
  std::string helper;  // "": $DTLAB_VORONOI_PEER, else the dtlab_voronoi_peer built with dtlab
  std::string script;  // "": $DTLAB_VORONOI_PEER_SCRIPT, else voronoi_peer.py of the source tree
  VoronoiCheckOptions check;
};

struct VoronoiPeerRun {
  std::string name;
  VoronoiVerdict verdict = VoronoiVerdict::not_installed;
  std::string message;         // a refusal's message, a signal's name
  double seconds = 0;          // the cells as the peer times them
  double wall_seconds = 0;     // the whole child process
  std::uint64_t peak_rss_bytes = 0;
  std::optional<VoronoiCheckReport> report;
};

const std::vector<std::string>& voronoi_peer_names();
bool is_voronoi_peer_name(const std::string& name);
// "all" expands to every peer; throws std::invalid_argument naming an unknown one.
std::vector<std::string> expand_voronoi_peer_names(const std::vector<std::string>& names);

// Runs one peer on the sites, clipped to `box`, and judges its cells. Never throws
// for what the peer does; throws std::invalid_argument for an unknown name.
VoronoiPeerRun run_voronoi_peer(const std::string& name, std::span<const Point3> sites, const vor::Box& box,
                                const VoronoiPeerOptions& options = {});

std::string voronoi_peer_version(const std::string& name, const VoronoiPeerOptions& options = {});

}  // namespace dtlab
