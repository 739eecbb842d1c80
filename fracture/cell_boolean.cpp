// CGAL lives here only: conversion, input validation and one corefinement per cell.
#include "fracture/cell_boolean.hpp"
#include "fracture/deadline_visitor.hpp"
#include "fracture/nearest_double.hpp"
#include "kernel/parallel_for.hpp"

#include <algorithm>
#include <future>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <tuple>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
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

TriangleMesh to_triangles(const Mesh& m) {
  TriangleMesh out;
  std::vector<std::uint32_t> id(m.number_of_vertices() + m.number_of_removed_vertices(), 0);
  for (auto v : m.vertices()) {
    id[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
    const P3& p = m.point(v);
    out.vertices.push_back({nearest_double(p.x()), nearest_double(p.y()), nearest_double(p.z())});
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

// --- The band boolean: a cell corefined with only the mesh triangles near its surface.
using Side = CGAL::Side_of_triangle_mesh<Mesh, K>;
using Face = Mesh::Face_index;
using Soup = std::vector<std::array<std::size_t, 3>>;

CGAL::Bbox_3 face_box(const Mesh& m, Face f) {
  CGAL::Bbox_3 b;
  for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) b += m.point(v).bbox();
  return b;
}

// The mesh triangles that meet the cell's box, parted exactly: `crossing`, whose box
// meets a cell triangle (a superset of those meeting the cell's surface); `inside`,
// the others strictly inside the cell. The rest lie strictly outside. Triangles that
// meet no cell triangle form components that lie wholly on one side: one point test
// per component, none for a component next to a triangle outside the cell's box.
struct Band {
  std::vector<Face> crossing, inside;
};
Band band_of(const Mesh& sm, const Tree& tree, const CGAL::Bbox_3& box, const Tree& cell_tree, const Side& cell_side) {
  std::vector<Face> near;
  tree.all_intersected_primitives(box, std::back_inserter(near));
  std::sort(near.begin(), near.end());
  enum : std::uint8_t { far = 0, crossing, unseen, done };
  std::vector<std::uint8_t> state(sm.number_of_faces(), far);
  Band band;
  for (Face f : near) {
    const bool cross = cell_tree.do_intersect(face_box(sm, f));
    if (cross) band.crossing.push_back(f);
    state[f.idx()] = cross ? crossing : unseen;
  }
  for (Face f : near) {
    if (state[f.idx()] != unseen) continue;
    std::vector<Face> comp{f};
    state[f.idx()] = done;
    bool outside = false;
    for (std::size_t k = 0; k < comp.size(); ++k) {
      for (auto h : CGAL::halfedges_around_face(sm.halfedge(comp[k]), sm)) {
        const Face g = sm.face(sm.opposite(h));
        if (state[g.idx()] == far) {
          outside = true;  // g misses the cell's box, so does their shared edge
        } else if (state[g.idx()] == unseen) {
          state[g.idx()] = done;
          comp.push_back(g);
        }
      }
    }
    if (!outside && cell_side(sm.point(sm.target(sm.halfedge(f)))) == CGAL::ON_BOUNDED_SIDE)
      band.inside.insert(band.inside.end(), comp.begin(), comp.end());
  }
  std::sort(band.inside.begin(), band.inside.end());
  return band;
}

// The crossing triangles as a mesh of their own; empty where a vertex would be
// non-manifold in it (a fan split by the band's edge).
std::optional<Mesh> band_mesh(const Mesh& sm, const std::vector<Face>& faces) {
  Mesh s;
  std::vector<Mesh::Vertex_index> id(sm.number_of_vertices(), Mesh::null_vertex());
  for (Face f : faces) {
    std::array<Mesh::Vertex_index, 3> t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (id[v.idx()] == Mesh::null_vertex()) id[v.idx()] = s.add_vertex(sm.point(v));
      t[k++] = id[v.idx()];
    }
    if (s.add_face(t[0], t[1], t[2]) == Mesh::null_face()) return std::nullopt;
  }
  return s;
}

// The faces of m whose patch (bounded by constrained edges) `side` puts inside, judged
// at one face's centroid per patch; false if a centroid lies on the other surface
// (a coplanar contact: the caller falls back to CGAL's boolean).
template <class SideOf>
bool kept_faces(const Mesh& m, const Mesh::Property_map<Mesh::Edge_index, bool>& constrained, SideOf&& side,
                std::vector<Face>& keep) {
  std::vector<std::size_t> patch(m.number_of_faces());
  const auto fcc = CGAL::make_property_map(patch);
  const std::size_t n = PMP::connected_components(m, fcc, CGAL::parameters::edge_is_constrained_map(constrained));
  std::vector<int> inside(n, -1);
  for (Face f : m.faces()) {
    int& in = inside[patch[f.idx()]];
    if (in < 0) {
      const auto h = m.halfedge(f);
      const P3 c = CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
      const CGAL::Bounded_side s = side(c);
      if (s == CGAL::ON_BOUNDARY) return false;
      in = s == CGAL::ON_BOUNDED_SIDE;
    }
    if (in) keep.push_back(f);
  }
  return true;
}

void add_faces(const Mesh& m, const std::vector<Face>& faces, std::vector<P3>& points, Soup& soup) {
  std::vector<std::size_t> id(m.number_of_vertices(), SIZE_MAX);
  for (Face f : faces) {
    std::array<std::size_t, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      if (id[v.idx()] == SIZE_MAX) {
        id[v.idx()] = points.size();
        points.push_back(m.point(v));
      }
      t[k++] = id[v.idx()];
    }
    soup.push_back(t);
  }
}

