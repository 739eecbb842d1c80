#pragma once
// `--peer NAME=COMMAND` (repeatable) and a peers file: Delaunay codes given by a
// command line (oracle/peer_command.hpp), usable wherever a built-in peer name is.
// One definition for oracle, fuzz and experiment leaderboard.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace dtlab::cli {

struct PeerDefinitionArgs {
  std::vector<std::string> definitions;  // NAME=COMMAND
  std::vector<std::string> files;        // peers files (JSON)

  // `file_option`: "--peers" where the name is free, else another spelling.
  void add_to(CLI::App& app, const std::string& file_option = "--peers,--peers-file");
  // Registers every peer, files first; returns their names in order. A bad definition
  // is bad usage (UsageError), a bad file an InputError (file:line: reason).
  std::vector<std::string> register_all() const;
};

}  // namespace dtlab::cli
