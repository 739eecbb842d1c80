#include "fuzz/campaign.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "dtlab/build_info.hpp"
#include "fuzz/campaign_report.hpp"
#include "fuzz/campaign_settings.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/corpus.hpp"
#include "fuzz/families.hpp"
#include "fuzz/record_json.hpp"
#include "fuzz/results_log.hpp"
#include "fuzz/shrink.hpp"
#include "fuzz/summary.hpp"
#include "fuzz/work_queue.hpp"
#include "kernel/output_file.hpp"

namespace dtlab::fuzz {

namespace fs = std::filesystem;

std::size_t CampaignResult::failing() const {
  std::size_t n = 0;
  for (const auto& r : records) n += !r.run.ok();
  return n;
}

std::string boundary_label(const BuildOptions& options) {
  if (options.boundary == Boundary::infinite) return "infinite";
  char buf[48];
  std::snprintf(buf, sizeof buf, "bigtet:%g", options.bigtet_factor);
  return buf;
}

std::string order_label(const BuildOptions& options) {
  return options.order == InsertionOrder::brio ? "brio" : "input";
}

std::string case_id(const std::string& family, std::uint64_t seed, std::size_t index) {
  return family + "-s" + std::to_string(seed) + "-" + std::to_string(index);
}

std::size_t case_points(std::uint64_t case_seed, std::size_t min_points, std::size_t max_points) {
  if (max_points <= min_points) return max_points;
  return min_points + mix64(case_seed ^ 0x706f696e7473ULL) % (max_points - min_points + 1);
}

bool is_results_file(const std::string& file_name) {
  return file_name.rfind("results", 0) == 0 && fs::path(file_name).extension() == ".jsonl";
}

std::vector<CaseRecord> read_records(const std::string& out_dir) {
  std::vector<CaseRecord> records;
  if (!fs::is_directory(out_dir)) return records;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(out_dir)) {
    if (e.is_regular_file() && is_results_file(e.path().filename().string())) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in(f);
    std::string line;
    while (std::getline(in, line)) {
      try {
        records.push_back(record_from_json(nlohmann::json::parse(line)));
      } catch (const nlohmann::json::exception&) {
        // a truncated last line of an interrupted run: that case runs again
      }
    }
  }
  return records;
}

namespace {

struct WorkItem {
  const Family* family;
  std::size_t index;
};

std::string resume_key(const std::string& id, const std::string& backend, const std::string& boundary) {
  return id + "|" + backend + "|" + boundary;
}

// " --against A,B" for the campaign's oracles, "" without.
std::string against_option(const CampaignOptions& o) {
  std::string names;
  for (const OracleHook& h : o.oracles) names += (names.empty() ? "" : ",") + h.name;
  return names.empty() ? "" : " --against " + names;
}

std::string original_command(const CampaignOptions& o, const CaseRecord& r) {
  return "dtlab fuzz --family " + r.family + " --seed " + std::to_string(o.seed) + " --case " +
         std::to_string(r.index) + " --min-points " + std::to_string(o.min_points) + " --points " +
         std::to_string(o.max_points) + " --predicates " + r.predicates + " --perturb " + (r.perturb ? "sos" : "none") +
         " --boundary " + r.boundary + " --order " + order_label(o.build) +
         (r.threads == 1 ? "" : " --threads " + std::to_string(r.threads)) + against_option(o) + " --out " + o.out_dir +
         "/repro-" + r.id;
}

// The cases of this shard that `done` does not hold for every backend, in family then index
// order; `resumed` counts the ones it does.
std::vector<WorkItem> pending_work(const CampaignOptions& o, const std::set<std::string>& done,
                                   const std::string& boundary, std::size_t& resumed) {
  std::vector<WorkItem> work;
  for (std::size_t fi = 0; fi < o.families.size(); ++fi) {
    const Family* f = find_family(o.families[fi]);
    if (!f) throw std::invalid_argument("unknown family '" + o.families[fi] + "'");
    // --case N jumps straight to case N (no walk over the indices before it).
    const std::size_t lo = o.only_case ? std::min(*o.only_case, o.cases) : 0;
    const std::size_t hi = o.only_case ? std::min(*o.only_case + 1, o.cases) : o.cases;
    for (std::size_t i = lo; i < hi; ++i) {
      const std::size_t ordinal = fi * o.cases + i;
      if (ordinal % o.shards != o.shard) continue;
      const std::string id = case_id(f->name, o.seed, i);
      bool all_done = true;
      for (const auto& spec : o.backends)
        all_done = all_done && done.count(resume_key(id, backend_label(spec), boundary));
      if (all_done)
        ++resumed;
      else
        work.push_back({f, i});
    }
  }
  return work;
}

// The fields every backend's record of one case shares.
CaseRecord case_base(const CampaignOptions& o, const WorkItem& item, const std::string& boundary) {
  CaseRecord base;
  base.family = item.family->name;
  base.index = item.index;
  base.id = case_id(base.family, o.seed, item.index);
  base.campaign_seed = o.seed;
  base.case_seed = case_seed(o.seed, base.family, item.index);
  base.boundary = boundary;
  base.threads = build_thread_count(o.build);
  base.version = build_version();
  base.commit = build_commit();
  return base;
}

// Before any case runs, the corpus entries that would not be this run's: those of the
// (case, backend) pairs it runs (an earlier run's failure it may not repeat) and of resumed
// results that are no failure. Resumed failures and other cases (other shards') keep theirs.
void remove_stale_corpus(const CampaignOptions& o, const std::vector<WorkItem>& work, const std::set<std::string>& done,
                         const std::vector<CaseRecord>& resumed, const std::string& boundary) {
  std::vector<std::string> files;
  const auto add = [&](const CaseRecord& r) {
    for (std::string& f : corpus_entry_files(o.out_dir, r)) files.push_back(std::move(f));
  };
  for (const WorkItem& item : work)
    for (const auto& spec : o.backends) {
      CaseRecord r = case_base(o, item, boundary);
      r.backend = backend_label(spec);
      if (!done.count(resume_key(r.id, r.backend, boundary))) add(r);
    }
  for (const CaseRecord& r : resumed)
    if (r.run.ok()) add(r);
  remove_output_set(files);
}

// One backend on one case; a failure is shrunk to a smaller input with the same outcome and
// written to the corpus (under `corpus_lock`: runs of other cases write there too).
void run_backend(const CampaignOptions& o, const PredicateSpec& spec, const BuildOptions& build,
                 const std::vector<Point3>& points, CaseRecord& r, std::mutex& corpus_lock) {
  r.backend = backend_label(spec);
  r.predicates = spec.backend;
  r.perturb = spec.perturb;
  r.run = run_case(points, spec, build, o.oracles);
  if (r.run.ok() || !o.shrink) return;
  const std::string target = r.run.outcome;
  const auto fails = [&](const std::vector<Point3>& candidate) {
    return run_case(candidate, spec, build, o.oracles).outcome == target;
  };
  const ShrinkResult s = shrink_points(points, fails, o.shrink_budget);
  r.shrunk_points = s.points.size();
  // The shrinker's builds are `build`, the case's own (threads and order included), so the
  // entry fails as recorded when replayed with the sidecar's settings.
  CorpusEntryInfo info{original_command(o, r), s.tests, s.minimal, order_label(build), spec.eps, spec.relative_eps, {}};
  for (const OracleHook& h : o.oracles) info.against.push_back(h.name);
  std::lock_guard<std::mutex> g(corpus_lock);
  r.corpus_file = write_corpus_entry(o.out_dir, r, s.points, info);
}

}  // namespace

