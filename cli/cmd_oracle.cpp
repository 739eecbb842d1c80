// `dtlab oracle INPUT [--against PEERS|all] [--predicates NAME] [--perturb sos|none]
// [--json]`: builds our DT, runs each peer in its own process (oracle/peers.hpp),
// judges every answer with the exact checker against the input points, and compares
// ours canonically (oracle/compare.hpp) with every peer whose answer is proven
// Delaunay.
// Exit 0: ours is proven Delaunay and agrees with every Delaunay answer, and every
// requested peer answered; 1: ours is wrong or differs; 2: bad usage or input;
// 3: ours is fine but some peer gave no answer (crashed, hung, refused, or not
// installed when named explicitly), so the comparison is incomplete.
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/input_points.hpp"
#include "kernel/build.hpp"
#include "kernel/point_io.hpp"
#include "oracle/check.hpp"
#include "oracle/compare.hpp"
#include "oracle/peer_json.hpp"
#include "oracle/peers.hpp"
#include "oracle/report_json.hpp"

namespace dtlab::cli {
namespace {

constexpr int kNoAnswer = 3;

struct Args {
  std::string input;
  std::vector<std::string> against = {"cgal", "tetgen"};
  std::string predicates = "adaptive";
  std::string perturb = "sos";
  std::string tetgen = "tetgen";
  double timeout = 600;
  double memory_mb = 0;
  bool json = false;
};

std::string cell_text(const std::vector<std::uint32_t>& c) {
  std::string s = "{";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(c[i]);
  }
  return s + "}";
}

std::string comparison_text(const Comparison& c) {
  std::ostringstream o;
  if (c.agree()) {
    if (c.general_position) o << "agree (general position: identical tets)";
    else if (c.tets_equal) o << "agree (identical tets; " << c.cells_a << " Delaunay cells)";
    else o << "agree (same Delaunay complex, " << c.cells_a << " cells; tets differ inside cospherical cells)";
  } else {
    o << "DIFFER: " << c.only_a_count << " cells only in dtlab's, " << c.only_b_count << " only in the peer's";
    if (!c.only_a.empty()) o << "; e.g. dtlab only " << cell_text(c.only_a[0]);
    if (!c.only_b.empty()) o << "; e.g. peer only " << cell_text(c.only_b[0]);
  }
  return o.str();
}

void run_oracle(const Args& a, int& rc) {
  std::vector<std::string> names;
  try {
    names = expand_peer_names(a.against);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--against", e.what());
  }
  bool all = false;
  for (const auto& n : a.against) all = all || n == "all";
  if (!(a.timeout > 0) || a.memory_mb < 0) throw CLI::ValidationError("--timeout/--memory", "must be positive");

  const PointFile pf = read_input_points(a.input);
  const auto& pts = pf.points;

  PredicateSpec spec;
  spec.backend = a.predicates;
  spec.perturb = a.perturb == "sos";
  const BuildResult built = build_delaunay(pts, spec, BuildOptions{});
  if (built.failure && built.failure->kind == FailureKind::lower_dimensional) {
    // No 3D triangulation to compare (fewer than 4 points, coplanar...): bad input, as for tetra.
    std::fprintf(stderr, "dtlab oracle: %s: %s\n", a.input.c_str(), built.failure->detail.c_str());
    rc = kBadInput;
    return;
  }
  CheckOptions check_options;
  check_options.duplicates = built.duplicates;
  const CheckReport ours = check_tetrahedralization(built.mesh, check_options);
  const bool ours_ok = ours.ok() && !built.failure;

  PeerOptions po;
  po.timeout_s = a.timeout;
  po.memory_bytes = static_cast<std::uint64_t>(a.memory_mb * 1e6);
  po.tetgen = a.tetgen;
  std::vector<PeerRun> peers;
  for (const auto& name : names) peers.push_back(run_peer(name, pts, po));

  // Ours against every peer whose answer the checker proved Delaunay. A peer with
  // no answer, or a wrong one, is "not compared", never "agree".
  struct Compared {
    std::size_t peer;
    Comparison c;
  };
  std::vector<Compared> compared;
  std::vector<std::string> not_compared, problems;
  bool incomplete = false;
  for (std::size_t i = 0; i < peers.size(); ++i) {
    const PeerRun& p = peers[i];
    if (no_answer(p.verdict)) {
      not_compared.push_back(p.name + " (" + verdict_name(p.verdict) + ")");
      if (p.verdict != Verdict::not_installed || !all) incomplete = true;
      continue;
    }
    if (p.verdict != Verdict::delaunay) {
      not_compared.push_back(p.name + " (its answer is " + verdict_name(p.verdict) + ")");
      continue;
    }
    if (!ours_ok) continue;
    compared.push_back({i, compare_canonical(built.mesh, ours, *p.mesh, *p.report)});
  }
  if (!ours_ok) {
    std::string why = built.failure ? std::string("build failed (") + failure_name(built.failure->kind) + ")" : "";
    const std::string counts = defect_counts_text(ours);
    if (!counts.empty()) why += (why.empty() ? "" : "; ") + counts;
    problems.push_back("dtlab's result is wrong: " + why);
  }
  for (const Compared& c : compared) {
    const std::string& name = peers[c.peer].name;
    if (!c.c.agree()) problems.push_back("dtlab differs from " + name + ", both proven Delaunay");
    // With sos, which is CGAL's perturbation, the tets themselves must be CGAL's.
    if (spec.perturb && name == "cgal" && !c.c.tets_equal)
      problems.push_back("dtlab's tets differ from CGAL's although both use the sos perturbation");
  }
  rc = !problems.empty() ? kDefect : incomplete ? kNoAnswer : kOk;
  const char* status = rc == kOk ? "OK" : rc == kDefect ? "FAILED" : "INCOMPLETE (some peer gave no answer)";

  if (a.json) {
    nlohmann::json j;
    j["input"] = a.input;
    j["points"] = pts.size();
    j["predicates"] = a.predicates;
    j["perturb"] = a.perturb;
    j["ok"] = rc == kOk;
    j["exit"] = rc;
    j["problems"] = problems;
    j["not_compared"] = not_compared;
    nlohmann::json d;
    d["verdict"] = ours_ok ? "delaunay" : verdict_name(verdict_of(ours));
    d["seconds"] = built.stats.seconds;
    d["tets"] = built.mesh.tets.size();
    d["duplicates"] = built.duplicates.size();
    if (built.failure) d["failure"] = failure_name(built.failure->kind);
    d["check"] = to_json(ours);
    j["dtlab"] = d;
    j["peers"] = nlohmann::json::object();
    for (const PeerRun& p : peers) j["peers"][p.name] = to_json(p);
    for (const Compared& c : compared) {
      j["peers"][peers[c.peer].name]["agree"] = c.c.agree();
      j["comparisons"]["dtlab vs " + peers[c.peer].name] = to_json(c.c);
    }
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("%s: %zu points; dtlab %s, perturbation %s\n", a.input.c_str(), pts.size(), a.predicates.c_str(),
              a.perturb.c_str());
  std::printf("  %-16s %-15s %10s  %9s  %8s  %s\n", "peer", "verdict", "tets", "seconds", "peak", "defects / note");
  {
    const Verdict v = built.failure && ours.ok() ? Verdict::missing_points : verdict_of(ours);
    std::printf("  %-16s %-15s %10zu  %7.3f s  %8s  %s%s\n", "dtlab", verdict_name(v), built.mesh.tets.size(),
                built.stats.seconds, "-", defect_counts_text(ours).c_str(),
                built.failure ? (std::string(" build failed: ") + failure_name(built.failure->kind)).c_str() : "");
  }
  for (const PeerRun& p : peers) std::printf("  %-16s %s\n", p.name.c_str(), peer_line(p).c_str());
  for (const Compared& c : compared)
    std::printf("  dtlab vs %s: %s\n", peers[c.peer].name.c_str(), comparison_text(c.c).c_str());
  if (!not_compared.empty()) {
    std::string s;
    for (const auto& n : not_compared) s += (s.empty() ? "" : ", ") + n;
    std::printf("  not compared: %s\n", s.c_str());
  }
  for (const auto& s : problems) std::printf("  PROBLEM: %s\n", s.c_str());
  std::printf("%s\n", status);
}

}  // namespace

void add_oracle_command(CLI::App& app, int& rc) {
  CLI::App* sub = app.add_subcommand(
      "oracle", "judge other Delaunay codes (CGAL, TetGen, qhull, scipy, gmsh, ...) with the exact checker");
  auto a = std::make_shared<Args>();
  sub->add_option("INPUT", a->input, "point file (.node, .xyz) or mesh file (.off .obj .ply .stl)")->required();
  std::string peers;
  for (const auto& n : peer_names()) peers += (peers.empty() ? "" : ", ") + n;
  sub->add_option("--against", a->against, "peers to run, or all: " + peers)->delimiter(',')->capture_default_str();
  sub->add_option("--predicates", a->predicates, "our backend: naive|epsilon|adaptive|exact");
  sub->add_option("--perturb", a->perturb, "symbolic perturbation: sos|none")
      ->check(CLI::IsMember({"sos", "none"}));
  sub->add_option("--tetgen", a->tetgen, "the tetgen binary");
  sub->add_option("--timeout", a->timeout, "seconds before a peer counts as hung")->check(number_in(0.001, 1e6))->capture_default_str();
  sub->add_option("--memory", a->memory_mb, "memory limit per peer in MB (0: half the machine's)")->check(number_in(0, 1e9));
  sub->add_flag("--json", a->json, "print a JSON object keyed by peer on stdout");
  sub->footer(
      "Verdicts: delaunay, triangulation, flat-tets, invalid, missing-points, extra-points, crashed, hung, refused, "
      "not-installed.\nExit: 0 ok, 1 dtlab wrong or differing, 2 bad input, 3 some peer gave no answer.");
  sub->callback([a, &rc] { run_oracle(*a, rc); });
}

}  // namespace dtlab::cli
