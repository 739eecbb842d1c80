#include "cli/peer_definitions.hpp"

#include <algorithm>
#include <stdexcept>

#include "cli/cli_error.hpp"
#include "oracle/peers/peer_command.hpp"
#include "oracle/peers/peers_file.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

namespace dtlab::cli {

namespace {

void add_once(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

// Every name of one kind must not be a peer of the other kind too.
void check_kinds_apart(const std::vector<std::string>& delaunay, const std::vector<std::string>& voronoi) {
  for (const auto& n : voronoi)
    if (std::find(delaunay.begin(), delaunay.end(), n) != delaunay.end())
      throw UsageError("--voronoi-peer: '" + n + "' names a Delaunay peer (--peer) too: use another name");
}

}  // namespace

void PeerDefinitionArgs::add_to(CLI::App& app, const std::string& file_option, PeerKinds kinds) {
  if (kinds != PeerKinds::voronoi)
    app.add_option("--peer", definitions,
                   "NAME=COMMAND: a peer run as a command (no shell); {in} is the input .node (0-based), {out} the "
                   "prefix of the .ele it writes (repeatable)")
        ->type_name("NAME=COMMAND");
  if (kinds != PeerKinds::delaunay)
    app.add_option("--voronoi-peer", voronoi_definitions,
                   "NAME=COMMAND: a Voronoi peer run as a command (no shell); {in} the sites as a .node (0-based), "
                   "{box} six arguments xmin ymin zmin xmax ymax zmax (or {xmin} .. {zmax}), {out} the prefix of the "
                   "{out}.json cells file it writes; {sites}: voro++'s input (id x y z) in the file {out} "
                   "(repeatable; README: Judge your own code)")
        ->type_name("NAME=COMMAND");
  app.add_option(
         file_option, files,
         "a JSON or TOML (.toml) file of peers: {\"peers\": [{\"name\": ..., \"command\": ..., \"kind\": "
         "\"delaunay\" | \"voronoi\"}]}, or one [[peers]] table (name = ..., command = ..., kind = ...) per peer")
      ->type_name("FILE");
}

std::vector<std::string> PeerDefinitionArgs::register_all() const {
  PeersFile all;
  for (const auto& f : files) {
    PeersFile more = read_peers_file(f, make_voronoi_command_peer);
    all.delaunay.insert(all.delaunay.end(), more.delaunay.begin(), more.delaunay.end());
    all.voronoi.insert(all.voronoi.end(), more.voronoi.begin(), more.voronoi.end());
  }
  std::vector<std::string> names, voronoi;
  try {
    for (const auto& d : definitions) all.delaunay.push_back(parse_peer_definition(d));
    for (const auto& p : all.delaunay) register_command_peer(p), add_once(names, p.name);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--peer: ") + e.what());
  }
  try {
    for (const auto& d : voronoi_definitions) all.voronoi.push_back(parse_voronoi_peer_definition(d));
    for (const auto& p : all.voronoi) register_voronoi_command_peer(p), add_once(voronoi, p.name);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--voronoi-peer: ") + e.what());
  }
  check_kinds_apart(names, voronoi);
  voronoi_registered_ = voronoi;
  return names;
}

}  // namespace dtlab::cli
