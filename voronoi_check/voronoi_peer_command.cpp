#include "voronoi_check/voronoi_peer_command.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <new>
#include <stdexcept>

#include "kernel/point_io.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_child.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "voronoi_check/cells_file.hpp"

namespace dtlab {

namespace {

CommandPeerRegistry& registry() {
  static CommandPeerRegistry r("Voronoi peer");
  return r;
}

const std::array<const char*, 6> kCorners = {"{xmin}", "{ymin}", "{zmin}", "{xmax}", "{ymax}", "{zmax}"};

bool is_placeholder(const std::string& key) {
  if (key == "{in}" || key == "{out}" || key == "{sites}" || key == "{box}") return true;
  for (const char* c : kCorners)
    if (key == c) return true;
  return false;
}

// Every {...} must be a known placeholder; {box} a whole argument; the sites and the
// answer must both have a place.
void check_voronoi_template(const std::string& name, const std::vector<std::string>& argv) {
  const std::string peer = "Voronoi peer '" + name + "': ";
  if (argv.empty()) throw std::invalid_argument(peer + "empty command");
  bool in = false, out = false, sites = false;
  for (const std::string& a : argv)
    for (std::size_t i = a.find('{'); i != std::string::npos; i = a.find('{', i + 1)) {
      const std::size_t j = a.find('}', i);
      const std::string key = j == std::string::npos ? a.substr(i) : a.substr(i, j - i + 1);
      if (!is_placeholder(key))
        throw std::invalid_argument(peer + "unknown placeholder '" + key +
                                    "' (use {in}, {sites}, {out}, {box}, {xmin} .. {zmax})");
      if (key == "{box}" && a != key)
        throw std::invalid_argument(peer +
                                    "{box} must be a whole argument (it becomes six); use {xmin} .. {zmax} in words");
      in |= key == "{in}", out |= key == "{out}", sites |= key == "{sites}";
    }
  if (!in && !sites) throw std::invalid_argument(peer + "the command has no {in} or {sites} (where the sites go)");
  if (!out && !sites)
    throw std::invalid_argument(peer + "the command has no {out} (the prefix of the {out}.json it writes)");
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size()))
    s.replace(i, from.size(), to);
  return s;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool uses(const CommandPeer& p, const std::string& key) {
  for (const auto& a : p.argv)
    if (a.find(key) != std::string::npos) return true;
  return false;
}

// The sites as voro++ reads them: "id x y z", ids from 0.
void write_sites_text(const std::string& path, std::span<const Point3> sites) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot write");
  for (std::size_t i = 0; i < sites.size(); ++i)
    std::fprintf(f, "%zu %.17g %.17g %.17g\n", i, sites[i].x, sites[i].y, sites[i].z);
  if (std::fclose(f) != 0) throw std::runtime_error(path + ": write failed");
}

// The argv with the placeholders filled in; {box} becomes six arguments.
std::vector<std::string> expand(const CommandPeer& p, const std::string& in, const std::string& out,
                                const vor::Box& box) {
  const std::array<double, 6> corner = {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
  std::vector<std::string> argv;
  for (const std::string& a : p.argv) {
    if (a == "{box}") {
      for (double v : corner) argv.push_back(number(v));
      continue;
    }
    std::string w = replace_all(replace_all(replace_all(a, "{in}", in), "{out}", out), "{sites}", out);
    for (std::size_t k = 0; k < kCorners.size(); ++k) w = replace_all(w, kCorners[k], number(corner[k]));
    argv.push_back(std::move(w));
  }
  return argv;
}

VoronoiVerdict voronoi_verdict_of(Verdict v) {
  switch (v) {
    case Verdict::not_installed: return VoronoiVerdict::not_installed;
    case Verdict::hung: return VoronoiVerdict::hung;
    case Verdict::crashed: return VoronoiVerdict::crashed;
    case Verdict::out_of_memory: return VoronoiVerdict::out_of_memory;
    default: return VoronoiVerdict::refused;
  }
}

// The child's end when it gave no answer (the Delaunay command peers' classification).
bool no_answer(const ChildResult& c, const std::string& log, VoronoiPeerRun& run) {
  PeerRun dt;
  const auto failure = child_failure(c, log, dt, false);
  run.wall_seconds = dt.wall_seconds;
  run.seconds = c.seconds;
  run.peak_rss_bytes = dt.peak_rss_bytes;
  run.message = dt.message;
  if (failure) run.verdict = voronoi_verdict_of(*failure);
  return failure.has_value();
}

// {out}.json, else {out}.vol ("" when it wrote neither).
std::string answer_file(const std::string& out) {
  for (const char* ext : {".json", ".vol"})
    if (std::filesystem::exists(out + ext)) return out + ext;
  return "";
}

}  // namespace

