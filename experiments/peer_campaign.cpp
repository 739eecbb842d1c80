#include "experiments/peer_campaign.hpp"

#include <algorithm>
#include <chrono>

#include <nlohmann/json.hpp>

#include "experiments/report.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/outcome.hpp"
#include "fuzz/shrink.hpp"
#include "oracle/peers/peer_command.hpp"
#include "oracle/peers/peer_json.hpp"
#include "oracle/peers/served_child.hpp"

namespace dtlab::experiments {

bool peer_failed(Verdict v, bool lower_dimensional) {
  if (v == Verdict::not_installed || v == Verdict::delaunay) return false;
  if (lower_dimensional && v == Verdict::refused) return false;
  return true;
}

bool PeerCase::failed() const { return peer_failed(run.verdict, lower_dimensional); }

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

PeerRun without_mesh(PeerRun r) {
  r.mesh.reset();
  return r;
}

}  // namespace

void shrink_pass(PeerCase& c, const std::vector<Point3>& original, const PeerOptions& options, ShrinkBudget budget,
                 ServedChildren* servers) {
  const auto t0 = Clock::now();
  const Verdict target = c.run.verdict;
  const bool hung = target == Verdict::hung;
  if (c.shrunk_input.empty()) {  // the first pass: start from the original, judged in its counted run
    c.shrunk_input = original;
    c.shrunk_run = without_mesh(c.run);
    c.shrink_position = {};
  }
  ++c.shrink_passes;
  const std::vector<Point3> start = c.shrunk_input;
  const auto finish = [&](fuzz::ShrinkResult s, bool out_of_time, PeerRun fresh, std::size_t runs) {
    c.shrunk_input = std::move(s.points);
    c.shrunk_points = c.shrunk_input.size();
    c.shrink_position = s.position;
    c.shrunk_minimal = s.minimal && !out_of_time;
    c.shrink_stop = out_of_time ? "time" : s.minimal ? "" : "runs";
    c.shrink_runs += runs;
    c.shrink_tests += s.tests;
    c.shrink_seconds += seconds_since(t0);
    c.shrunk_run = without_mesh(std::move(fresh));
    c.shrunk_verdict = c.shrunk_run.verdict;
  };
  if (hung && budget.hung_try_seconds <= 0) {
    fuzz::ShrinkResult unshrunk;
    unshrunk.points = start;
    unshrunk.position = c.shrink_position;
    finish(std::move(unshrunk), false, c.shrunk_run, 0);
    c.shrink_stop = "hung";
    return;
  }
  ServedChildren own;
  PeerOptions tries = options;
  tries.servers = servers ? servers : &own;
  tries.timeout_s = hung ? std::min(budget.hung_try_seconds, options.timeout_s)
                         : shrink_try_limit(c.run.wall_seconds, options.timeout_s);
  if (hung) c.hung_try_seconds = tries.timeout_s;
  // A failure on a 3D input must stay 3D (else any peer "fails" a flat subset by
  // refusing it); one on a flat input may shrink within flat inputs.
  const bool flat = fuzz::is_lower_dimensional(original);
  bool out_of_time = false;
  std::size_t runs = 0;
  const auto seconds_left = [&] { return budget.seconds > 0 ? budget.seconds - seconds_since(t0) : 1e300; };
  const auto stop = [&] { return out_of_time = out_of_time || seconds_left() <= 0; };
  const auto shrink_with = [&](const PeerOptions& run_options, std::size_t run_budget, fuzz::ShrinkPosition from) {
    const auto fails = [&](const std::vector<Point3>& candidate) {
      if (!flat && fuzz::is_lower_dimensional(candidate)) return false;
      // Each try ends within the budget: one cut short by it tells nothing, and ends the pass.
      const double left = seconds_left();
      if (left <= 0) {
        out_of_time = true;
        return false;
      }
      ++runs;
      PeerOptions o = run_options;
      o.timeout_s = std::min(run_options.timeout_s, left);
      const Verdict v = run_peer(c.peer, candidate, o).verdict;
      if (v == Verdict::hung && o.timeout_s < run_options.timeout_s) {
        out_of_time = true;
        return false;
      }
      return v == target;  // for a hang: it exceeded the short limit
    };
    return fuzz::shrink_points(start, fails, run_budget, from, stop);
  };
  fuzz::ShrinkResult s = shrink_with(tries, budget.runs, c.shrink_position);
  if (hung || s.points.size() == start.size()) {  // a hang is confirmed once, after the last pass
    finish(std::move(s), out_of_time, c.shrunk_run, runs);
    return;
  }
  // A shrunk input judged once more in a fresh process (under the tries' limit). A
  // served helper can carry state from one try to the next (gmsh's answers depend on
  // its memory layout): when the fresh run disagrees, shrink again with fresh
  // processes in what is left of the budget.
  PeerOptions fresh = tries;
  fresh.servers = nullptr;
  PeerRun again = run_peer(c.peer, s.points, fresh);
  if (again.verdict != target) {
    c.served_not_reproduced = s.points.size();
    const std::size_t tests = s.tests;
    out_of_time = false;
    s = shrink_with(fresh, budget.runs > runs ? budget.runs - runs : 0, {});
    s.tests += tests;
    again = s.points.size() == start.size() ? c.shrunk_run : run_peer(c.peer, s.points, fresh);
  }
  finish(std::move(s), out_of_time, std::move(again), runs);
}

