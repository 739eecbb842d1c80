// CGAL lives here only: conversion, input validation and one corefinement per cell.
#include "fracture/cell_boolean.hpp"
#include "fracture/deadline_visitor.hpp"

#include <algorithm>
#include <future>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace dtlab {

namespace {
// Exact constructions: with EPICK the corefinement rounds intersection points and can
// loop on coplanar contacts (an 8-vertex cube at 18+ pieces never finished).
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

using ExactFT = K::Exact_kernel::FT;

// 6 x the signed volume the closed mesh bounds, exactly (forces the exact coordinates).
ExactFT exact_volume6(const Mesh& m) {
  ExactFT sum = 0;
  for (auto f : m.faces()) {
    const auto h = m.halfedge(f);
    const auto a = CGAL::exact(m.point(m.source(h)));
    const auto b = CGAL::exact(m.point(m.target(h)));
    const auto c = CGAL::exact(m.point(m.target(m.next(h))));
    sum += a.x() * (b.y() * c.z() - b.z() * c.y()) + a.y() * (b.z() * c.x() - b.x() * c.z()) +
           a.z() * (b.x() * c.y() - b.y() * c.x());
  }
  return sum;
}

// tm1 ∩ tm2 -> out within the time budget (0: none).
bool intersect_within(Mesh& a, Mesh& b, Mesh& out, double budget) {
  if (budget <= 0) return PMP::corefine_and_compute_intersection(a, b, out);
  return PMP::corefine_and_compute_intersection(a, b, out, CGAL::parameters::visitor(DeadlineVisitor<Mesh>(budget)),
                                                CGAL::parameters::default_values(), CGAL::parameters::default_values());
}

// A lazy-exact coordinate to the nearest double or next to it: the interval when it is
// tight, else the exact value (CGAL's own to_double accepts intervals 1e-5 wide).
double coordinate(const K::FT& v) {
  const auto& i = v.approx();
  if (i.sup() - i.inf() <= 1e-14 * std::max(std::abs(i.inf()), std::abs(i.sup()))) return CGAL::to_double(i);
  return CGAL::to_double(v.exact());
}

TriangleMesh to_triangles(const Mesh& m) {
  TriangleMesh out;
  std::vector<std::uint32_t> id(m.number_of_vertices() + m.number_of_removed_vertices(), 0);
  for (auto v : m.vertices()) {
    id[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
    const P3& p = m.point(v);
    out.vertices.push_back({coordinate(p.x()), coordinate(p.y()), coordinate(p.z())});
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
    // Summed in sorted order: the neighbour cell, listing the same corners in another
    // order, gets the same double and so the same fan (the cells tile space exactly).
    std::vector<Point3> corners;
    for (auto k = b; k < e; ++k) corners.push_back(c.vertices[c.face_vertices[k]]);
    std::sort(corners.begin(), corners.end(),
              [](const Point3& p, const Point3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); });
    Point3 ctr{0, 0, 0};
    for (const Point3& p : corners) ctr = ctr + p;
    ctr = 1.0 / (e - b) * ctr;
    const auto cv = m.add_vertex(P3(ctr.x, ctr.y, ctr.z));
    for (auto k = b; k < e; ++k) {
      const auto n = k + 1 < e ? k + 1 : b;
      m.add_face(cv, vid[c.face_vertices[k]], vid[c.face_vertices[n]]);
    }
  }
  return m;
}

// The closed box as 12 outward triangles.
Mesh box_mesh(const CGAL::Bbox_3& b) {
  Mesh m;
  Mesh::Vertex_index v[8];
  for (int k = 0; k < 8; ++k)
    v[k] = m.add_vertex(P3((k & 1) ? b.xmax() : b.xmin(), (k & 2) ? b.ymax() : b.ymin(), (k & 4) ? b.zmax() : b.zmin()));
  static const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.add_face(v[q[0]], v[q[1]], v[q[2]]);
    m.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
  return m;
}

CGAL::Bbox_3 cell_box(const VoronoiCell& c) {
  CGAL::Bbox_3 box;
  for (const auto& p : c.vertices) box += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
  return box;
}

bool box_inside(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b) {
  return a.xmin() >= b.xmin() && a.ymin() >= b.ymin() && a.zmin() >= b.zmin() && a.xmax() <= b.xmax() &&
         a.ymax() <= b.ymax() && a.zmax() <= b.zmax();
}
}  // namespace

