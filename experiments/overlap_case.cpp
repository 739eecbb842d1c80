// A picture-sized naive failure: the first near-degenerate input whose naive
// (unperturbed) build has inverted or overlapping tets, shrunk by delta debugging to
// a handful of points, with the exact checker's witnesses and the correct result.
#include <sstream>
#include <fstream>

#include "experiments/point_sources.hpp"
#include "experiments/thesis_parts.hpp"
#include "fuzz/shrink.hpp"
#include "kernel/output_file.hpp"
#include "oracle/check/check.hpp"

namespace dtlab::experiments {

namespace {

const PredicateSpec kNaive{"naive", 0, false, false};

// strict: overlapping tets (two tets on one side of a facet, or the hull covered twice);
// otherwise also an inverted tet among at least three (a lone inverted tet is no picture)
bool overlaps(const std::vector<Point3>& points, std::uint64_t seed, bool strict, CheckReport* report = nullptr,
              BuildResult* build = nullptr) {
  BuildOptions opt;
  opt.seed = seed;
  BuildResult r = build_delaunay(points, kNaive, opt);
  CheckOptions co;
  co.duplicates = r.duplicates;
  co.witnesses_per_kind = 64;
  CheckReport rep = check_tetrahedralization(r.mesh, co);
  const bool bad = rep.counts[int(DefectKind::overlap)] > 0 ||
                   (!strict && rep.counts[int(DefectKind::inverted)] > 0 && r.mesh.tets.size() >= 3);
  if (report) *report = std::move(rep);
  if (build) *build = std::move(r);
  return bad;
}

nlohmann::json tets_json(const std::vector<Tet>& tets) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& t : tets) a.push_back({t[0], t[1], t[2], t[3]});
  return a;
}

}  // namespace

nlohmann::json overlap_case_section(const SectionContext& c) {
  for (const bool strict : {true, false})
  for (const std::string fam : {"ulp_jitter", "near_degenerate", "kettner_grid"})
    for (int i = 0; i < (strict ? 300 : 100); ++i) {
      const std::uint64_t s = case_seed(c.seed, "picture/" + fam, 0, i);
      const std::size_t n = 12 + s % 40;
      const auto points = experiment_points(fam, n, s);
      if (!overlaps(points, s, strict)) continue;
      const auto shrunk = fuzz::shrink_points(points, [&](const std::vector<Point3>& p) { return overlaps(p, s, strict); },
                                              c.quick ? 300 : 1500);
      CheckReport rep;
      BuildResult naive;
      overlaps(shrunk.points, s, strict, &rep, &naive);
      BuildOptions opt;
      opt.seed = s;
      const BuildResult exact = build_delaunay(shrunk.points, {"exact", 0, false, true}, opt);
      nlohmann::json defects = nlohmann::json::array();
      for (const auto& d : rep.defects)
        defects.push_back({{"kind", defect_name(d.kind)}, {"tets", d.tets}, {"vertices", d.vertices},
                           {"sign", d.sign}, {"detail", d.detail}});
      nlohmann::json counts = nlohmann::json::object();
      for (int k = 0; k < kDefectKinds; ++k)
        if (rep.counts[k]) counts[defect_name(DefectKind(k))] = rep.counts[k];
      nlohmann::json pts = nlohmann::json::array();
      for (const auto& p : shrunk.points) pts.push_back({p.x, p.y, p.z});
      nlohmann::json j = {{"family", fam}, {"case_seed", s}, {"original_points", n},
                          {"points", pts}, {"naive_tets", tets_json(naive.mesh.tets)},
                          {"naive_failure", naive.failure ? failure_name(naive.failure->kind) : ""},
                          {"exact_tets", tets_json(exact.mesh.tets)}, {"defects", defects},
                          {"defect_counts", counts}, {"shrink_tests", shrunk.tests}, {"minimal", shrunk.minimal}};
      write_text_file((c.dir / "data" / "overlap_case.json").string(), j.dump(1) + "\n");
      // the coordinates, bit exact, to replay with `dtlab tetra`
      std::ostringstream xyz;
      xyz.precision(17);
      for (const auto& p : shrunk.points) xyz << p.x << " " << p.y << " " << p.z << "\n";
      write_text_file((c.dir / "data" / "overlap_case.xyz").string(), xyz.str());
      return j;
    }
  return nullptr;
}

}  // namespace dtlab::experiments
