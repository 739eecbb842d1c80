// CGAL's Polygon Mesh Processing drives the repair; the diagnosis before and after is
// sampling/mesh_report (the same words as everywhere else).
#include "fracture/mesh_repair.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include "fracture/deadline_visitor.hpp"
#include "fracture/pinched_vertices.hpp"
#include "fracture/surface_mesh_convert.hpp"
#include "fracture/winding_solid.hpp"
#include "predicates/adaptive.hpp"
#include "sampling/merge_vertices.hpp"
#include "sampling/self_intersection.hpp"

namespace PMP = CGAL::Polygon_mesh_processing;

namespace dtlab {

namespace {
using surface_mesh_convert::to_mesh;
using surface_mesh_convert::to_triangles;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<EK::Point_3>;
using Polygon = std::vector<std::size_t>;

// Seconds the autorefinement may take before the repair gives up on self-intersections.
constexpr double kAutorefineSeconds = 30;

void append(TriangleMesh& a, const TriangleMesh& b) {
  const auto n = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
}

// The union of the shells of `m` when each shell alone is a solid (outward), by exact
// corefinements; false when that does not apply or a corefinement fails.
bool union_of_shells(const TriangleMesh& m, TriangleMesh& out, std::size_t& count) {
  std::vector<TriangleMesh> shells = connected_shells(m);
  count = shells.size();
  if (shells.size() < 2 || shells.size() > 500) return false;
  for (auto& c : shells) {
    const MeshReport r = analyze_mesh(c);
    if (!r.solid() || r.volume <= 0) return false;
  }
  const DeadlineVisitor<ExactMesh> deadline(kAutorefineSeconds);
  try {
    ExactMesh acc;
    to_mesh(shells[0], acc);
    for (std::size_t i = 1; i < shells.size(); ++i) {
      ExactMesh b, joined;
      to_mesh(shells[i], b);
      if (!PMP::corefine_and_compute_union(acc, b, joined, CGAL::parameters::visitor(deadline),
                                           CGAL::parameters::default_values(), CGAL::parameters::default_values()))
        return false;
      acc = std::move(joined);
    }
    out = to_triangles(acc);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

bool has_repeated_triangle(const TriangleMesh& m) {
  std::set<std::array<std::uint32_t, 3>> seen;
  for (auto t : m.triangles) {
    std::sort(t.begin(), t.end());
    if (!seen.insert(t).second) return true;
  }
  return false;
}

bool same_cycle_reversed(const Polygon& a, const Polygon& b) {
  // b is a with the opposite orientation (3 corners): some rotation of b reversed equals a.
  for (int s = 0; s < 3; ++s)
    if (a[0] == b[s] && a[1] == b[(s + 2) % 3] && a[2] == b[(s + 1) % 3]) return true;
  return false;
}

void add_step(RepairResult& r, const char* what, std::size_t count, std::string detail = "") {
  if (count > 0) r.steps.push_back({what, count, std::move(detail)});
}

// Stage 1's shortcut: a mesh the report judged a solid once merged needs nothing but
// an inward orientation turned outward.
RepairResult& finish_solid(MergedMesh& merged, RepairResult& r) {
  r.mesh = std::move(merged.mesh);
  if (r.before.volume < 0) {
    for (auto& t : r.mesh.triangles) std::swap(t[1], t[2]);
    add_step(r, "reversed triangles to bound a volume", r.mesh.triangles.size());
  }
  r.after = r.before;
  r.after.vertices = r.mesh.vertices.size();
  r.after.duplicate_vertices = 0;
  r.after.duplicate_at.clear();
  r.after.volume = std::abs(r.before.volume);
  return r;
}

// Stage 2: the polygons left without degenerate triangles (repeated corner, collinear
// corners: exact) and repeated triangles (the same three vertices again, in either
// orientation).
std::vector<Polygon> without_degenerate_or_repeated(const TriangleMesh& mesh, RepairResult& r) {
  const AdaptivePredicates pred;
  std::vector<Polygon> polygons;
  std::set<std::array<std::uint32_t, 3>> seen;
  std::size_t degenerate = 0, repeated = 0;
  const auto& V = mesh.vertices;
  for (const auto& tri : mesh.triangles) {
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] ||
        detail::collinear(V[tri[0]], V[tri[1]], V[tri[2]], pred)) {
      ++degenerate;
      continue;
    }
    auto key = tri;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) {
      ++repeated;
      continue;
    }
    polygons.push_back({tri[0], tri[1], tri[2]});
  }
  add_step(r, "dropped degenerate triangles", degenerate);
  add_step(r, "dropped repeated triangles", repeated);
  return polygons;
}

// Stage 3: non-manifold vertices split, faces oriented consistently (per component).
void orient_soup(std::vector<K::Point_3>& points, std::vector<Polygon>& polygons, RepairResult& r) {
  const std::size_t points_before = points.size();
  const std::vector<Polygon> polygons_before = polygons;
  PMP::orient_polygon_soup(points, polygons);
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < polygons.size() && i < polygons_before.size(); ++i)
    flipped += polygons[i] != polygons_before[i] && same_cycle_reversed(polygons[i], polygons_before[i]);
  add_step(r, "split non-manifold vertices and edges", points.size() - points_before,
           "added " + std::to_string(points.size() - points_before) + " vertices");
  add_step(r, "reversed triangles to orient consistently", flipped);
}

