#include "cli/peer_definitions.hpp"

#include <algorithm>
#include <stdexcept>

#include "cli/cli_error.hpp"
#include "oracle/peer_command.hpp"
#include "oracle/peers_file.hpp"

namespace dtlab::cli {

void PeerDefinitionArgs::add_to(CLI::App& app, const std::string& file_option) {
  app.add_option("--peer", definitions,
                 "NAME=COMMAND: a peer run as a command (no shell); {in} is the input .node (0-based), {out} the "
                 "prefix of the .ele it writes (repeatable)")
      ->type_name("NAME=COMMAND");
  app.add_option(file_option, files,
                 "a JSON or TOML (.toml) file of peers: {\"peers\": [{\"name\": ..., \"command\": ...}]}, or one "
                 "[[peers]] table (name = ..., command = ...) per peer")
      ->type_name("FILE");
}

std::vector<std::string> PeerDefinitionArgs::register_all() const {
  std::vector<CommandPeer> peers;
  for (const auto& f : files) {
    auto more = read_peers_file(f);
    peers.insert(peers.end(), more.begin(), more.end());
  }
  std::vector<std::string> names;
  try {
    for (const auto& d : definitions) peers.push_back(parse_peer_definition(d));
    for (const auto& p : peers) {
      register_command_peer(p);
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
    }
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--peer: ") + e.what());
  }
  return names;
}

}  // namespace dtlab::cli
