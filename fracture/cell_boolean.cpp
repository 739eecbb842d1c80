// CGAL lives here only: conversion, input validation and one corefinement per cell.
#include "fracture/cell_boolean.hpp"

#include <mutex>
#include <stdexcept>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace dtlab {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

TriangleMesh to_triangles(const Mesh& m) {
  TriangleMesh out;
  std::vector<std::uint32_t> id(m.number_of_vertices() + m.number_of_removed_vertices(), 0);
  for (auto v : m.vertices()) {
    id[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
    const P3& p = m.point(v);
    out.vertices.push_back({p.x(), p.y(), p.z()});
  }
  for (auto f : m.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      if (k == 3) throw std::runtime_error("corefinement returned a non-triangle face");
      t[k++] = id[v.idx()];
    }
    out.triangles.push_back(t);
  }
  return out;
}

// The cell as a closed triangle mesh: each convex face fanned from its centroid (no
// sliver triangles even where the polygon has nearly collinear corners).
Mesh cell_mesh(const VoronoiCell& c) {
  Mesh m;
  std::vector<Mesh::Vertex_index> vid;
  for (const auto& p : c.vertices) vid.push_back(m.add_vertex(P3(p.x, p.y, p.z)));
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    Point3 ctr{0, 0, 0};
    for (auto k = b; k < e; ++k) ctr = vor::vadd(ctr, c.vertices[c.face_vertices[k]]);
    ctr = vor::vscale(1.0 / (e - b), ctr);
    const auto cv = m.add_vertex(P3(ctr.x, ctr.y, ctr.z));
    for (auto k = b; k < e; ++k) {
      const auto n = k + 1 < e ? k + 1 : b;
      m.add_face(cv, vid[c.face_vertices[k]], vid[c.face_vertices[n]]);
    }
  }
  return m;
}
}  // namespace

struct MeshClipper::Impl {
  Mesh sm;
  TriangleMesh repaired;
  double volume = 0;
  Tree tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K>> side;
  std::mutex side_mutex;
};

MeshClipper::MeshClipper(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  std::vector<P3> points;
  for (const auto& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  if (polygons.empty()) throw std::invalid_argument("mesh has no triangles");
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw std::invalid_argument("mesh is not manifold (an edge in more than two triangles, or inconsistent orientation)");
  Mesh& sm = impl_->sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  if (!CGAL::is_closed(sm)) throw std::invalid_argument("mesh is not closed (it has boundary edges)");
  if (PMP::does_self_intersect(sm)) throw std::invalid_argument("mesh intersects itself");
  if (!PMP::is_outward_oriented(sm)) PMP::reverse_face_orientations(sm);
  impl_->volume = PMP::volume(sm);
  impl_->repaired = to_triangles(sm);
  impl_->tree.insert(faces(sm).first, faces(sm).second, sm);
  impl_->tree.build();
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K>>(impl_->tree);
}

MeshClipper::~MeshClipper() = default;
const TriangleMesh& MeshClipper::mesh() const { return impl_->repaired; }
double MeshClipper::volume() const { return impl_->volume; }

PieceMesh MeshClipper::intersect(const VoronoiCell& c) const {
  PieceMesh piece;
  if (c.vertices.empty()) return piece;
  CGAL::Bbox_3 box;
  for (const auto& p : c.vertices) box += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
  Mesh cell = cell_mesh(c);
  Mesh out;
  if (!impl_->tree.do_intersect(box)) {
    // No mesh triangle comes near the cell: it lies wholly inside or wholly outside.
    CGAL::Bounded_side s;
    {
      std::lock_guard<std::mutex> lock(impl_->side_mutex);
      s = (*impl_->side)(P3(c.centroid.x, c.centroid.y, c.centroid.z));
    }
    if (s != CGAL::ON_BOUNDED_SIDE) return piece;
    out = cell;
    piece.boolean_skipped = true;
  } else {
    Mesh a = impl_->sm;
    if (!PMP::corefine_and_compute_intersection(a, cell, out))
      throw std::runtime_error("corefinement failed for a cell");
  }
  piece.mesh = to_triangles(out);
  // Cut faces: triangles whose three corners lie on one of the cell's face planes.
  const double tol = 1e-9 * vor::vnorm(vor::vsub(Point3{box.xmax(), box.ymax(), box.zmax()},
                                               Point3{box.xmin(), box.ymin(), box.zmin()}));
  struct Plane {
    Point3 n;
    double c;
    std::int32_t tag;
  };
  std::vector<Plane> planes;
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    const Point3 o = c.vertices[c.face_vertices[b]];
    Point3 n{0, 0, 0};
    for (auto k = b + 1; k + 1 < e; ++k)
      n = vor::vadd(n, vor::vcross(vor::vsub(c.vertices[c.face_vertices[k]], o), vor::vsub(c.vertices[c.face_vertices[k + 1]], o)));
    n = vor::vscale(1.0 / vor::vnorm(n), n);
    planes.push_back({n, vor::vdot(n, o), c.face_neighbor[f]});
  }
  piece.cut.assign(piece.mesh.triangles.size(), 0);
  piece.cut_tag.assign(piece.mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < piece.mesh.triangles.size(); ++t) {
    for (const auto& pl : planes) {
      bool on = true;
      for (int k = 0; k < 3 && on; ++k) on = std::abs(vor::vdot(pl.n, piece.mesh.corner(t, k)) - pl.c) <= tol;
      if (on) {
        piece.cut[t] = 1;
        piece.cut_tag[t] = pl.tag;
        break;
      }
    }
  }
  return piece;
}

}  // namespace dtlab
