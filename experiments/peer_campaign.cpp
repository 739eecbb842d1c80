#include "experiments/peer_campaign.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "fuzz/work_queue.hpp"
#include "kernel/output_file.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "fuzz/outcome.hpp"
#include "fuzz/shrink.hpp"
#include "kernel/point_io.hpp"
#include "oracle/peer_json.hpp"
#include "oracle/served_child.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;

std::vector<PointSource> fuzz_family_sources(const std::vector<std::string>& names) {
  std::vector<PointSource> out;
  for (const auto& name : names) {
    const fuzz::Family* f = fuzz::find_family(name);
    if (!f) throw std::invalid_argument("unknown family '" + name + "'");
    out.push_back({f->name, f->generate});
  }
  return out;
}

bool peer_failed(Verdict v, bool lower_dimensional) {
  if (v == Verdict::not_installed || v == Verdict::delaunay) return false;
  if (lower_dimensional && v == Verdict::refused) return false;
  return true;
}

bool PeerCase::failed() const { return peer_failed(run.verdict, lower_dimensional); }

void shrink_and_save(PeerCase& c, const std::vector<Point3>& points, const PeerOptions& options,
                     ShrinkBudget budget, const std::string& out_dir, const std::string& original_command,
                     ServedChildren* servers) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const Verdict target = c.run.verdict;
  ServedChildren own;
  PeerOptions tries = options;
  tries.servers = servers ? servers : &own;
  tries.timeout_s = std::clamp(10 * c.run.wall_seconds, std::min(2.0, options.timeout_s), options.timeout_s);
  PeerOptions fresh = options;
  fresh.servers = nullptr;
  // A failure on a 3D input must stay 3D (else any peer "fails" a flat subset by
  // refusing it); one on a flat input may shrink within flat inputs.
  const bool flat = fuzz::is_lower_dimensional(points);
  bool out_of_time = false;
  std::size_t runs = 0;
  const auto shrink_with = [&](const PeerOptions& run_options, std::size_t run_budget) {
    const auto fails = [&](const std::vector<Point3>& candidate) {
      if (!flat && fuzz::is_lower_dimensional(candidate)) return false;
      if (budget.seconds > 0 && std::chrono::duration<double>(Clock::now() - t0).count() > budget.seconds)
        out_of_time = true;
      if (out_of_time) return false;  // the shrinker then ends without more runs
      ++runs;
      return run_peer(c.peer, candidate, run_options).verdict == target;
    };
    return fuzz::shrink_points(points, fails, run_budget);
  };
  const bool hung = target == Verdict::hung;
  fuzz::ShrinkResult s = shrink_with(tries, hung ? 0 : budget.runs);
  // A shrunk input judged once more in a fresh process (an unshrunk one already was).
  // A served helper can carry state from one try to the next (gmsh's answers depend
  // on its memory layout): when the fresh run disagrees, shrink again with fresh
  // processes in what is left of the budget.
  PeerRun again = s.points.size() == points.size() ? c.run : run_peer(c.peer, s.points, fresh);
  std::size_t served_shrunk = 0;
  if (again.verdict != target) {
    served_shrunk = s.points.size();
    out_of_time = false;
    PeerOptions fresh_tries = tries;
    fresh_tries.servers = nullptr;
    s = shrink_with(fresh_tries, budget.runs > runs ? budget.runs - runs : 0);
    again = s.points.size() == points.size() ? c.run : run_peer(c.peer, s.points, fresh);
  }
  c.shrunk_points = s.points.size();
  c.shrunk_minimal = s.minimal && !out_of_time && !hung;
  c.shrink_stop = hung ? "hung" : out_of_time ? "time" : s.minimal ? "" : "runs";
  c.shrink_runs = runs;
  c.shrunk_verdict = again.verdict;
  const fs::path dir = fs::path(out_dir) / "corpus";
  fs::create_directories(dir);
  std::string stem = c.peer + "-" + c.source + "-n" + std::to_string(c.n) + "-" + std::to_string(c.index);
  std::replace(stem.begin(), stem.end(), ':', '_');
  write_node((dir / (stem + ".node")).string(), s.points);
  c.corpus_file = "corpus/" + stem + ".node";
  c.shrink_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  nlohmann::json j = {
      {"peer", c.peer},
      {"file", c.corpus_file},
      {"source", c.source},
      {"case", c.index},
      {"case_seed", c.seed},
      {"points_original", c.n},
      {"points", s.points.size()},
      {"verdict", verdict_name(target)},
      {"shrink_tests", s.tests},
      {"shrink_runs", runs},
      {"shrink_seconds", c.shrink_seconds},
      {"minimal", c.shrunk_minimal},
      {"shrink_stopped_by", c.shrink_stop},
      {"served_shrink_not_reproduced", served_shrunk},  // points of a served shrink a fresh run disagreed with
      {"shrunk_run", to_json(again)},
      {"command", "dtlab oracle " + c.corpus_file + " --against " + c.peer},
      {"original_command", original_command},
  };
  write_text_file((dir / (stem + ".json")).string(), j.dump(2) + "\n");
}

std::vector<PeerCase> run_peer_campaign(const PeerCampaignOptions& o) {
  struct Work {
    const std::string* peer;
    const PointSource* source;
    std::size_t index;
  };
  const std::vector<std::string> peers = o.peers.empty() ? std::vector<std::string>{o.peer} : o.peers;
  std::vector<Work> work;
  for (const std::string& p : peers)
    for (const PointSource& s : o.sources)
      for (std::size_t i = 0; i < o.cases; ++i)
        if (!o.only_case || *o.only_case == i) work.push_back({&p, &s, i});
  std::vector<PeerCase> results(work.size());
  std::mutex lock;
  const auto run_one = [&](std::size_t w) {
    PeerCase c;
    c.peer = *work[w].peer;
    c.source = work[w].source->name;
    c.index = work[w].index;
    c.seed = fuzz::case_seed(o.seed, c.source, c.index);
    const std::size_t n = fuzz::case_points(c.seed, o.min_points, o.max_points);
    const std::vector<Point3> points = work[w].source->generate(n, c.seed);
    c.n = points.size();
    c.lower_dimensional = fuzz::is_lower_dimensional(points);
    c.run = run_peer(c.peer, points, o.peer_options);
    c.run.mesh.reset();
    if (c.failed() && o.shrink && !o.out_dir.empty() && c.run.verdict != Verdict::hung) {
      const std::string cmd = "dtlab fuzz --target " + c.peer + " --family " + c.source + " --case " +
                              std::to_string(c.index) + " --seed " + std::to_string(o.seed) + " --min-points " +
                              std::to_string(o.min_points) + " --points " + std::to_string(o.max_points) +
                              " --out DIR";
      shrink_and_save(c, points, o.peer_options, {o.shrink_budget, 0}, o.out_dir, cmd);
    }
    std::lock_guard<std::mutex> g(lock);
    if (o.on_case) o.on_case(c);
    results[w] = std::move(c);
  };
  // The first exception (a folder that cannot be written) stops the queue and is
  // rethrown here.
  fuzz::run_work_queue(work.size(), o.jobs, run_one);
  return results;
}

}  // namespace dtlab::experiments
