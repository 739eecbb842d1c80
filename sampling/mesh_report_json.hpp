#pragma once
// The mesh report as JSON: the same keys in `mesh check --json`, `sample --json` and
// the fracture manifest. Header-only so that sampling/ needs no JSON library.
#include <nlohmann/json.hpp>

#include "sampling/mesh_report.hpp"

namespace dtlab {

inline nlohmann::json mesh_report_json(const MeshReport& r) {
  auto points = [](const std::vector<Point3>& at) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : at) a.push_back({p.x, p.y, p.z});
    return a;
  };
  return {{"vertices", r.vertices},
          {"triangles", r.triangles},
          {"solid", r.solid()},
          {"closed", r.closed},
          {"manifold", r.manifold},
          {"oriented", r.oriented},
          {"self_intersecting_pairs", r.self_intersections},
          {"boundary_edges", r.boundary_edges},
          {"boundary_loops", r.boundary_loops},
          {"nonmanifold_edges", r.nonmanifold_edges},
          {"nonmanifold_vertices", r.nonmanifold_vertices},
          {"misoriented_edges", r.misoriented_edges},
          {"duplicate_vertices", r.duplicate_vertices},
          {"degenerate_triangles", r.degenerate_triangles},
          {"area", r.area},
          {"volume", r.volume},
          {"bbox", {{r.box.lo.x, r.box.lo.y, r.box.lo.z}, {r.box.hi.x, r.box.hi.y, r.box.hi.z}}},
          {"problems", r.problems()},
          {"locations",
           {{"duplicate_vertices", points(r.duplicate_at)},
            {"degenerate_triangles", points(r.degenerate_at)},
            {"boundary_edges", points(r.boundary_at)},
            {"nonmanifold", points(r.nonmanifold_at)},
            {"misoriented_edges", points(r.misoriented_at)},
            {"self_intersections", points(r.self_intersection_at)}}}};
}

}  // namespace dtlab
