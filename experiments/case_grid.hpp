#pragma once
// What the two peer campaigns share (experiments/peer_campaign.hpp judges Delaunay
// peers, experiments/voronoi_campaign.hpp Voronoi peers): the grid of peers x point
// sources x cases run in one work queue, each case's input drawn from its case seed
// (fuzz/case_seed.hpp), the command that reruns one case, and the corpus files a
// shrunk failure is saved as.
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/work_queue.hpp"
#include "predicates/point.hpp"

namespace dtlab::experiments {

using PointGenerator = std::function<std::vector<Point3>(std::size_t n, std::uint64_t seed)>;

struct PointSource {
  std::string name;
  PointGenerator generate;
};

// Every fuzz family as a point source; std::invalid_argument for an unknown name.
std::vector<PointSource> fuzz_family_sources(const std::vector<std::string>& names);

// The options both campaigns take.
struct CaseGrid {
  std::vector<PointSource> sources;
  std::size_t cases = 10;
  std::optional<std::size_t> only_case;         // run just this case index
  std::size_t min_points = 8, max_points = 64;  // n per case, from the case seed
  std::uint64_t seed = 1;
  std::string out_dir;  // corpus/ goes here; "" writes nothing
  bool shrink = true;
  std::size_t shrink_budget = 200;  // peer runs per shrunk case
  unsigned jobs = 1;
};

// One case of the grid: who runs it on what, and its case seed.
struct GridCase {
  const std::string* peer = nullptr;
  const PointSource* source = nullptr;
  std::size_t index = 0;
  std::uint64_t seed = 0;
};

// peers x grid.sources x cases (only grid.only_case when set), in that order.
std::vector<GridCase> grid_cases(const std::vector<std::string>& peers, const CaseGrid& grid);

// The case's input: n from its seed in [min_points, max_points], drawn from its source.
std::vector<Point3> grid_points(const GridCase& c, const CaseGrid& grid);

// `dtlab fuzz --target TARGET --family SOURCE --case INDEX ... --out DIR`: reruns one case.
std::string grid_case_command(const std::string& target, const CaseGrid& grid, const std::string& source,
                              std::size_t index);

// Runs every case of the grid, grid.jobs at a time: `run(c, points)` fills a Case
// (its peer, source, index, seed and n already set), then `on_case` sees it under a
// lock. The results are in grid_cases order; the first exception (a folder that
// cannot be written) stops the queue and is rethrown here.
template <class Case, class Run>
std::vector<Case> run_grid(const std::vector<std::string>& peers, const CaseGrid& grid, Run run,
                           const std::function<void(const Case&)>& on_case) {
  const std::vector<GridCase> cases = grid_cases(peers, grid);
  std::vector<Case> results(cases.size());
  std::mutex lock;
  fuzz::run_work_queue(cases.size(), grid.jobs, [&](std::size_t w) {
    const std::vector<Point3> points = grid_points(cases[w], grid);
    Case c;
    c.peer = *cases[w].peer;
    c.source = cases[w].source->name;
    c.index = cases[w].index;
    c.seed = cases[w].seed;
    c.n = points.size();
    run(c, points);
    std::lock_guard<std::mutex> g(lock);
    if (on_case) on_case(c);
    results[w] = std::move(c);
  });
  return results;
}

// A shrink try's time limit: 10x the original run's, 2 s at least, `timeout_s` at most.
double shrink_try_limit(double original_seconds, double timeout_s);

// "<peer>-<source>": what a case's corpus names start with. The peer is escaped one to
// one: letters, digits and . - + kept, ':' made '_' (dtlab:exact: dtlab_exact), any other
// byte, '_' and '~' too, made ~XX, its hex (my_peer: my~5Fpeer). The source (a fuzz
// family, MESH-surface, MESH-volume) is kept: none ends in "-" and another's name.
std::string corpus_prefix(const std::string& peer, const std::string& source);

// "<prefix>-n<N>-<case>": the name of a case's corpus files.
std::string corpus_stem(const std::string& peer, const std::string& source, std::size_t n, std::size_t index);

// A corpus file name "<prefix>-n<N>-<case>.node" (or .json) taken apart; nullopt for a
// name of another form.
struct CorpusName {
  std::string prefix;
  std::size_t index = 0;
};
std::optional<CorpusName> parse_corpus_name(const std::string& file_name);

// Removes the files of <out_dir>/corpus with a corpus name that `ours` accepts (given
// the name and the file's name in the folder: the names a run writes), before the run
// writes any: an earlier run's failure that this one does not repeat is not left beside
// its results. Returns the paths removed.
std::vector<std::string> remove_corpus_names(const std::string& out_dir,
                                             const std::function<bool(const CorpusName&, const std::string&)>& ours);

// remove_corpus_names for the cases of the grid (any size: their n is drawn afresh):
// the entries a run of `peers` on it would write, and those an earlier dtlab wrote for
// them under the names before the one-to-one escape (':' as '_', the Voronoi campaign's
// '+' as 'p'), when their sidecar names the same peer.
void remove_grid_corpus(const std::vector<std::string>& peers, const CaseGrid& grid);

// Writes <out_dir>/corpus/<stem>.node (creating the folder); returns "corpus/<stem>.node".
std::string save_corpus_points(const std::string& out_dir, const std::string& stem, const std::vector<Point3>& points);

// What both campaigns' sidecars hold: the case (peer, source, case, case_seed), its
// file, the points before and after the shrink, how the shrink ended (minimal,
// shrink_runs, shrink_seconds, shrink_stopped_by) and the commands that replay the
// saved input and the original case.
template <class Case>
nlohmann::json case_sidecar(const Case& c, std::size_t points_original, std::size_t points, const std::string& command,
                            const std::string& original_command) {
  return {{"peer", c.peer},
          {"file", c.corpus_file},
          {"source", c.source},
          {"case", c.index},
          {"case_seed", c.seed},
          {"points_original", points_original},
          {"points", points},
          {"minimal", c.shrunk_minimal},
          {"shrink_runs", c.shrink_runs},
          {"shrink_seconds", c.shrink_seconds},
          {"shrink_stopped_by", c.shrink_stop},
          {"command", command},
          {"original_command", original_command}};
}

// Writes the sidecar <out_dir>/corpus/<stem>.json.
void save_corpus_sidecar(const std::string& out_dir, const std::string& stem, const nlohmann::json& sidecar);

}  // namespace dtlab::experiments