CommandPeer make_voronoi_command_peer(const std::string& name, std::vector<std::string> argv) {
  check_peer_name(name);
  check_voronoi_template(name, argv);
  return {name, std::move(argv)};
}

CommandPeer parse_voronoi_peer_definition(const std::string& definition) {
  const std::size_t eq = definition.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("expected NAME=COMMAND, got '" + definition + "'");
  return make_voronoi_command_peer(definition.substr(0, eq), split_command(definition.substr(eq + 1)));
}

void register_voronoi_command_peer(const CommandPeer& peer) {
  for (const auto& n : voronoi_peer_names())
    if (n == peer.name) throw std::invalid_argument("Voronoi peer name '" + peer.name + "' is a built-in peer's");
  if (is_builtin_peer_name(peer.name))
    throw std::invalid_argument("Voronoi peer name '" + peer.name + "' is a built-in Delaunay peer's");
  registry().add(peer);
}

std::optional<CommandPeer> find_voronoi_command_peer(const std::string& name) { return registry().find(name); }

std::vector<std::string> voronoi_command_peer_names() { return registry().names(); }

std::string voronoi_peer_definition_arguments(const std::string& name) {
  const auto p = find_voronoi_command_peer(name);
  return p ? " --voronoi-peer " + command_text({p->name + "=" + command_text(p->argv)}) : "";
}

VoronoiPeerRun run_voronoi_command_peer(const CommandPeer& peer, std::span<const Point3> sites, const vor::Box& box,
                                        const VoronoiPeerOptions& options) {
  VoronoiPeerRun run;
  run.name = peer.name;
  TempDir dir("dtlab-vpeer");
  const std::string log = dir.file("log.txt"), in = dir.file("in.node"), out = dir.file("out");
  if (uses(peer, "{in}")) write_node(in, std::vector<Point3>(sites.begin(), sites.end()));
  if (uses(peer, "{sites}")) write_sites_text(out, sites);
  ChildLimits limits =
      ChildLimits::of(options.timeout_s, log, options.memory_bytes ? options.memory_bytes : default_peer_memory());
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  limits.memory_bytes = 0;  // as for the Delaunay command peers (oracle/peers/peer_command.cpp)
#endif
  const ChildResult c = run_child(expand(peer, in, out, box), limits);
  const bool failed = no_answer(c, log, run);
  run.message = replace_all(run.message, dir.path().string() + "/", "");  // the temp folder says nothing
  if (failed) return run;
  const std::string answer = answer_file(out);
  if (answer.empty()) {
    run.verdict = VoronoiVerdict::refused;
    run.message = "exited 0 but wrote no {out}.json (or {out}.vol)" + (run.message.empty() ? "" : ": " + run.message);
    return run;
  }
  try {
    PeerCells cells = answer.ends_with(".json") ? read_cells_json(answer) : read_cells_vol(answer);
    if (cells.seconds > 0) run.seconds = cells.seconds;
    run.report = check_voronoi(sites, box, cells.cells, options.check);
    run.verdict = run.report->verdict;
  } catch (const std::invalid_argument&) {
    throw;  // the checker refused the sites: not the peer's doing
  } catch (const std::bad_alloc&) {
    run.verdict = VoronoiVerdict::refused;
    run.message = "unreadable answer: out of memory reading its cells";
  } catch (const std::exception& e) {
    run.verdict = VoronoiVerdict::refused;
    run.message = "unreadable answer: " + replace_all(e.what(), dir.path().string() + "/", "");
  }
  return run;
}

}  // namespace dtlab
