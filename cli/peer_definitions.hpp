#pragma once
// `--peer NAME=COMMAND` (repeatable), `--voronoi-peer NAME=COMMAND` (repeatable) and a
// peers file: Delaunay codes (oracle/peers/peer_command.hpp) and Voronoi codes
// (voronoi_check/voronoi_peer_command.hpp) given by a command line, usable wherever a
// built-in peer name is. One definition for oracle, fuzz, voronoi and experiment
// leaderboard.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace dtlab::cli {

// Which definitions a command takes: Delaunay peers (--peer), Voronoi peers
// (--voronoi-peer), or both; a peers file may hold both kinds in every case.
enum class PeerKinds { delaunay, voronoi, both };

struct PeerDefinitionArgs {
  std::vector<std::string> definitions;          // NAME=COMMAND, Delaunay peers
  std::vector<std::string> voronoi_definitions;  // NAME=COMMAND, Voronoi peers
  std::vector<std::string> files;                // peers files (JSON or TOML)

  // `file_option`: "--peers" where the name is free, else another spelling.
  void add_to(CLI::App& app, const std::string& file_option = "--peers,--peers-file",
              PeerKinds kinds = PeerKinds::delaunay);
  // Registers every peer, files first; returns the Delaunay peers' names in order. A
  // bad definition is bad usage (UsageError), a bad file an InputError (file:line: reason).
  std::vector<std::string> register_all() const;
  // The Voronoi peers' names register_all registered, in order.
  const std::vector<std::string>& voronoi_names() const { return voronoi_registered_; }

 private:
  mutable std::vector<std::string> voronoi_registered_;
};

}  // namespace dtlab::cli
