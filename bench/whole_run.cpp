#include "bench/whole_run.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "oracle/peers/cgal_oracle.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peers.hpp"
#include "oracle/peers/tetgen_oracle.hpp"

namespace dtlab {

namespace {

struct ChildReport {
  int ok;
  double seconds;
  double peak_mb_self;
  double peak_mb_children;
  double peak_mb_peer;  // a peer's helper process (oracle/peers/peers.hpp), 0 for the others
  std::uint64_t tets;
  char note[200];
};

// A peer of `dtlab oracle` (cgal-parallel, gmsh-hxt) in its own helper process, unchecked:
// its seconds are the triangulation as it times it, its peak the helper's.
void run_peer_tool(const std::string& tool, const std::vector<Point3>& points, unsigned threads, ChildReport& rep) {
  PeerOptions po;
  po.check = false;
  po.threads = threads;
  // No address-space limit, as for the other tools' whole runs: HXT reserves more than
  // half of this machine at 10^7 points (measured: std::bad_alloc under the oracle's limit).
  po.memory_bytes = PeerOptions::kNoMemoryLimit;
  const PeerRun r = run_peer(tool, points, po);
  rep.ok = r.mesh.has_value() && r.verdict != Verdict::crashed && r.verdict != Verdict::hung;
  rep.seconds = r.seconds;
  rep.tets = r.mesh ? r.mesh->tets.size() : 0;
  rep.peak_mb_peer = double(r.peak_rss_bytes) / (1024.0 * 1024.0);
  std::snprintf(rep.note, sizeof rep.note, "%s", r.message.c_str());
}

ChildReport run_in_child(const std::string& tool, std::vector<Point3>& points,
                         const PredicateSpec& spec, const BuildOptions& options, unsigned threads) {
  ChildReport rep{};
  const auto report_build = [&rep](const BuildResult& r, std::chrono::steady_clock::time_point t0) {
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rep.ok = !r.failure;
    rep.tets = r.mesh.tets.size();
    if (r.failure) std::snprintf(rep.note, sizeof rep.note, "%s", failure_name(r.failure->kind));
  };
  if (tool == "dtlab" || tool == "dtlab-serial") {
    BuildOptions timed = options;
    timed.count_stages = false;  // no per-call counting in timed runs
    timed.threads = tool == "dtlab" ? threads : 1;
    const auto t0 = std::chrono::steady_clock::now();
    // The child's copy of the caller's points is handed to the build, as a program that
    // read them would: one copy of the points at the peak.
    report_build(build_delaunay(std::move(points), spec, timed), t0);
  } else if (tool == "dtlab-cgal-order") {
    // Our inserter fed in CGAL's spatial_sort order (timed with the sort and the copy
    // into that order, as BRIO is timed in "dtlab"); the peak holds both copies.
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<std::uint32_t> order = cgal_spatial_sort_order(points);
    std::vector<Point3> sorted(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = points[order[k]];
    BuildOptions timed = options;
    timed.count_stages = false;
    timed.order = InsertionOrder::input;
    timed.threads = 1;
    report_build(build_delaunay(std::move(sorted), spec, timed), t0);
  } else if (tool == "cgal") {
    OracleRun r = cgal_delaunay(points);
    rep.ok = r.mesh.has_value();
    rep.seconds = r.seconds;
    rep.tets = r.mesh ? r.mesh->tets.size() : 0;
  } else if (tool == "cgal-parallel" || tool == "gmsh-hxt") {
    run_peer_tool(tool, points, threads, rep);
  } else if (tool == "tetgen") {
    OracleRun r = tetgen_delaunay(points);
    rep.ok = r.mesh.has_value();
    rep.seconds = r.seconds;
    rep.tets = r.mesh ? r.mesh->tets.size() : 0;
    std::snprintf(rep.note, sizeof rep.note, "%s", r.note.c_str());
  } else {
    std::snprintf(rep.note, sizeof rep.note, "unknown tool");
  }
  rusage self{}, kids{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &kids);
  rep.peak_mb_self = double(self.ru_maxrss) / 1024.0;
  rep.peak_mb_children = double(kids.ru_maxrss) / 1024.0;
  return rep;
}

}  // namespace

RunMeasure measure_run(const std::string& tool, std::vector<Point3>& points,
                       const PredicateSpec& spec, const BuildOptions& options, unsigned threads) {
  RunMeasure m;
  m.tool = tool;
  // No time or memory limit of its own (a whole run is as long as it is); stdout and
  // stderr stay the caller's.
  ChildLimits limits = ChildLimits::of(1e9);
  limits.log_cap_bytes = sizeof(ChildReport);
  std::string reply;
  const ChildResult c = run_forked(
      [&](int fd) {
        ChildReport rep = run_in_child(tool, points, spec, options, threads);
        if (write(fd, &rep, sizeof rep) != static_cast<ssize_t>(sizeof rep)) throw std::runtime_error("write failed");
      },
      limits, reply);
  if (reply.size() != sizeof(ChildReport)) {
    m.note = "child died (signal " + std::to_string(c.status == ChildStatus::signaled ? c.signal : 0) + ")";
    return m;
  }
  ChildReport rep{};
  std::memcpy(&rep, reply.data(), sizeof rep);
  m.ok = rep.ok;
  m.seconds = rep.seconds;
  m.tets = rep.tets;
  m.note = rep.note;
  // TetGen's memory is its own process's, not the parent's that waited for it.
  m.peak_mb = tool == "tetgen"       ? rep.peak_mb_children
              : rep.peak_mb_peer > 0 ? rep.peak_mb_peer
                                     : double(c.maxrss_bytes) / (1024.0 * 1024.0);
  m.bytes_per_tet = m.tets ? m.peak_mb * 1024.0 * 1024.0 / double(m.tets) : 0;
  return m;
}

namespace {
std::vector<double> ok_values(const std::vector<RunMeasure>& runs, double RunMeasure::*field) {
  std::vector<double> v;
  for (const auto& r : runs)
    if (r.ok) v.push_back(r.*field);
  std::sort(v.begin(), v.end());
  return v;
}
double median(const std::vector<double>& v) {
  if (v.empty()) return 0;
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}
}  // namespace

double BenchRow::median_seconds() const { return median(ok_values(runs, &RunMeasure::seconds)); }
double BenchRow::min_seconds() const {
  auto v = ok_values(runs, &RunMeasure::seconds);
  return v.empty() ? 0 : v.front();
}
double BenchRow::max_seconds() const {
  auto v = ok_values(runs, &RunMeasure::seconds);
  return v.empty() ? 0 : v.back();
}
double BenchRow::median_peak_mb() const { return median(ok_values(runs, &RunMeasure::peak_mb)); }

}  // namespace dtlab
