#pragma once
// A peers file (`--peers FILE`): command peers (oracle/peer_command.hpp) kept for reuse,
// one entry per peer with the fields of `--peer NAME=COMMAND`:
//   name     the peer's name
//   command  one string (split like --peer's COMMAND) or an array of argv strings
// in JSON, {"peers": [{"name": ..., "command": ...}, ...]} (or the array alone), or, for
// a name ending in .toml, TOML: one [[peers]] table per peer. Unknown fields are refused
// (a misspelt key is never silently a peer without it).
#include <string>
#include <vector>

#include "oracle/peer_command.hpp"

namespace dtlab {

// Throws InputError (file:line: reason) for a file that cannot be read or parsed, an
// entry without a name or command, an unknown field, or a bad name or template.
std::vector<CommandPeer> read_peers_file(const std::string& path);

}  // namespace dtlab