// The soup welded by exact point equality; empty if it is not a closed polygon mesh.
std::optional<Mesh> closed_mesh(std::vector<P3>& points, Soup& soup) {
  Mesh out;
  if (soup.empty()) return out;
  PMP::merge_duplicate_points_in_polygon_soup(points, soup);
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup)) return std::nullopt;
  PMP::polygon_soup_to_polygon_mesh(points, soup, out);
  if (!CGAL::is_closed(out)) return std::nullopt;
  return out;
}
}  // namespace

struct MeshClipper::Impl {
  PieceMesh intersect_with(const Mesh& m, const VoronoiCell& c) const;
  bool intersect_band(const VoronoiCell& c, PieceMesh& piece) const;
  std::vector<std::uint32_t> band_pass(const std::vector<std::uint32_t>& ids, const std::vector<VoronoiCell>& cells,
                                       std::vector<PieceMesh>& out, unsigned threads) const;
  void finish_piece(const Mesh& out, const VoronoiCell& c, PieceMesh& piece) const;
  CGAL::Bounded_side side_of_mesh(const P3& p) const;
  void report_progress() const;
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
  bool band_booleans = true;
  mutable ClipStats stats;  // of the last intersect_all
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
  t.difference = nearest_double(ExactFT((impl_->tally_sum - impl_->mesh_volume6) / 6));
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
  std::vector<std::uint32_t> rest = impl_->band_booleans ? impl_->band_pass(ids, cells, out, threads) : ids;
  impl_->stats = {ids.size() - rest.size(), rest.size()};
  impl_->split(impl_->sm, std::move(rest), cells, out, threads);
  return out;
}

void MeshClipper::set_band_booleans(bool on) { impl_->band_booleans = on; }
MeshClipper::ClipStats MeshClipper::last_stats() const { return impl_->stats; }

// Every cell through the band boolean, in parallel (each writes only its own piece);
// returns the cells it left to the box splits, in order.
std::vector<std::uint32_t> MeshClipper::Impl::band_pass(const std::vector<std::uint32_t>& ids,
                                                        const std::vector<VoronoiCell>& cells,
                                                        std::vector<PieceMesh>& out, unsigned threads) const {
  std::vector<char> done_here(ids.size(), 0);
  parallel_for(ids.size(), threads, 1, [&](std::size_t k, unsigned) {
    try {
      done_here[k] = intersect_band(cells[ids[k]], out[ids[k]]);
    } catch (const BooleanTimeout& e) {
      throw std::runtime_error("cell " + std::to_string(ids[k]) + ": " + e.what());
    }
    if (done_here[k]) report_progress();
  });
  std::vector<std::uint32_t> rest;
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (!done_here[k]) rest.push_back(ids[k]);
  return rest;
}