// Stage 5: every boundary cycle triangulated (minimum-weight, Delaunay-restricted), or
// where that finds nothing, a fan from the loop's centroid.
void fill_holes(Mesh& m, RepairResult& r) {
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
  std::size_t filled = 0, fanned = 0, added = 0;
  for (auto h : cycles) {
    if (!m.is_border(h)) continue;
    std::vector<Mesh::Face_index> patch;
    try {
      PMP::triangulate_hole(m, h, std::back_inserter(patch));
    } catch (const std::exception&) {
      patch.clear();
    }
    if (!patch.empty()) {
      ++filled, added += patch.size();
      continue;
    }
    if (!m.is_border(h)) continue;
    K::Vector_3 c(0, 0, 0);
    std::size_t n = 0;
    for (auto g : CGAL::halfedges_around_face(h, m)) c = c + (m.point(m.target(g)) - CGAL::ORIGIN), ++n;
    CGAL::Euler::fill_hole(h, m);
    const auto centre = CGAL::Euler::add_center_vertex(h, m);
    m.point(m.target(centre)) = CGAL::ORIGIN + c / static_cast<double>(n);
    ++fanned, added += n;
  }
  add_step(r, "filled holes", filled + fanned,
           "added " + std::to_string(added) + " triangles" +
               (fanned ? ", " + std::to_string(fanned) + " as fans from the centroid" : ""));
}

// Stage 6: degenerate triangles left by stitching or filling, collapsed.
void collapse_degenerate(Mesh& m, RepairResult& r) {
  std::size_t before = 0;
  for (auto f : m.faces()) before += PMP::is_degenerate_triangle_face(f, m);
  if (before == 0) return;
  try {
    PMP::remove_degenerate_faces(m);
  } catch (const std::exception&) {
  }
  m.collect_garbage();
  std::size_t after = 0;
  for (auto f : m.faces()) after += PMP::is_degenerate_triangle_face(f, m);
  add_step(r, "collapsed degenerate triangles", before - std::min(before, after));
}

// The mesh between the stages 7 to 9 and its report, with the result's steps.
struct RepairState {
  RepairResult& result;
  TriangleMesh current;
  MeshReport now;
  void accept(TriangleMesh mesh, const MeshReport& report) {
    current = std::move(mesh);
    now = report;
  }
};

// Stage 7: closed shells that enclose nothing (flat patches closed by the hole filling)
// dropped when other shells enclose a volume.
void drop_empty_shells(RepairState& s) {
  std::vector<TriangleMesh> shells = connected_shells(s.current);
  double total = 0;
  std::vector<double> volumes;
  for (const auto& c : shells) total += std::abs(volumes.emplace_back(signed_volume(c)));
  std::size_t dropped = 0;
  TriangleMesh kept;
  for (std::size_t i = 0; i < shells.size(); ++i) {
    if (shells.size() > 1 && std::abs(volumes[i]) <= 1e-9 * total)
      ++dropped;
    else
      append(kept, shells[i]);
  }
  if (dropped > 0 && !kept.triangles.empty()) {
    add_step(s.result, "dropped shells that enclose no volume", dropped);
    const MeshReport report = analyze_mesh(kept);
    s.accept(std::move(kept), report);
  }
}

