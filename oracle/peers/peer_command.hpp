#pragma once
// Peers given by a command line instead of an adapter compiled into dtlab:
// `--peer NAME=COMMAND` or a peers file. COMMAND is an argv template, split like a
// shell would split words (quotes and backslashes) but never run by a shell, with
//   {in}   a TetGen .node file of the input points, numbered from 0,
//   {out}  a prefix: the peer writes {out}.ele (TetGen's format, numbered from 0 or 1,
//          either orientation) and, when it drops or renumbers points, {out}.node.
// Once registered, NAME is a peer name like the built-in ones (oracle/peers/peers.hpp):
// it runs under the same limits and is judged by the same adapter and checker.
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "oracle/peers/peers.hpp"

namespace dtlab {

struct CommandPeer {
  std::string name;
  std::vector<std::string> argv;  // with the {in} and {out} placeholders
};

// The command peers defined in this process (one registry for Delaunay peers, one for
// Voronoi peers), thread-safe. `add` accepts the same definition twice and throws
// std::invalid_argument for one name with two commands; `kind` names the registry in
// that message ("peer", "Voronoi peer").
class CommandPeerRegistry {
 public:
  explicit CommandPeerRegistry(std::string kind) : kind_(std::move(kind)) {}
  void add(const CommandPeer& peer);
  std::optional<CommandPeer> find(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::string kind_;
  mutable std::mutex lock_;
  std::vector<CommandPeer> peers_;
};

// "NAME=COMMAND". Throws std::invalid_argument naming what is wrong: no '=', a bad
// name, an unterminated quote, no {in} or no {out}, an unknown {placeholder}.
CommandPeer parse_peer_definition(const std::string& definition);
// Checks a name and an argv template as parse_peer_definition does (peers files).
CommandPeer make_command_peer(const std::string& name, std::vector<std::string> argv);
// Throws std::invalid_argument unless `name` can name a peer (letters, digits and
// _ - . + only; not "all" or "none"): command and function peers (oracle/peers/peer_function.hpp).
void check_peer_name(const std::string& name);
// Words of a command line: whitespace separates, '...' is literal, "..." is literal but
// for \" and \\, a backslash outside quotes takes the next character as it is.
std::vector<std::string> split_command(const std::string& command);

// Adds a peer to this process's peer names. Throws std::invalid_argument when the name
// is a built-in peer's or another command peer's with a different command.
void register_command_peer(const CommandPeer& peer);
std::optional<CommandPeer> find_command_peer(const std::string& name);
std::vector<std::string> command_peer_names();  // in the order registered

// The options that define `name` again on a command line ("--peer 'NAME=...'"), for
// the reproducing commands of a corpus; "" for a built-in peer.
std::string peer_definition_arguments(const std::string& name);
// The command as one line, quoted where needed.
std::string command_text(const std::vector<std::string>& argv);

// Runs the command on `points` and judges its answer (PeerOrientation::by_sign).
// Never throws for what the command does: exit status != 0 is `refused`, a signal
// `crashed`, the time limit `hung`, a program that cannot start `not-installed`, an
// unreadable or out-of-range {out}.ele `invalid` with the reader's message.
PeerRun run_command_peer(const CommandPeer& peer, std::span<const Point3> points, const PeerOptions& options);

}  // namespace dtlab
