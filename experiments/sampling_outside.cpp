// Chapter 3's ray-intersection sampler against the SDF and winding-number samplers on
// the bumpy torus (concave, with a hole) with a growing share of its faces removed.
// "Outside" is judged against the closed torus: the solid the user meant.
#include <cmath>
#include <fstream>

#include "kernel/output_file.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_sampler.hpp"
#include "sampling/sample_quality.hpp"
#include "sampling/winding_number.hpp"

namespace dtlab::experiments {

nlohmann::json sampling_section(const SectionContext& c) {
  const TriangleMesh closed = make_bumpy_torus();
  const Bvh reference(closed);
  const std::vector<int> every = {0, 100, 50, 20, 7};  // remove every k-th triangle (0: none)
  const std::vector<std::string> methods = {"rays", "sdf", "winding"};
  const std::size_t count = c.quick ? 3000 : 20000;
  std::vector<std::vector<std::string>> rows;
  nlohmann::json cells = nlohmann::json::array();
  for (int k : every) {
    TriangleMesh mesh = closed;
    if (k > 0) {
      mesh.triangles.clear();
      for (std::size_t t = 0; t < closed.triangles.size(); ++t)
        if (t % k != 0) mesh.triangles.push_back(closed.triangles[t]);
    }
    const double removed = 1.0 - double(mesh.triangles.size()) / double(closed.triangles.size());
    const MeshSampler sampler(mesh);
    for (const auto& m : methods) {
      SampleRequest r;
      r.method = *parse_sample_method(m);
      r.count = count;
      r.seed = case_seed(c.seed, "sampling/" + m, count, k);
      const SampleOutput out = sampler.sample(r);
      const OutsideStats st = count_outside(reference, out.points);
      cells.push_back({{"removed_every", k}, {"removed_fraction", removed}, {"method", m},
                       {"points", out.points.size()}, {"outside", st.outside}, {"outside_fraction", st.fraction()}});
      rows.push_back({std::to_string(k), fmt("%.4f", removed), m, std::to_string(out.points.size()),
                      std::to_string(st.outside), fmt("%.5f", st.fraction())});
      // the slab |y| < 0.05 of the 5%-holed torus, for the picture
      if (k == 20) {
        const auto inside = inside_flags_robust(reference, out.points);
        nlohmann::json pts = nlohmann::json::array();
        for (std::size_t i = 0; i < out.points.size(); ++i)
          if (std::abs(out.points[i].y) < 0.05) pts.push_back({out.points[i].x, out.points[i].z, inside[i] ? 1 : 0});
        write_text_file((c.dir / "data" / ("slice_" + m + ".json")).string(), pts.dump() + "\n");
      }
    }
  }
  write_csv(c.dir / "data" / "sampling.csv",
            {"removed_every", "removed_fraction", "method", "points", "outside", "outside_fraction"}, rows);
  return {{"count", count}, {"triangles", closed.triangles.size()}, {"cells", cells}};
}

}  // namespace dtlab::experiments
