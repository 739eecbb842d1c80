#include "cli/tetra_report.hpp"

#include "oracle/check/report_json.hpp"

namespace dtlab::cli {

void print_tetra_summary(std::FILE* out, const BuildResult& r, const std::string& input) {
  std::fprintf(out, "%s: %zu points, %llu inserted, %zu duplicates, %zu skipped -> %zu tets in %.3f s\n",
               input.c_str(), r.mesh.points.size(), (unsigned long long)r.stats.inserted,
               r.duplicates.size(), r.skipped.size(), r.mesh.tets.size(), r.stats.seconds);
  std::fprintf(out, "flips 1-4 %llu, 2-3 %llu, 3-2 %llu, 4-4 %llu; walk steps %llu; orient3d %llu, insphere %llu\n",
               (unsigned long long)r.stats.flips14, (unsigned long long)r.stats.flips23,
               (unsigned long long)r.stats.flips32, (unsigned long long)r.stats.flips44,
               (unsigned long long)r.stats.walk_steps, (unsigned long long)r.stats.orient3d_calls,
               (unsigned long long)r.stats.insphere_calls);
  if (r.stats.threads > 1)
    std::fprintf(out, "built on %u threads; %llu insertions met another thread's tets and were retried\n",
                 r.stats.threads, (unsigned long long)r.stats.conflicts);
  if (!r.stats.stages.empty()) {
    std::fprintf(out, "adaptive stages:");
    for (const auto& [stage, count] : r.stats.stages) std::fprintf(out, " %s %llu", stage.c_str(), (unsigned long long)count);
    std::fprintf(out, "\n");
  }
  if (!r.duplicates.empty()) {
    std::fprintf(out, "duplicates (input indices):");
    for (std::size_t i = 0; i < r.duplicates.size() && i < 20; ++i) std::fprintf(out, " %u", r.duplicates[i]);
    std::fprintf(out, r.duplicates.size() > 20 ? " ...\n" : "\n");
  }
  if (r.failure)
    std::fprintf(out, "FAILURE %s while inserting point %lld: %s\n", failure_name(r.failure->kind),
                 (long long)r.failure->point, r.failure->detail.c_str());
}

void print_tetra_check(std::FILE* out, const CheckReport& r) {
  if (r.ok()) {
    std::fprintf(out, "check: valid Delaunay tetrahedralization (exact checker, %.3f s)\n", r.stats.seconds);
    return;
  }
  std::fprintf(out, "check: DEFECTS FOUND (exact checker, %.3f s):", r.stats.seconds);
  for (int k = 0; k < kDefectKinds; ++k)
    if (r.counts[k])
      std::fprintf(out, " %llu x %s", static_cast<unsigned long long>(r.counts[k]), defect_name(static_cast<DefectKind>(k)));
  std::fprintf(out, "\n");
  for (const Defect& d : r.defects) std::fprintf(out, "  %s\n", format_defect(d).c_str());
}

}  // namespace dtlab::cli
