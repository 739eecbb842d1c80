#include "fuzz/outcome.hpp"

#include <filesystem>
#include <chrono>
#include <exception>

#include "oracle/check/check.hpp"
#include "predicates/exact.hpp"

namespace dtlab::fuzz {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// a, b, c collinear iff orient3d(a, b, c, q) == 0 for four affinely independent q:
// otherwise a, b, c span a plane, and it cannot hold all four.
bool collinear(const Point3& a, const Point3& b, const Point3& c) {
  static constexpr Point3 probes[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& q : probes)
    if (exact_orient3d(a, b, c, q) != 0) return false;
  return true;
}

}  // namespace

std::string backend_label(const PredicateSpec& spec) {
  // A plug-in by its file's stem: the label names files and table columns.
  const std::string base = spec.backend.rfind("plugin:", 0) == 0
                               ? "plugin:" + std::filesystem::path(spec.backend.substr(7)).stem().string()
                               : spec.backend;
  return base + (spec.perturb ? "+sos" : "");
}

bool is_lower_dimensional(std::span<const Point3> points) {
  if (points.empty()) return true;
  const Point3& a = points[0];
  std::size_t ib = 0;
  while (ib < points.size() && points[ib] == a) ++ib;
  if (ib == points.size()) return true;
  const Point3& b = points[ib];
  std::size_t ic = ib + 1;
  while (ic < points.size() && collinear(a, b, points[ic])) ++ic;
  if (ic == points.size()) return true;
  const Point3& c = points[ic];
  for (const auto& d : points)
    if (exact_orient3d(a, b, c, d) != 0) return false;
  return true;
}

CaseRun run_case(std::span<const Point3> points, const PredicateSpec& predicates,
                 const BuildOptions& options, const std::vector<OracleHook>& oracles) {
  CaseRun run;
  BuildResult built;
  auto t0 = std::chrono::steady_clock::now();
  try {
    built = build_delaunay(points, predicates, options);
  } catch (const std::exception& e) {
    run.build_seconds = seconds_since(t0);
    run.outcome = "exception";
    run.detail = e.what();
    return run;
  }
  run.build_seconds = seconds_since(t0);
  run.tets = built.mesh.tets.size();
  run.parallel_passes = built.stats.parallel_passes;
  run.duplicates = built.duplicates.size();

  const bool flat_input = is_lower_dimensional(points);
  if (built.failure) {
    run.detail = built.failure->detail;
    if (built.failure->kind == FailureKind::lower_dimensional)
      run.outcome = flat_input ? "lower-dimensional" : "false-lower-dimensional";
    else
      run.outcome = failure_name(built.failure->kind);
    return run;
  }
  if (flat_input) {
    // No tets is the only right answer for a flat input.
    run.outcome = built.mesh.tets.empty() ? "lower-dimensional" : "flat";
    return run;
  }

  t0 = std::chrono::steady_clock::now();
  CheckOptions check_options;
  check_options.duplicates = built.duplicates;
  check_options.witnesses_per_kind = 1;
  const CheckReport report = check_tetrahedralization(built.mesh, check_options);
  run.check_seconds = seconds_since(t0);
  for (int k = 0; k < kDefectKinds; ++k)
    if (report.counts[k]) run.defects[defect_name(static_cast<DefectKind>(k))] = report.counts[k];
  if (!report.ok()) {
    for (int k = 0; k < kDefectKinds && run.outcome.empty(); ++k)
      if (report.counts[k]) run.outcome = defect_name(static_cast<DefectKind>(k));
    if (!report.defects.empty()) {
      // the witness of the first kind counted (the outcome), not of the first listed
      const Defect* w = &report.defects.front();
      for (const auto& d : report.defects)
        if (defect_name(d.kind) == run.outcome) {
          w = &d;
          break;
        }
      run.detail = w->detail;
      run.witness_tets = w->tets;
      run.witness_vertices = w->vertices;
    }
    return run;
  }
  for (const auto& oracle : oracles) {
    const std::string difference = oracle.compare(points, built);
    if (!difference.empty()) {
      run.outcome = "oracle-" + oracle.name;
      run.detail = difference;
      return run;
    }
  }
  run.outcome = "valid";
  return run;
}

}  // namespace dtlab::fuzz
