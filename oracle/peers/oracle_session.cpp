#include "oracle/peers/oracle_session.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "kernel/progress.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/report_json.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_json.hpp"
#include "oracle/peers/verdict.hpp"

namespace dtlab {
namespace {

std::string cell_text(const std::vector<std::uint32_t>& c) {
  std::string s = "{";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(c[i]);
  }
  return s + "}";
}

}  // namespace

std::string comparison_text(const Comparison& c) {
  std::ostringstream o;
  if (c.agree()) {
    if (c.general_position)
      o << "agree (general position: identical tets)";
    else if (c.tets_equal)
      o << "agree (identical tets; " << c.cells_a << " Delaunay cells)";
    else
      o << "agree (same Delaunay complex, " << c.cells_a << " cells; tets differ inside cospherical cells)";
  } else {
    o << "DIFFER: " << c.only_a_count << " cells only in dtlab's, " << c.only_b_count << " only in the peer's";
    if (!c.only_a.empty()) o << "; e.g. dtlab only " << cell_text(c.only_a[0]);
    if (!c.only_b.empty()) o << "; e.g. peer only " << cell_text(c.only_b[0]);
  }
  return o.str();
}

OracleSession run_oracle_session(std::span<const Point3> pts, const OracleSessionOptions& opt) {
  const std::vector<std::string> names = expand_peer_names(opt.against);
  const bool all = std::find(opt.against.begin(), opt.against.end(), "all") != opt.against.end();
  OracleSession s;
  // Between stages, a host's interrupt check (child_process.hpp) ends the session.
  const auto stop_if_interrupted = [] {
    if (interrupt_requested()) throw ChildInterrupted();
  };
  s.built = build_delaunay(pts, opt.predicates, opt.build);
  stop_if_interrupted();
  if (s.built.failure && s.built.failure->kind == FailureKind::lower_dimensional)
    throw std::invalid_argument(s.built.failure->detail);
  CheckOptions check_options;
  check_options.duplicates = s.built.duplicates;
  check_options.threads = opt.peers.threads;
  s.ours = check_tetrahedralization(s.built.mesh, check_options);
  s.ours_ok = s.ours.ok() && !s.built.failure;

  for (const auto& name : names) {
    stop_if_interrupted();
    if (opt.progress) opt.progress(name, s.peers.size(), names.size());
    {
      const ProgressScope quiet(nullptr);
      s.peers.push_back(run_peer(name, pts, opt.peers));
    }
    if (opt.on_peer) opt.on_peer(s.peers.back(), s.peers.size(), names.size());
  }
  bool incomplete = false;
  for (std::size_t i = 0; i < s.peers.size(); ++i) {
    const PeerRun& p = s.peers[i];
    if (no_answer(p.verdict)) {
      s.not_compared.push_back(p.name + " (" + verdict_name(p.verdict) + ")");
      // `all` means "every installed peer": a missing one is listed, not a failure.
      if (p.verdict != Verdict::not_installed || !all) incomplete = true;
      continue;
    }
    if (p.verdict != Verdict::delaunay) {
      s.not_compared.push_back(p.name + " (its answer is " + verdict_name(p.verdict) + ")");
      continue;
    }
    if (s.ours_ok) s.compared.push_back({i, compare_canonical(s.built.mesh, s.ours, *p.mesh, *p.report)});
  }
  if (!s.ours_ok) {
    std::string why = s.built.failure ? std::string("build failed (") + failure_name(s.built.failure->kind) + ")" : "";
    const std::string counts = defect_counts_text(s.ours);
    if (!counts.empty()) why += (why.empty() ? "" : "; ") + counts;
    s.problems.push_back("dtlab's result is wrong: " + why);
  }
  for (const auto& c : s.compared) {
    const std::string& name = s.peers[c.peer].name;
    if (!c.comparison.agree()) s.problems.push_back("dtlab differs from " + name + ", both proven Delaunay");
    // With sos, which is CGAL's perturbation, the tets themselves must be CGAL's.
    if (opt.predicates.perturb && name == "cgal" && !c.comparison.tets_equal)
      s.problems.push_back("dtlab's tets differ from CGAL's although both use the sos perturbation");
  }
  s.exit = !s.problems.empty() ? oracle_defect : incomplete ? oracle_no_answer : oracle_ok;
  return s;
}

nlohmann::json to_json(const OracleSession& s) {
  nlohmann::json j;
  j["ok"] = s.exit == oracle_ok;
  j["exit"] = s.exit;
  j["problems"] = s.problems;
  j["not_compared"] = s.not_compared;
  nlohmann::json d;
  d["verdict"] = s.ours_ok ? "delaunay" : verdict_name(verdict_of(s.ours));
  d["seconds"] = s.built.stats.seconds;
  d["tets"] = s.built.mesh.tets.size();
  d["duplicates"] = s.built.duplicates.size();
  if (s.built.failure) d["failure"] = failure_name(s.built.failure->kind);
  d["check"] = to_json(s.ours);
  j["dtlab"] = d;
  j["peers"] = nlohmann::json::object();
  for (const PeerRun& p : s.peers) j["peers"][p.name] = to_json(p);
  j["comparisons"] = nlohmann::json::object();
  for (const auto& c : s.compared) {
    j["peers"][s.peers[c.peer].name]["agree"] = c.comparison.agree();
    j["comparisons"]["dtlab vs " + s.peers[c.peer].name] = to_json(c.comparison);
  }
  return j;
}

}  // namespace dtlab