void confirm_hang(PeerCase& c, const std::vector<Point3>& original, const PeerOptions& options,
                  double seconds_left) {
  if (c.run.verdict != Verdict::hung || c.shrunk_input.size() >= original.size()) return;
  const auto t0 = Clock::now();
  const std::size_t shrunk = c.shrunk_input.size();
  PeerOptions fresh = options;
  fresh.servers = nullptr;
  std::string why;
  if (seconds_left < options.timeout_s) {
    why = "no time left for a confirming run under the " + fmt("%g", options.timeout_s) + " s limit";
  } else {
    PeerRun r = run_peer(c.peer, c.shrunk_input, fresh);
    ++c.shrink_runs;
    if (r.verdict == Verdict::hung) {
      c.shrunk_run = without_mesh(std::move(r));
      c.shrunk_verdict = Verdict::hung;
      c.shrink_seconds += seconds_since(t0);
      return;
    }
    why = std::string("that input gave ") + verdict_name(r.verdict) + " after " + fmt("%.1f", r.wall_seconds) +
          " s in a fresh process under the " + fmt("%g", options.timeout_s) + " s limit";
  }
  c.shrink_note = "shrunk to " + std::to_string(shrunk) + " points under a " + fmt("%.1f", c.hung_try_seconds) +
                  " s limit per try, but " + why + "; the original input is saved";
  c.shrunk_input = original;
  c.shrunk_points = original.size();
  c.shrunk_minimal = false;
  c.shrink_stop = "unconfirmed";
  c.shrunk_run = without_mesh(c.run);
  c.shrunk_verdict = c.run.verdict;
  c.shrink_seconds += seconds_since(t0);
}

void save_shrunk(PeerCase& c, std::size_t original_points, const std::string& out_dir,
                 const std::string& original_command) {
  const std::string stem = corpus_stem(c.peer, c.source, c.n, c.index);
  c.corpus_file = save_corpus_points(out_dir, stem, c.shrunk_input);
  nlohmann::json j = case_sidecar(
      c, original_points, c.shrunk_input.size(),
      "dtlab oracle " + c.corpus_file + " --against " + c.peer + peer_definition_arguments(c.peer), original_command);
  j["verdict"] = verdict_name(c.run.verdict);
  j["shrink_tests"] = c.shrink_tests;
  j["shrink_passes"] = c.shrink_passes;
  j["served_shrink_not_reproduced"] = c.served_not_reproduced;  // points of a served shrink a fresh run disagreed with
  j["shrunk_run"] = to_json(c.shrunk_run);
  if (c.hung_try_seconds > 0) j["hung_try_seconds"] = c.hung_try_seconds;  // the short limit of a hang's tries
  if (!c.shrink_note.empty()) j["shrink_note"] = c.shrink_note;
  save_corpus_sidecar(out_dir, stem, j);
}

void shrink_and_save(PeerCase& c, const std::vector<Point3>& points, const PeerOptions& options,
                     ShrinkBudget budget, const std::string& out_dir, const std::string& original_command,
                     ServedChildren* servers) {
  const auto t0 = Clock::now();
  shrink_pass(c, points, options, budget, servers);
  const double left = budget.seconds > 0 ? budget.seconds - seconds_since(t0) : options.timeout_s;
  confirm_hang(c, points, options, left);
  save_shrunk(c, points.size(), out_dir, original_command);
}

std::vector<PeerCase> run_peer_campaign(const PeerCampaignOptions& o) {
  const std::vector<std::string> peers = o.peers.empty() ? std::vector<std::string>{o.peer} : o.peers;
  if (!o.out_dir.empty()) remove_grid_corpus(peers, o);
  return run_grid<PeerCase>(
      peers, o,
      [&](PeerCase& c, const std::vector<Point3>& points) {
        c.lower_dimensional = fuzz::is_lower_dimensional(points);
        c.run = run_peer(c.peer, points, o.peer_options);
        c.run.mesh.reset();
        if (c.failed() && o.shrink && !o.out_dir.empty() && c.run.verdict != Verdict::hung) {
          const std::string cmd = grid_case_command(c.peer + peer_definition_arguments(c.peer), o, c.source, c.index);
          shrink_and_save(c, points, o.peer_options, {o.shrink_budget, 0}, o.out_dir, cmd);
        }
      },
      o.on_case);
}

}  // namespace dtlab::experiments
