#include "voronoi_check/check_json.hpp"

namespace dtlab {

nlohmann::json to_json(const VoronoiCheckReport& r) {
  nlohmann::json counts = nlohmann::json::object();
  for (int k = 0; k < kVoronoiDefects; ++k)
    if (r.counts[k]) counts[voronoi_defect_name(static_cast<VoronoiDefect>(k))] = r.counts[k];
  nlohmann::json w = nlohmann::json::array();
  for (const auto& x : r.witnesses)
    w.push_back({{"kind", voronoi_defect_name(x.kind)}, {"site", x.site}, {"neighbor", x.neighbor},
                 {"size", x.size}, {"detail", x.detail}});
  const auto& t = r.tolerances;
  const auto rule = [](const AppliedTolerance& a) { return a.ulps ? "ulps" : "relative"; };
  const nlohmann::json tolerances = {
      {"ulp", t.ulp},
      {"floor_distance", t.floor_distance},
      {"vertex", {{"value", t.vertex.value}, {"rule", rule(t.vertex)}}},
      {"convex", {{"value", t.convex.value}, {"rule", rule(t.convex)}}},
      {"small_face", {{"value", t.small_face.value}, {"rule", rule(t.small_face)}}},
      {"volume", {{"value", t.volume.value}, {"rule", rule(t.volume)}, {"surface", t.surface}}}};
  return {{"verdict", voronoi_verdict_name(r.verdict)}, {"topology", topology_name(r.topology)},
          {"counts", counts}, {"witnesses", w},
          {"largest_wrong_face", r.largest_wrong_face}, {"largest_small_face", r.largest_small_face},
          {"max_vertex_ulps", r.max_vertex_ulps}, {"max_vertex_error", r.max_vertex_error},
          {"volume_sum", r.volume_sum}, {"box_volume", r.box_volume}, {"volume_error", r.volume_error}, {"tolerances", tolerances},
          {"sites", r.sites}, {"distinct_sites", r.distinct_sites}, {"cells", r.cells}, {"faces", r.faces},
          {"vertices", r.vertices}, {"voronoi_edges", r.voronoi_edges}, {"degenerate_edges", r.degenerate_edges},
          {"seconds_delaunay", r.seconds_dt}, {"seconds_check", r.seconds}};
}

}  // namespace dtlab
