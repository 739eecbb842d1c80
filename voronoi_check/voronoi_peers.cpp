#include "voronoi_check/voronoi_peers.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_child.hpp"
#include "oracle/peers/peer_exchange.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "voronoi_check/cell_exchange.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

#ifndef DTLAB_VORONOI_PEER_BINARY
#define DTLAB_VORONOI_PEER_BINARY "dtlab_voronoi_peer"
#endif
#ifndef DTLAB_VORONOI_PEER_SCRIPT
#define DTLAB_VORONOI_PEER_SCRIPT "voronoi_peer.py"
#endif

namespace dtlab {

namespace {

bool is_python_peer(const std::string& name) { return name == "scipy-voronoi" || name == "qvoronoi"; }

std::string from_env(const std::string& given, const char* var, const char* built) {
  if (!given.empty()) return given;
  const char* e = std::getenv(var);
  return e && *e ? e : built;
}

std::uint64_t memory_limit(const std::string& name, const VoronoiPeerOptions& o) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // A sanitizer build of our own helper reserves terabytes of shadow address space as
  // it starts, so RLIMIT_AS would kill it before it runs (as for the DT peer helpers in
  // oracle/peers/peers.cpp): in sanitizer builds only it runs without the memory limit.
  if (!is_python_peer(name)) return 0;
#else
  (void)name;
#endif
  return o.memory_bytes ? o.memory_bytes : default_peer_memory();
}

std::vector<std::string> command(const std::string& name, const VoronoiPeerOptions& o) {
  if (is_python_peer(name))
    return {o.python, from_env(o.script, "DTLAB_VORONOI_PEER_SCRIPT", DTLAB_VORONOI_PEER_SCRIPT),
            name == "qvoronoi" ? "qvoronoi" : "scipy"};
  return {from_env(o.helper, "DTLAB_VORONOI_PEER", DTLAB_VORONOI_PEER_BINARY), name};
}

std::string box_arg(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The verdict of a child that gave no answer, or "" when it answered.
bool no_answer(const ChildResult& c, const std::string& log, VoronoiPeerRun& run) {
  run.wall_seconds = c.seconds;
  run.peak_rss_bytes = c.peak_rss_bytes;
  switch (c.status) {
    case ChildStatus::not_started:
      run.verdict = VoronoiVerdict::not_installed, run.message = c.message;
      return true;
    case ChildStatus::timed_out:
      run.verdict = VoronoiVerdict::hung, run.message = "killed after the time limit";
      return true;
    case ChildStatus::output_limit: run.verdict = VoronoiVerdict::refused, run.message = c.message; return true;
    case ChildStatus::signaled:
      if (c.out_of_memory) break;
      run.verdict = VoronoiVerdict::crashed, run.message = strsignal(c.signal);
      return true;
    case ChildStatus::exited:
      if (c.exit_code == 0) return false;
      if (c.out_of_memory) break;
      run.verdict = c.exit_code == 4 ? VoronoiVerdict::not_installed : VoronoiVerdict::refused;
      run.message = last_line_of(log);
      return true;
  }
  run.verdict = VoronoiVerdict::out_of_memory;
  run.message = last_line_of(log).empty() ? c.message : last_line_of(log);
  return true;
}

}  // namespace

const std::vector<std::string>& voronoi_peer_names() {
  static const std::vector<std::string> names{"voro++",         "scipy-voronoi", "qvoronoi",
                                              "cgal-dual",      "dtlab:naive",   "dtlab:epsilon",
                                              "dtlab:adaptive", "dtlab:exact"};
  return names;
}

bool is_voronoi_peer_name(const std::string& name) {
  const auto& k = voronoi_peer_names();
  return std::find(k.begin(), k.end(), name) != k.end() || find_voronoi_command_peer(name).has_value();
}

std::vector<std::string> expand_voronoi_peer_names(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& n : names) {
    if (n == "all") {  // the built-in peers and the commands (voronoi_peer_command.hpp)
      out.insert(out.end(), voronoi_peer_names().begin(), voronoi_peer_names().end());
      for (const auto& c : voronoi_command_peer_names()) out.push_back(c);
      continue;
    }
    if (!is_voronoi_peer_name(n)) {
      std::string commands;
      for (const auto& c : voronoi_command_peer_names()) commands += ", " + c;
      throw std::invalid_argument("unknown Voronoi peer '" + n +
                                  "' (known: voro++, scipy-voronoi, qvoronoi, "
                                  "cgal-dual, dtlab:naive|epsilon|adaptive|exact" +
                                  commands + ", all; or --voronoi-peer NAME=COMMAND)");
    }
    out.push_back(n);
  }
  return out;
}

VoronoiPeerRun run_voronoi_peer(const std::string& name, std::span<const Point3> sites, const vor::Box& box,
                                const VoronoiPeerOptions& options) {
  expand_voronoi_peer_names({name});
  if (const auto c = find_voronoi_command_peer(name)) return run_voronoi_command_peer(*c, sites, box, options);
  VoronoiPeerRun run;
  run.name = name;
  TempDir dir("dtlab-vpeer");
  const std::string in = dir.file("sites.bin"), out = dir.file("cells.bin"), log = dir.file("log.txt");
  write_peer_points(in, std::vector<Point3>(sites.begin(), sites.end()));
  std::vector<std::string> argv = command(name, options);
  argv.insert(argv.end(), {in, out});
  for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z}) argv.push_back(box_arg(v));
  const ChildResult c = run_child(argv, ChildLimits::of(options.timeout_s, log, memory_limit(name, options)));
  if (no_answer(c, log, run)) return run;
  try {
    const PeerCells cells = read_peer_cells(out);
    run.seconds = cells.seconds;
    run.report = check_voronoi(sites, box, cells.cells, options.check);
    run.verdict = run.report->verdict;
  } catch (const std::runtime_error& e) {
    run.verdict = VoronoiVerdict::refused;
    run.message = std::string("malformed answer: ") + e.what();
  }
  return run;
}

std::string voronoi_peer_version(const std::string& name, const VoronoiPeerOptions& options) {
  expand_voronoi_peer_names({name});
  if (const auto c = find_voronoi_command_peer(name)) return "command: " + command_text(c->argv);
  TempDir dir("dtlab-vpeer");
  const std::string log = dir.file("log.txt");
  std::vector<std::string> argv = command(name, options);
  argv.insert(argv.begin() + (is_python_peer(name) ? 2 : 1), "--version");
  const ChildResult c = run_child(argv, ChildLimits::of(30, log));
  if (c.status != ChildStatus::exited || c.exit_code != 0) return "not installed";
  const std::string v = last_line_of(log);
  return v.empty() ? "unknown" : v;
}

}  // namespace dtlab