CampaignResult run_campaign(const CampaignOptions& o) {
  if (o.shards == 0 || o.shard >= o.shards) throw std::invalid_argument("bad shard");
  fs::create_directories(o.out_dir);
  std::string results_name = "results.jsonl";
  if (o.shards > 1)
    results_name = "results.shard-" + std::to_string(o.shard) + "-of-" + std::to_string(o.shards) + ".jsonl";
  // Locked and repaired before anything is read: what is resumed is what this run owns.
  ResultsLog out((fs::path(o.out_dir) / results_name).string());
  check_resume_settings(o);
  CampaignResult result;
  result.records = read_records(o.out_dir);
  std::set<std::string> done;
  for (const auto& r : result.records) done.insert(resume_key(r.id, r.backend, r.boundary));

  const std::string boundary = boundary_label(o.build);
  const std::vector<WorkItem> work = pending_work(o, done, boundary, result.resumed);
  remove_stale_corpus(o, work, done, result.records, boundary);
  write_campaign_environment(o);

  std::mutex lock;
  std::size_t finished = 0, failing = 0;
  const auto run_one = [&](std::size_t w) {
    const CaseRecord base = case_base(o, work[w], boundary);
    const std::size_t n = case_points(base.case_seed, o.min_points, o.max_points);
    const std::vector<Point3> points = work[w].family->generate(n, base.case_seed);
    BuildOptions build = o.build;
    build.seed = base.case_seed;
    std::vector<CaseRecord> local;
    for (const auto& spec : o.backends) {
      if (done.count(resume_key(base.id, backend_label(spec), boundary))) continue;
      CaseRecord r = base;
      r.points = points.size();
      run_backend(o, spec, build, points, r, lock);
      local.push_back(std::move(r));
    }

    std::lock_guard<std::mutex> g(lock);
    std::string lines;
    for (const auto& r : local) lines += record_to_json(r).dump() + "\n";
    out.append(lines);  // one write: a kill cuts at most the last line, repaired on resume
    for (auto& r : local) {
      failing += !r.run.ok();
      result.records.push_back(std::move(r));
    }
    ++finished;
    ++result.ran;
    if (o.progress) o.progress(finished, work.size(), failing);
  };
  // The first exception (a folder that cannot be written) stops the queue and is
  // rethrown here.
  run_work_queue(work.size(), o.jobs, run_one);
  // A shard's folder may be shared with running shards: their merged summary is
  // written by `dtlab fuzz --summarize` once all are done.
  if (o.shards == 1) write_summary_files(o.out_dir, summarize(result.records));
  return result;
}

}  // namespace dtlab::fuzz
