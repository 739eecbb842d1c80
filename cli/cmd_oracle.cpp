// `dtlab oracle INPUT [--against PEERS|all] [kernel options as tetra] [--json]`: builds our
// DT, runs each peer in its own process (oracle/peers/peers.hpp), judges every answer with
// the exact checker against the input points, and compares ours canonically
// (oracle/check/compare.hpp) with every peer whose answer is proven Delaunay.
//
// Exit 0: ours is proven Delaunay and agrees with every Delaunay answer, and every
// requested peer answered; 1: ours is wrong or differs; 2: bad usage or input;
// 3: ours is fine but some peer gave no answer (crashed, hung, refused, or not
// installed when named explicitly), so the comparison is incomplete.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/build_options.hpp"
#include "cli/command.hpp"
#include "cli/input_points.hpp"
#include "cli/number_options.hpp"
#include "cli/peer_definitions.hpp"
#include "cli/progress.hpp"
#include "kernel/build.hpp"
#include "kernel/input_error.hpp"
#include "kernel/parallel_for.hpp"
#include "kernel/point_io.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/check/report_json.hpp"
#include "oracle/peers/oracle_session.hpp"
#include "oracle/peers/peer_json.hpp"
#include "oracle/peers/peers.hpp"
#include "oracle/peers/verdict.hpp"

namespace dtlab::cli {
namespace {

struct Args {
  std::string input;
  std::vector<std::string> against = {"cgal", "tetgen"};
  KernelArgs kernel;
  std::string tetgen = "tetgen";
  double timeout = 600;
  double memory_mb = 0;
  bool json = false;
  bool quiet = false;
  bool against_given = false;
  PeerDefinitionArgs defined;
};

void run_oracle(const Args& a, int& rc) {
  // Defined peers run too unless --against names the peers to run.
  std::vector<std::string> against = a.against;
  for (const auto& name : a.defined.register_all())
    if (!a.against_given && std::find(against.begin(), against.end(), name) == against.end()) against.push_back(name);
  const PointFile pf = read_input_points(a.input);
  const auto& pts = pf.points;
  OracleSessionOptions o;
  o.against = against;
  o.predicates = a.kernel.predicate_spec();
  o.build = a.kernel.build_options();
  o.peers.timeout_s = a.timeout;
  o.peers.memory_bytes = static_cast<std::uint64_t>(a.memory_mb * 1e6);
  o.peers.tetgen = a.tetgen;
  o.peers.threads = thread_count(a.kernel.threads);
  try {
    expand_peer_names(against);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--against", e.what());
  }
  Progress progress("oracle", a.quiet);
  o.progress = [&progress](const std::string& peer, std::size_t done, std::size_t total) {
    progress.update("peers", done, total, "running " + peer);
  };
  OracleSession s;
  try {
    s = run_oracle_session(pts, o);
  } catch (const std::invalid_argument& e) {
    // No 3D triangulation to compare (fewer than 4 points, coplanar...): bad input, as for tetra.
    throw InputError(a.input, 0, e.what());
  }
  rc = s.exit;
  if (a.json) {
    nlohmann::json j = to_json(s);
    j["input"] = a.input;
    j["points"] = pts.size();
    j["predicates"] = a.kernel.predicates;
    j["perturb"] = a.kernel.perturb;
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  const BuildResult& built = s.built;
  std::printf("%s: %zu points; dtlab %s, perturbation %s\n", a.input.c_str(), pts.size(), a.kernel.predicates.c_str(),
              a.kernel.perturb.c_str());
  std::printf("  %-16s %-15s %10s  %9s  %8s  %s\n", "peer", "verdict", "tets", "seconds", "peak", "defects / note");
  {
    const Verdict v = built.failure && s.ours.ok() ? Verdict::missing_points : verdict_of(s.ours);
    std::printf("  %-16s %-15s %10zu  %7.3f s  %8s  %s%s\n", "dtlab", verdict_name(v), built.mesh.tets.size(),
                built.stats.seconds, "-", defect_counts_text(s.ours).c_str(),
                built.failure ? (std::string(" build failed: ") + failure_name(built.failure->kind)).c_str() : "");
  }
  for (const PeerRun& p : s.peers) std::printf("  %-16s %s\n", p.name.c_str(), peer_line(p).c_str());
  for (const auto& c : s.compared)
    std::printf("  dtlab vs %s: %s\n", s.peers[c.peer].name.c_str(), comparison_text(c.comparison).c_str());
  if (!s.not_compared.empty()) {
    std::string line;
    for (const auto& n : s.not_compared) line += (line.empty() ? "" : ", ") + n;
    std::printf("  not compared: %s\n", line.c_str());
  }
  for (const auto& p : s.problems) std::printf("  PROBLEM: %s\n", p.c_str());
  std::printf("%s\n", rc == oracle_ok ? "OK" : rc == oracle_defect ? "FAILED" : "INCOMPLETE (some peer gave no answer)");
}

}  // namespace

void add_oracle_command(CLI::App& app, int& rc) {
  CLI::App* sub = app.add_subcommand(
      "oracle", "judge other Delaunay codes (CGAL, TetGen, qhull, scipy, gmsh, ...) with the exact checker");
  auto a = std::make_shared<Args>();
  sub->add_option("INPUT", a->input, kInputPointsHelp)->required();
  std::string peers;
  for (const auto& n : peer_names()) peers += (peers.empty() ? "" : ", ") + n;
  auto* against = sub->add_option("--against", a->against, "peers to run, or all: " + peers + " (and the --peer names)")
                      ->delimiter(',')
                      ->capture_default_str();
  a->defined.add_to(*sub);
  sub->add_option("--tetgen", a->tetgen, "the tetgen binary")->capture_default_str();
  sub->add_option("--timeout", a->timeout, "seconds before a peer counts as hung")->check(number_in(0.001, 1e6))->capture_default_str();
  sub->add_option("--memory", a->memory_mb, "memory limit per peer in MB (0: half the machine's)")->check(number_in(0, 1e9));
  sub->add_flag("--json", a->json, "print a JSON object keyed by peer on stdout");
  sub->add_flag("--quiet", a->quiet, "no progress lines on stderr");
  a->kernel.add_to(*sub, kAllKernelOptions | kThreadsOption);  // how dtlab's own DT is built, as in tetra
  sub->footer(
      "Verdicts: delaunay, triangulation, flat-tets, invalid, unproven, missing-points, extra-points, crashed, hung, refused, "
      "not-installed.\nExit: 0 ok, 1 dtlab wrong or differing, 2 bad input, 3 some peer gave no answer.");
  sub->callback([a, against, &rc] {
    a->against_given = against->count() > 0;
    run_oracle(*a, rc);
  });
}

}  // namespace dtlab::cli
