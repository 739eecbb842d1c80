#pragma once
// A peers file (`--peers FILE`): command peers (oracle/peers/peer_command.hpp) kept for reuse,
// one entry per peer with the fields of `--peer NAME=COMMAND`:
//   name     the peer's name
//   command  one string (split like --peer's COMMAND) or an array of argv strings
//   kind     "delaunay" (the default: a --peer) or "voronoi" (a --voronoi-peer,
//            voronoi_check/voronoi_peer_command.hpp, whose template the caller checks)
// in JSON, {"peers": [{"name": ..., "command": ...}, ...]} (or the array alone), or, for
// a name ending in .toml, TOML: one [[peers]] table per peer. Unknown fields are refused
// (a misspelt key is never silently a peer without it).
#include <functional>
#include <string>
#include <vector>

#include "oracle/peers/peer_command.hpp"

namespace dtlab {

struct PeersFile {
  std::vector<CommandPeer> delaunay, voronoi;  // in the file's order
};

// Checks a Voronoi peer's name and template (make_voronoi_command_peer): throws
// std::invalid_argument naming what is wrong.
using VoronoiPeerCheck = std::function<CommandPeer(const std::string& name, std::vector<std::string> argv)>;

// Throws InputError (file:line: reason) for a file that cannot be read or parsed, an
// entry without a name or command, an unknown field or kind, or a bad name or template.
PeersFile read_peers_file(const std::string& path, const VoronoiPeerCheck& voronoi_check);

}  // namespace dtlab