CGAL::Bounded_side MeshClipper::Impl::side_of_mesh(const P3& p) const {
  std::lock_guard<std::mutex> lock(side_mutex);
  return (*side)(p);
}

void MeshClipper::Impl::report_progress() const {
  if (!progress) return;
  std::lock_guard<std::mutex> g(progress_mutex);
  progress(++done, total);
}

// Mesh ∩ cell from the band: the crossing triangles corefined with the cell, their
// patches inside the cell, the cell's patches inside the mesh, and the triangles
// strictly inside the cell as they are. False (piece untouched) where a patch touches
// the other surface in a face (coplanar) or the result is not a closed polygon mesh.
bool MeshClipper::Impl::intersect_band(const VoronoiCell& c, PieceMesh& piece) const {
  const Mesh cell0 = cell_mesh(c);
  const Tree cell_tree(faces(cell0).first, faces(cell0).second, cell0);
  const Side cell_side(cell_tree);
  const Band band = band_of(sm, tree, PMP::bbox(cell0), cell_tree, cell_side);
  std::vector<P3> points;
  Soup soup;
  add_faces(sm, band.inside, points, soup);
  bool skipped = band.crossing.empty();
  if (skipped) {
    // Nothing meets the cell's surface: the cell is inside the mesh or outside it.
    if (side_of_mesh(cell0.point(*cell0.vertices().begin())) == CGAL::ON_BOUNDED_SIDE) {
      const std::vector<Face> all(cell0.faces().begin(), cell0.faces().end());
      add_faces(cell0, all, points, soup);
    }
  } else {
    std::optional<Mesh> s = band_mesh(sm, band.crossing);
    if (!s) return false;
    Mesh cell = cell0;
    const auto ecm_s = s->add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
    const auto ecm_c = cell.add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
    PMP::corefine(*s, cell, CGAL::parameters::edge_is_constrained_map(ecm_s).visitor(DeadlineVisitor<Mesh>(budget)),
                  CGAL::parameters::edge_is_constrained_map(ecm_c));
    std::vector<Face> keep_s, keep_c;
    if (!kept_faces(*s, ecm_s, cell_side, keep_s)) return false;
    const auto mesh_side = [&](const P3& p) { return side_of_mesh(p); };
    if (!kept_faces(cell, ecm_c, mesh_side, keep_c)) return false;
    add_faces(*s, keep_s, points, soup);
    add_faces(cell, keep_c, points, soup);
  }
  const std::optional<Mesh> out = closed_mesh(points, soup);
  if (!out) return false;
  piece.boolean_skipped = skipped && !soup.empty();
  finish_piece(*out, c, piece);
  return true;
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
        report_progress();
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
    if (side_of_mesh(P3(c.centroid.x, c.centroid.y, c.centroid.z)) != CGAL::ON_BOUNDED_SIDE) return piece;
    out = cell;
    piece.boolean_skipped = true;
  } else if (m.number_of_faces() == 0) {
    return piece;  // the mesh misses the box holding this cell
  } else {
    Mesh a = m;
    if (!intersect_within(a, cell, out, budget))
      throw std::runtime_error("corefinement failed for a cell");
  }
  finish_piece(out, c, piece);
  return piece;
}

// The piece's triangles rounded to doubles, its exact volume into the tally, and its
// cut faces marked.
void MeshClipper::Impl::finish_piece(const Mesh& out, const VoronoiCell& c, PieceMesh& piece) const {
  const CGAL::Bbox_3 box = cell_box(c);
  if (tally) {  // first: forcing the exact values must not change the written doubles
    const ExactFT v = exact_volume6(out);
    std::lock_guard<std::mutex> g(progress_mutex);
    tally_sum += v;
  }
  piece.mesh = to_triangles(out);
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
}

}  // namespace dtlab