struct MeshClipper::Impl {
  PieceMesh intersect_with(const Mesh& m, const VoronoiCell& c) const;
  void split(const Mesh& m, std::vector<std::uint32_t> ids, const std::vector<VoronoiCell>& cells,
             std::vector<PieceMesh>& out, unsigned threads) const;

  Mesh sm;
  TriangleMesh repaired;
  double volume = 0;
  Tree tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K>> side;
  mutable std::mutex side_mutex;
  double budget = 0;
  std::function<void(std::size_t, std::size_t)> progress;
  mutable std::mutex progress_mutex;
  mutable std::size_t done = 0, total = 0;  // of the running intersect_all, under progress_mutex
  bool tally = false;
  mutable ExactFT tally_sum = 0;  // under progress_mutex
  ExactFT mesh_volume6 = 0;
};

MeshClipper::MeshClipper(const TriangleMesh& mesh, MeshCheck check) : impl_(std::make_unique<Impl>()) {
  std::vector<P3> points;
  for (const auto& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  if (polygons.empty()) throw std::invalid_argument("mesh has no triangles");
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  if (check == MeshCheck::full && !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw std::invalid_argument("mesh is not manifold (an edge in more than two triangles, or inconsistent orientation)");
  Mesh& sm = impl_->sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  if (!CGAL::is_closed(sm)) throw std::invalid_argument("mesh is not closed (it has boundary edges)");
  // Self-intersections are the caller's check (analyze_mesh, exact predicates): CGAL's
  // test on the exact kernel cost seconds on 75k triangles.
  if (!PMP::is_outward_oriented(sm)) PMP::reverse_face_orientations(sm);
  impl_->repaired = to_triangles(sm);  // input coordinates: exact doubles
  impl_->volume = signed_volume(impl_->repaired);
  impl_->tree.insert(faces(sm).first, faces(sm).second, sm);
  impl_->tree.build();
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K>>(impl_->tree);
}

MeshClipper::~MeshClipper() = default;
void MeshClipper::set_time_budget(double seconds) { impl_->budget = seconds; }
void MeshClipper::set_exact_tally(bool on) {
  impl_->tally = on;
  if (on) impl_->mesh_volume6 = exact_volume6(impl_->sm);
}
MeshClipper::ExactTally MeshClipper::exact_tally() const {
  std::lock_guard<std::mutex> g(impl_->progress_mutex);
  ExactTally t;
  t.holds = impl_->tally && impl_->tally_sum == impl_->mesh_volume6;
  t.difference = CGAL::to_double((impl_->tally_sum - impl_->mesh_volume6) / 6);
  return t;
}
void MeshClipper::set_progress(std::function<void(std::size_t, std::size_t)> progress) {
  impl_->progress = std::move(progress);
}
const TriangleMesh& MeshClipper::mesh() const { return impl_->repaired; }
double MeshClipper::volume() const { return impl_->volume; }

PieceMesh MeshClipper::intersect(const VoronoiCell& c) const { return impl_->intersect_with(impl_->sm, c); }

std::vector<PieceMesh> MeshClipper::intersect_all(const std::vector<VoronoiCell>& cells, unsigned threads) const {
  std::vector<PieceMesh> out(cells.size());
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < cells.size(); ++i)
    if (!cells[i].vertices.empty()) ids.push_back(i);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  {
    std::lock_guard<std::mutex> g(impl_->progress_mutex);
    impl_->done = 0;
    impl_->total = ids.size();
    impl_->tally_sum = 0;
  }
  impl_->split(impl_->sm, std::move(ids), cells, out, threads);
  return out;
}

void MeshClipper::Impl::split(const Mesh& m, std::vector<std::uint32_t> ids, const std::vector<VoronoiCell>& cells,
                              std::vector<PieceMesh>& out, unsigned threads) const {
  // Cells per leaf: below this a box cut costs more than it saves (measured: 4, 8,
  // 16, 32 cells per leaf on the 65k-triangle benchmark, 16 best).
  constexpr std::size_t kLeaf = 16;
  if (ids.size() <= kLeaf || m.number_of_faces() == 0) {
    for (auto i : ids) {
      try {
        out[i] = intersect_with(m, cells[i]);
        if (progress) {
          std::lock_guard<std::mutex> g(progress_mutex);
          progress(++done, total);
        }
      } catch (const BooleanTimeout& e) {
        throw std::runtime_error("cell " + std::to_string(i) + ": " + e.what());
      }
    }
    return;
  }
  // Halve along the longest spread of the cell centroids.
  CGAL::Bbox_3 spread;
  for (auto i : ids) {
    const Point3& c = cells[i].centroid;
    spread += CGAL::Bbox_3(c.x, c.y, c.z, c.x, c.y, c.z);
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (spread.max(k) - spread.min(k) > spread.max(axis) - spread.min(axis)) axis = k;
  auto coord = [&](std::uint32_t i) {
    const Point3& c = cells[i].centroid;
    return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
  };
  const auto mid = ids.begin() + ids.size() / 2;
  std::nth_element(ids.begin(), mid, ids.end(), [&](auto a, auto b) { return coord(a) < coord(b); });
  std::vector<std::uint32_t> half[2] = {{ids.begin(), mid}, {mid, ids.end()}};
  const CGAL::Bbox_3 mbox = CGAL::Polygon_mesh_processing::bbox(m);
  auto run = [&](int h, unsigned th) {
    // The box around this half's cells, grown a little so that no cell face lies on
    // a box wall (no coplanar contact in the later corefinements).
    CGAL::Bbox_3 b;
    for (auto i : half[h]) b += cell_box(cells[i]);
    double g = 0;
    for (int k = 0; k < 3; ++k) g = std::max(g, b.max(k) - b.min(k));
    g = 1e-6 * g;
    // A wall within a few g of the mesh's box (the parent's wall, whose cut faces the
    // mesh now has) moves well outside instead: no coplanar or near-coplanar walls.
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      const double far = 0.01 * (mbox.max(k) - mbox.min(k)) + g;
      lo[k] = b.min(k) - g <= mbox.min(k) + 4 * g ? mbox.min(k) - far : b.min(k) - g;
      hi[k] = b.max(k) + g >= mbox.max(k) - 4 * g ? mbox.max(k) + far : b.max(k) + g;
    }
    b = CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    if (box_inside(mbox, b)) return split(m, std::move(half[h]), cells, out, th);
    Mesh a = m, box = box_mesh(b), cut;
    try {
      if (!intersect_within(a, box, cut, budget))
        throw std::runtime_error("corefinement failed for a box of cells");
    } catch (const BooleanTimeout& e) {
      throw std::runtime_error("box around " + std::to_string(half[h].size()) + " cells: " + e.what());
    }
    split(cut, std::move(half[h]), cells, out, th);
  };
  if (threads > 1) {
    auto other = std::async(std::launch::async, run, 1, threads / 2);
    run(0, threads - threads / 2);
    other.get();
  } else {
    run(0, 1);
    run(1, 1);
  }
}

PieceMesh MeshClipper::Impl::intersect_with(const Mesh& m, const VoronoiCell& c) const {
  PieceMesh piece;
  if (c.vertices.empty()) return piece;
  const CGAL::Bbox_3 box = cell_box(c);
  Mesh cell = cell_mesh(c);
  Mesh out;
  if (!tree.do_intersect(box)) {
    // No mesh triangle comes near the cell: it lies wholly inside or wholly outside.
    CGAL::Bounded_side s;
    {
      std::lock_guard<std::mutex> lock(side_mutex);
      s = (*side)(P3(c.centroid.x, c.centroid.y, c.centroid.z));
    }
    if (s != CGAL::ON_BOUNDED_SIDE) return piece;
    out = cell;
    piece.boolean_skipped = true;
  } else if (m.number_of_faces() == 0) {
    return piece;  // the mesh misses the box holding this cell
  } else {
    Mesh a = m;
    if (!intersect_within(a, cell, out, budget))
      throw std::runtime_error("corefinement failed for a cell");
  }
  piece.mesh = to_triangles(out);
  if (tally) {
    const ExactFT v = exact_volume6(out);
    std::lock_guard<std::mutex> g(progress_mutex);
    tally_sum += v;
  }
  // Cut faces: triangles whose three corners lie on one of the cell's face planes.
  const double tol =
      1e-9 * norm(Point3{box.xmax(), box.ymax(), box.zmax()} - Point3{box.xmin(), box.ymin(), box.zmin()});
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
      n = n + cross(c.vertices[c.face_vertices[k]] - o, c.vertices[c.face_vertices[k + 1]] - o);
    n = 1.0 / norm(n) * n;
    planes.push_back({n, dot(n, o), c.face_neighbor[f]});
  }
  piece.cut.assign(piece.mesh.triangles.size(), 0);
  piece.cut_tag.assign(piece.mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < piece.mesh.triangles.size(); ++t) {
    for (const auto& pl : planes) {
      bool on = true;
      for (int k = 0; k < 3 && on; ++k) on = std::abs(dot(pl.n, piece.mesh.corner(t, k)) - pl.c) <= tol;
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
