#pragma once
// Voronoi peers given by a command line (`--voronoi-peer NAME=COMMAND`, or a peers file
// entry with kind = "voronoi"), as the Delaunay command peers (oracle/peers/peer_command.hpp):
// COMMAND is an argv template, split like shell words but never run by a shell, with
//   {in}      the sites as a TetGen .node, numbered from 0;
//   {sites}   the sites as "id x y z" lines (voro++'s input format, ids from 0) in the
//             file named {out}, so a tool that writes FILE.vol next to its input FILE
//             (the voro++ command line) writes {out}.vol;
//   {out}     a prefix: the peer writes its cells to {out}.json (cells_file.hpp), or
//             {out}.vol (voro++'s `-c "%i %w %P %s %n %t"` output);
//   {box}     (a whole argument) six arguments: xmin ymin zmin xmax ymax zmax;
//   {xmin} {ymin} {zmin} {xmax} {ymax} {zmax}   one coordinate of the box each.
// It needs {in} or {sites}, and {out} or {sites}. Once registered, NAME is a Voronoi
// peer name like the built-in ones (voronoi_peers.hpp): it runs under the same limits
// (oracle/peers/child_process.hpp, its own process group) and is judged by the same checker.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "oracle/peers/peer_command.hpp"
#include "voronoi_check/voronoi_peers.hpp"

namespace dtlab {

// Checks the template (std::invalid_argument naming what is wrong: no {in} or {sites},
// no {out} or {sites}, an unknown placeholder, {box} inside a word) and the name.
CommandPeer make_voronoi_command_peer(const std::string& name, std::vector<std::string> argv);
// "NAME=COMMAND" (std::invalid_argument as make_voronoi_command_peer, or no '=').
CommandPeer parse_voronoi_peer_definition(const std::string& definition);

// Adds a Voronoi peer to this process's names. Throws std::invalid_argument when the
// name is a built-in Voronoi or Delaunay peer's, or another command's.
void register_voronoi_command_peer(const CommandPeer& peer);
std::optional<CommandPeer> find_voronoi_command_peer(const std::string& name);
std::vector<std::string> voronoi_command_peer_names();  // in the order registered

// " --voronoi-peer 'NAME=...'": defines `name` again on a command line (the replay
// commands of a corpus); "" for a built-in peer.
std::string voronoi_peer_definition_arguments(const std::string& name);

// Runs the command on the sites and judges its cells. Never throws for what the
// command does: exit status != 0 is `refused`, a signal `crashed`, the time limit
// `hung`, out of memory `out-of-memory`, a program that cannot start `not-installed`,
// no cells file or an unreadable one `refused` ("unreadable answer: out.json: ...").
VoronoiPeerRun run_voronoi_command_peer(const CommandPeer& peer, std::span<const Point3> sites, const vor::Box& box,
                                        const VoronoiPeerOptions& options);

}  // namespace dtlab
