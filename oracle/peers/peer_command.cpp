#include "oracle/peers/peer_command.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>

#include "kernel/input_error.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_adapter.hpp"
#include "oracle/peers/peer_child.hpp"
#include "oracle/peers/temp_dir.hpp"

namespace dtlab {
namespace {

CommandPeerRegistry& registry() {
  static CommandPeerRegistry r("peer");
  return r;
}

}  // namespace

void check_peer_name(const std::string& name) {
  if (name.empty()) throw std::invalid_argument("a peer needs a name (NAME=COMMAND)");
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == '+'))
      throw std::invalid_argument("peer name '" + name + "': use letters, digits and _ - . + only");
  if (name == "all" || name == "none") throw std::invalid_argument("peer name '" + name + "' is reserved");
}

namespace {

// Every {...} in the template must be {in} or {out}, and each must appear.
void check_template(const std::string& name, const std::vector<std::string>& argv) {
  if (argv.empty()) throw std::invalid_argument("peer '" + name + "': empty command");
  bool in = false, out = false;
  for (const std::string& a : argv)
    for (std::size_t i = a.find('{'); i != std::string::npos; i = a.find('{', i + 1)) {
      const std::size_t j = a.find('}', i);
      const std::string key = j == std::string::npos ? a.substr(i) : a.substr(i, j - i + 1);
      if (key == "{in}")
        in = true;
      else if (key == "{out}")
        out = true;
      else
        throw std::invalid_argument("peer '" + name + "': unknown placeholder '" + key + "' (use {in} and {out})");
    }
  if (!in) throw std::invalid_argument("peer '" + name + "': the command has no {in} (where the input .node goes)");
  if (!out)
    throw std::invalid_argument("peer '" + name + "': the command has no {out} (the prefix of the .ele it writes)");
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size()))
    s.replace(i, from.size(), to);
  return s;
}

std::string shell_quote(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string("_-.+/:={},@%").find(c) != std::string::npos;
  });
  if (plain) return s;
  std::string q = "'";
  q += replace_all(s, "'", "'\\''");
  q += '\'';
  return q;
}

// The numbering base of a TetGen .ele: the number of its first tetrahedron (TetGen
// numbers elements from the base of its nodes); 0 when it has none.
int ele_first_index(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  int seen = 0;
  while (std::getline(in, line)) {
    const std::size_t b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    if (seen++ == 0) continue;  // the header
    return line.compare(b, 1, "1") == 0 &&
                   (b + 1 == line.size() || std::isspace(static_cast<unsigned char>(line[b + 1])))
               ? 1
               : 0;
  }
  return 0;
}

// read_ele swaps two vertices into dtlab's orientation; a command peer's tets are
// oriented by their exact sign instead, and a flat one keeps the order the peer wrote
// (as the built-in adapters keep it), so the swap is undone.
void unswap(std::vector<Tet>& tets) {
  for (Tet& t : tets) std::swap(t[0], t[1]);
}

// {out}.ele with {out}.node when the peer wrote one (its points become extra
// vertices, which the adapter maps back to input points by their coordinates).
PeerAnswer read_command_answer(const std::string& prefix, std::size_t n) {
  PeerAnswer a;
  const std::string node = prefix + ".node", ele = prefix + ".ele";
  if (std::filesystem::exists(node)) {
    PointFile pf = read_node(node);
    a.tets = read_ele(ele, pf.first_index, pf.points.size());
    unswap(a.tets);
    for (Tet& t : a.tets)
      for (auto& v : t) v += static_cast<std::uint32_t>(n);
    a.extra = std::move(pf.points);
    return a;
  }
  a.tets = read_ele(ele, ele_first_index(ele), n);
  unswap(a.tets);
  return a;
}

}  // namespace

std::vector<std::string> split_command(const std::string& s) {
  std::vector<std::string> words;
  std::string w;
  bool in_word = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\'' || c == '"') {
      const std::size_t end = s.find(c, i + 1);
      std::size_t j = i + 1;
      for (; j < s.size() && s[j] != c; ++j) {
        if (c == '"' && s[j] == '\\' && j + 1 < s.size() && (s[j + 1] == '"' || s[j + 1] == '\\')) ++j;
        w += s[j];
      }
      if (end == std::string::npos || j >= s.size()) throw std::invalid_argument("unterminated quote in: " + s);
      i = j;
      in_word = true;
    } else if (c == '\\' && i + 1 < s.size()) {
      w += s[++i];
      in_word = true;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (in_word) words.push_back(w);
      w.clear();
      in_word = false;
    } else {
      w += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(w);
  return words;
}

