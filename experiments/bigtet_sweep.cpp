// The thesis's big enclosing tetrahedron: for each input, the tets of the bigtet
// build are compared with the infinite-vertex build (both adaptive + SoS, so the
// boundary method is the only difference) over a sweep of the bigtet factor.
#include <algorithm>
#include <cmath>
#include <limits>

#include "experiments/point_sources.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"

namespace dtlab::experiments {

namespace {

std::vector<Tet> canonical_tets(const Tetrahedralization& t) {
  std::vector<Tet> v = t.tets;
  for (auto& tet : v) std::sort(tet.begin(), tet.end());
  std::sort(v.begin(), v.end());
  return v;
}

std::size_t count_missing(const std::vector<Tet>& ref, const std::vector<Tet>& got) {
  std::vector<Tet> diff;
  std::set_difference(ref.begin(), ref.end(), got.begin(), got.end(), std::back_inserter(diff));
  return diff.size();
}

}  // namespace

nlohmann::json bigtet_section(const SectionContext& c) {
  const std::vector<std::string> families = c.quick
      ? std::vector<std::string>{"uniform", "torus-winding"}
      : std::vector<std::string>{"uniform", "torus-winding", "clustered", "coplanar_slabs"};
  const std::vector<std::size_t> sizes = c.quick ? std::vector<std::size_t>{100} : std::vector<std::size_t>{100, 1000};
  const int cases = c.quick ? 3 : 8;
  const std::vector<double> factors = {1, 1.5, 2, 3, 5, 10, 30, 100, 300, 1e3, 1e4, 1e5, 1e6, 1e8, 1e10, 1e12};
  const PredicateSpec spec{"adaptive", 0, false, true};
  std::vector<std::vector<std::string>> rows, need_rows;
  nlohmann::json cells = nlohmann::json::array(), needs = nlohmann::json::array();
  for (const auto& fam : families)
    for (std::size_t n : sizes)
      for (int i = 0; i < cases; ++i) {
        const std::uint64_t s = case_seed(c.seed, "bigtet/" + fam, n, i);
        const auto points = experiment_points(fam, n, s);
        BuildOptions opt;
        opt.seed = s;
        const BuildResult ref_build = build_delaunay(points, spec, opt);
        const auto ref = canonical_tets(ref_build.mesh);
        double need = std::numeric_limits<double>::infinity();  // smallest factor from which all agree
        for (auto it = factors.rbegin(); it != factors.rend(); ++it) {
          BuildOptions b = opt;
          b.boundary = Boundary::bigtet;
          b.bigtet_factor = *it;
          const BuildResult r = build_delaunay(points, spec, b);
          const auto got = canonical_tets(r.mesh);
          const std::size_t missing = count_missing(ref, got), extra = count_missing(got, ref);
          const bool same = !r.failure && missing == 0 && extra == 0;
          if (same && (need == std::numeric_limits<double>::infinity() ? it == factors.rbegin() : need == *(it - 1)))
            need = *it;
          const std::string failure = r.failure ? failure_name(r.failure->kind) : "";
          cells.push_back({{"family", fam}, {"n", n}, {"case", i}, {"factor", *it}, {"reference_tets", ref.size()},
                           {"tets", got.size()}, {"missing", missing}, {"extra", extra}, {"failure", failure}});
          rows.push_back({fam, std::to_string(n), std::to_string(i), fmt("%g", *it), std::to_string(ref.size()),
                          std::to_string(got.size()), std::to_string(missing), std::to_string(extra), failure});
        }
        needs.push_back({{"family", fam}, {"n", n}, {"case", i},
                         {"required_factor", std::isinf(need) ? nlohmann::json(nullptr) : nlohmann::json(need)}});
        need_rows.push_back({fam, std::to_string(n), std::to_string(i), std::isinf(need) ? "none" : fmt("%g", need)});
      }
  write_csv(c.dir / "data" / "bigtet.csv",
            {"family", "n", "case", "factor", "reference_tets", "tets", "missing", "extra", "failure"}, rows);
  write_csv(c.dir / "data" / "bigtet_required.csv", {"family", "n", "case", "required_factor"}, need_rows);
  return {{"families", families}, {"sizes", sizes}, {"cases", cases}, {"factors", factors},
          {"cells", cells}, {"required", needs}};
}

}  // namespace dtlab::experiments