// Stage 7b: shells nested in a shell of the same orientation (a volume covered twice):
// their union, which is the outer shell alone.
void unite_nested_shells(RepairState& s) {
  if (s.now.nested_shells == 0) return;
  const std::vector<TriangleMesh> shells = connected_shells(s.current);
  const std::vector<char> nested = nested_same_orientation(shells);
  TriangleMesh kept;
  std::size_t dropped = 0;
  for (std::size_t j = 0; j < shells.size(); ++j) {
    if (nested[j])
      ++dropped;
    else
      append(kept, shells[j]);
  }
  const MeshReport check = analyze_mesh(kept);
  if (dropped > 0 && check.nested_shells == 0) {
    add_step(s.result, "united nested shells of the same orientation (kept the outer)", dropped);
    s.accept(std::move(kept), check);
  }
}

// Stage 7c: pinched vertices (two fans touching at a point, e.g. where a duplicate
// vertex was merged): one vertex per fan, each moved 1e-3 of the way into its fan.
void separate_pinched(RepairState& s) {
  if (!(s.now.closed && !s.now.manifold && s.now.nonmanifold_edges == 0)) return;
  TriangleMesh separated = s.current;
  const std::size_t pinched = separate_pinched_vertices(separated);
  const MeshReport check = analyze_mesh(separated);
  if (pinched > 0 && check.manifold && check.closed) {
    add_step(s.result, "separated pinched vertices", pinched, "one vertex per fan, moved 1e-3 of the way into it");
    s.accept(std::move(separated), check);
  }
}

// Stage 8a: shells that are solids each but overlap: their union, one exact
// corefinement at a time.
void unite_overlapping_shells(RepairState& s) {
  if (!(s.now.self_intersections > 0 && s.now.closed)) return;
  TriangleMesh joined;
  std::size_t shells = 0;
  if (!union_of_shells(s.current, joined, shells)) return;
  const MeshReport check = analyze_mesh(joined);
  if (check.solid() && check.volume > 0) {
    add_step(s.result, "resolved self-intersecting triangle pairs", s.now.self_intersections,
             "union of " + std::to_string(shells) + " overlapping shells");
    s.accept(std::move(joined), check);
  }
}

// Stage 8b: autorefinement (exact constructions), the patches inside the volume
// removed, accepted only if it leaves a closed mesh that keeps at least half the volume.
void autorefine(RepairState& s) {
  ExactMesh em;
  to_mesh(s.current, em);
  try {
    const bool fixed = PMP::experimental::autorefine_and_remove_self_intersections(
        em, CGAL::parameters::visitor(DeadlineVisitor<ExactMesh>(kAutorefineSeconds)));
    em.collect_garbage();
    TriangleMesh refined = to_triangles(em);
    const MeshReport check = analyze_mesh(refined);
    if (fixed && check.self_intersections == 0 && check.closed &&
        std::abs(check.volume) >= 0.5 * std::abs(s.now.volume)) {
      add_step(s.result, "resolved self-intersecting triangle pairs", s.now.self_intersections,
               "autorefined, inner patches removed");
      s.accept(std::move(refined), check);
    }
  } catch (const std::exception&) {
    // Autorefinement gave up (or ran out of time): the report at the end says what remains.
  }
}

