#pragma once
// TriangleMesh <-> CGAL Surface_mesh, for the CGAL translation units of fracture/
// (mesh_repair.cpp, winding_solid.cpp, cell_boolean.cpp). Exact (lazy) coordinates are
// rounded to the nearest double (fracture/nearest_double.hpp).
#include <cstdint>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "fracture/nearest_double.hpp"
#include "kernel/ids.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab::surface_mesh_convert {

inline double coordinate(double v) { return v; }
inline double coordinate(const CGAL::Epeck::FT& v) { return nearest_double(v); }

// The faces of a Surface_mesh as a TriangleMesh; isolated vertices are left out (CGAL's
// orient_to_bound_a_volume does not accept them).
template <class M>
TriangleMesh to_triangles(const M& m) {
  TriangleMesh out;
  std::vector<std::uint32_t> id(m.number_of_vertices() + m.number_of_removed_vertices(), kNone);
  for (auto f : m.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      if (k == 3) break;
      if (id[v.idx()] == kNone) {
        id[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
        const auto& p = m.point(v);
        out.vertices.push_back({coordinate(p.x()), coordinate(p.y()), coordinate(p.z())});
      }
      t[k++] = id[v.idx()];
    }
    if (k == 3) out.triangles.push_back(t);
  }
  return out;
}

// A polygon soup that is a valid oriented surface (as the repair's steps leave it).
template <class M>
void to_mesh(const TriangleMesh& t, M& m) {
  using P = typename M::Point;
  std::vector<P> points;
  for (const auto& p : t.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : t.triangles) polygons.push_back({f[0], f[1], f[2]});
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, m);
}

}  // namespace dtlab::surface_mesh_convert
