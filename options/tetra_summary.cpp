#include "options/tetra_summary.hpp"

namespace dtlab {

nlohmann::json tetra_summary(const BuildResult& r, const KernelOptions& k) {
  nlohmann::json j;
  j["points"] = r.mesh.points.size();
  j["inserted"] = r.stats.inserted;
  j["duplicates"] = r.duplicates;
  j["skipped"] = r.skipped.size();
  j["tets"] = r.mesh.tets.size();
  j["predicates"] = k.predicates;
  j["perturb"] = k.perturb;
  j["boundary"] = k.boundary;
  j["order"] = k.order;
  j["seconds"] = r.stats.seconds;
  j["flips"] = {{"1-4", r.stats.flips14}, {"2-3", r.stats.flips23}, {"3-2", r.stats.flips32}, {"4-4", r.stats.flips44}};
  j["walk_steps"] = r.stats.walk_steps;
  j["orient3d_calls"] = r.stats.orient3d_calls;
  j["insphere_calls"] = r.stats.insphere_calls;
  j["build_threads"] = r.stats.threads;
  j["conflicts"] = r.stats.conflicts;              // parallel build: insertions rolled back and retried
  j["storage_growths"] = r.stats.storage_growths;  // parallel build: the shared tet storage grew
  if (r.stats.threads > 1)
    j["parallel"] = {{"passes", r.stats.parallel_passes},
                     {"pass_seconds", r.stats.parallel_seconds},
                     {"idle_seconds", r.stats.idle_seconds},
                     {"serial_points", r.stats.serial_points},
                     {"serial_seconds", r.stats.serial_seconds}};
  for (const auto& [stage, count] : r.stats.stages) j["adaptive_stages"][stage] = count;
  if (r.failure)
    j["failure"] = {
        {"kind", failure_name(r.failure->kind)}, {"point", r.failure->point}, {"detail", r.failure->detail}};
  else
    j["failure"] = nullptr;
  return j;
}

}  // namespace dtlab
