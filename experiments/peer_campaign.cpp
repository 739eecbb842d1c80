#include "experiments/peer_campaign.hpp"

#include <algorithm>
#include <atomic>
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
                     std::size_t budget, const std::string& out_dir, const std::string& original_command) {
  const Verdict target = c.run.verdict;
  const PeerOptions& quiet = options;
  // A failure on a 3D input must stay 3D (else any peer "fails" a flat subset by
  // refusing it); one on a flat input may shrink within flat inputs.
  const bool flat = fuzz::is_lower_dimensional(points);
  const auto fails = [&](const std::vector<Point3>& candidate) {
    if (!flat && fuzz::is_lower_dimensional(candidate)) return false;
    return run_peer(c.peer, candidate, quiet).verdict == target;
  };
  const fuzz::ShrinkResult s = fuzz::shrink_points(points, fails, budget);
  c.shrunk_points = s.points.size();
  c.shrunk_minimal = s.minimal;
  const fs::path dir = fs::path(out_dir) / "corpus";
  fs::create_directories(dir);
  std::string stem = c.peer + "-" + c.source + "-n" + std::to_string(c.n) + "-" + std::to_string(c.index);
  std::replace(stem.begin(), stem.end(), ':', '_');
  write_node((dir / (stem + ".node")).string(), s.points);
  c.corpus_file = "corpus/" + stem + ".node";
  // The shrunk input judged once more, for the sidecar.
  const PeerRun again = run_peer(c.peer, s.points, quiet);
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
      {"minimal", s.minimal},
      {"shrunk_run", to_json(again)},
      {"command", "dtlab oracle " + c.corpus_file + " --against " + c.peer},
      {"original_command", original_command},
  };
  write_text_file((dir / (stem + ".json")).string(), j.dump(2) + "\n");
}

std::vector<PeerCase> run_peer_campaign(const PeerCampaignOptions& o) {
  struct Work {
    const PointSource* source;
    std::size_t index;
  };
  std::vector<Work> work;
  for (const PointSource& s : o.sources)
    for (std::size_t i = 0; i < o.cases; ++i)
      if (!o.only_case || *o.only_case == i) work.push_back({&s, i});
  std::vector<PeerCase> results(work.size());
  std::mutex lock;
  const auto run_one = [&](std::size_t w) {
    PeerCase c;
    c.peer = o.peer;
    c.source = work[w].source->name;
    c.index = work[w].index;
    c.seed = fuzz::case_seed(o.seed, c.source, c.index);
    const std::size_t n = fuzz::case_points(c.seed, o.min_points, o.max_points);
    const std::vector<Point3> points = work[w].source->generate(n, c.seed);
    c.n = points.size();
    c.lower_dimensional = fuzz::is_lower_dimensional(points);
    c.run = run_peer(o.peer, points, o.peer_options);
    c.run.mesh.reset();
    if (c.failed() && o.shrink && !o.out_dir.empty() && c.run.verdict != Verdict::hung) {
      const std::string cmd = "dtlab fuzz --target " + o.peer + " --family " + c.source + " --case " +
                              std::to_string(c.index) + " --seed " + std::to_string(o.seed) + " --min-points " +
                              std::to_string(o.min_points) + " --points " + std::to_string(o.max_points) +
                              " --out DIR";
      shrink_and_save(c, points, o.peer_options, o.shrink_budget, o.out_dir, cmd);
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