// Stage 8c: the winding-number solid (the region with winding number >= 1/2), when it
// is a solid; where it touches itself at a point (intersection curves crossing), the
// pinched vertex is separated.
void winding_solid(RepairState& s) {
  WindingSolid ws = winding_number_solid(s.current, kAutorefineSeconds);
  if (!ws.ok) return;
  MeshReport check = analyze_mesh(ws.mesh);
  std::size_t pinched = 0;
  if (check.closed && !check.manifold && check.nonmanifold_edges == 0) {
    pinched = separate_pinched_vertices(ws.mesh);
    check = analyze_mesh(ws.mesh);
  }
  if (check.solid() && check.volume > 0) {
    add_step(s.result, "resolved self-intersecting triangle pairs", s.now.self_intersections,
             "winding-number solid: " + std::to_string(ws.kept + ws.reversed) + " of " + std::to_string(ws.patches) +
                 " patches kept" + (ws.reversed ? " (" + std::to_string(ws.reversed) + " reversed)" : ""));
    add_step(s.result, "separated pinched vertices", pinched);
    s.accept(std::move(ws.mesh), check);
  }
}

// Stage 8: self-intersections, by union (8a), else autorefinement (8b), else the
// winding-number solid (8c). CGAL's experimental autorefinement crashed on flat shells
// (a patch closed by its own hole filling, two coplanar sheets) in CGAL 5.5: only
// volumes go to 8b and 8c.
void resolve_self_intersections(RepairState& s) {
  unite_overlapping_shells(s);
  const Point3 ext = s.now.box.hi - s.now.box.lo;
  const bool flat = !(std::abs(s.now.volume) > 1e-9 * ext.x * ext.y * ext.z) || has_repeated_triangle(s.current);
  if (s.now.self_intersections > 0 && s.now.closed && !flat) autorefine(s);
  if (s.now.self_intersections > 0 && s.now.closed && !flat) winding_solid(s);
}

// Stage 9: every shell oriented so that the mesh bounds a volume (outer shells outward,
// cavities inward).
void orient_to_bound_volume(RepairState& s) {
  if (!(s.now.closed && s.now.manifold && s.now.self_intersections == 0 && s.now.degenerate_triangles == 0)) return;
  Mesh o;
  to_mesh(s.current, o);
  const TriangleMesh before = to_triangles(o);
  PMP::orient_to_bound_a_volume(o);
  TriangleMesh oriented = to_triangles(o);
  std::size_t reversed = 0;
  for (std::size_t t = 0; t < oriented.triangles.size() && t < before.triangles.size(); ++t)
    reversed += same_cycle_reversed({oriented.triangles[t][0], oriented.triangles[t][1], oriented.triangles[t][2]},
                                    {before.triangles[t][0], before.triangles[t][1], before.triangles[t][2]});
  add_step(s.result, "reversed triangles to bound a volume", reversed);
  s.current = std::move(oriented);
}
}  // namespace

RepairResult repair_mesh(const TriangleMesh& input) {
  RepairResult r;
  r.before = analyze_mesh(input);
  // 1. Duplicate vertices (identical coordinates).
  MergedMesh merged = merge_duplicate_vertices(input);
  add_step(r, "merged duplicate vertices", merged.duplicates);
  if (r.before.solid()) return finish_solid(merged, r);
  // 2. Degenerate and repeated triangles.
  std::vector<Polygon> polygons = without_degenerate_or_repeated(merged.mesh, r);
  if (polygons.empty()) {
    r.mesh = TriangleMesh{};
    r.after = analyze_mesh(r.mesh);
    return r;
  }
  // 3. Non-manifold vertices, orientation.
  std::vector<K::Point_3> points;
  for (const auto& p : merged.mesh.vertices) points.emplace_back(p.x, p.y, p.z);
  orient_soup(points, polygons, r);
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
  // 4. Borders that run along each other with equal vertices, stitched.
  add_step(r, "stitched border edges", PMP::stitch_borders(m));
  // 5. Holes. 6. Degenerate triangles they left.
  fill_holes(m, r);
  collapse_degenerate(m, r);
  // 7. Empty and nested shells, pinched vertices. 8. Self-intersections. 9. Orientation.
  RepairState s{r, to_triangles(m), {}};
  s.now = analyze_mesh(s.current);
  drop_empty_shells(s);
  unite_nested_shells(s);
  separate_pinched(s);
  resolve_self_intersections(s);
  orient_to_bound_volume(s);
  r.mesh = std::move(s.current);
  r.after = analyze_mesh(r.mesh);
  return r;
}

}  // namespace dtlab