CommandPeer make_command_peer(const std::string& name, std::vector<std::string> argv) {
  check_peer_name(name);
  check_template(name, argv);
  return {name, std::move(argv)};
}

CommandPeer parse_peer_definition(const std::string& definition) {
  const std::size_t eq = definition.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("expected NAME=COMMAND, got '" + definition + "'");
  return make_command_peer(definition.substr(0, eq), split_command(definition.substr(eq + 1)));
}

std::string command_text(const std::vector<std::string>& argv) {
  std::string s;
  for (const auto& a : argv) {
    if (!s.empty()) s += ' ';
    s += shell_quote(a);
  }
  return s;
}

void CommandPeerRegistry::add(const CommandPeer& peer) {
  std::lock_guard<std::mutex> g(lock_);
  for (const CommandPeer& p : peers_)
    if (p.name == peer.name) {
      if (p.argv == peer.argv) return;
      throw std::invalid_argument(kind_ + " '" + peer.name + "' is defined twice with different commands");
    }
  peers_.push_back(peer);
}

std::optional<CommandPeer> CommandPeerRegistry::find(const std::string& name) const {
  std::lock_guard<std::mutex> g(lock_);
  for (const CommandPeer& p : peers_)
    if (p.name == name) return p;
  return std::nullopt;
}

std::vector<std::string> CommandPeerRegistry::names() const {
  std::lock_guard<std::mutex> g(lock_);
  std::vector<std::string> names;
  for (const CommandPeer& p : peers_) names.push_back(p.name);
  return names;
}

void register_command_peer(const CommandPeer& peer) {
  if (is_builtin_peer_name(peer.name))
    throw std::invalid_argument("peer name '" + peer.name + "' is a built-in peer's");
  registry().add(peer);
}

std::optional<CommandPeer> find_command_peer(const std::string& name) { return registry().find(name); }

std::vector<std::string> command_peer_names() { return registry().names(); }

std::string peer_definition_arguments(const std::string& name) {
  const auto p = find_command_peer(name);
  return p ? " --peer " + shell_quote(p->name + "=" + command_text(p->argv)) : "";
}

PeerRun run_command_peer(const CommandPeer& peer, std::span<const Point3> points, const PeerOptions& options) {
  PeerRun run;
  run.name = peer.name;
  TempDir dir("dtlab-peer");
  const std::string log = dir.file("log.txt"), in = dir.file("in.node"), out = dir.file("out");
  write_node(in, std::vector<Point3>(points.begin(), points.end()));
  std::vector<std::string> argv;
  for (const std::string& a : peer.argv) argv.push_back(replace_all(replace_all(a, "{in}", in), "{out}", out));
  // In sanitizer builds the command is typically our own instrumented binary.
  const ChildLimits limits = peer_limits(options, log, true);
  const ChildResult c = run_child(argv, limits);
  const auto failure = child_failure(c, log, run, false);
  run.message = replace_all(run.message, dir.path().string() + "/", "");  // the temp folder says nothing
  if (failure) {
    run.verdict = *failure;
    return run;
  }
  if (!std::filesystem::exists(out + ".ele")) {
    run.verdict = Verdict::refused;
    run.message = "exited 0 but wrote no {out}.ele" + (run.message.empty() ? "" : ": " + run.message);
    return run;
  }
  PeerAnswer a;
  try {
    a = read_command_answer(out, points.size());
  } catch (const std::exception& e) {
    // Garbage is a wrong answer: a verdict, with the reader's message (temp path shortened).
    run.verdict = Verdict::invalid;
    run.message = "unreadable answer: " + replace_all(e.what(), dir.path().string() + "/", "");
    return run;
  }
  a.seconds = c.seconds;
  adapt_and_judge(points, a, PeerOrientation::by_sign, options.check, 1, run);
  return run;
}

}  // namespace dtlab
