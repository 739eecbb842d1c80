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
}  // namespace

RepairResult repair_mesh(const TriangleMesh& input) {
  RepairResult r;
  r.before = analyze_mesh(input);
  auto step = [&](const char* what, std::size_t count, std::string detail = "") {
    if (count > 0) r.steps.push_back({what, count, std::move(detail)});
  };

  // 1. Duplicate vertices (identical coordinates).
  MergedMesh merged = merge_duplicate_vertices(input);
  step("merged duplicate vertices", merged.duplicates);
  if (r.before.solid()) {
    // Nothing else to repair (the report judged the merged mesh); only an inward
    // orientation is turned outward.
    r.mesh = std::move(merged.mesh);
    if (r.before.volume < 0) {
      for (auto& t : r.mesh.triangles) std::swap(t[1], t[2]);
      step("reversed triangles to bound a volume", r.mesh.triangles.size());
    }
    r.after = r.before;
    r.after.vertices = r.mesh.vertices.size();
    r.after.duplicate_vertices = 0;
    r.after.duplicate_at.clear();
    r.after.volume = std::abs(r.before.volume);
    return r;
  }

  // 2. Degenerate triangles (repeated corner, collinear corners: exact) and repeated
  //    triangles (the same three vertices again, in either orientation).
  const AdaptivePredicates pred;
  std::vector<K::Point_3> points;
  for (const auto& p : merged.mesh.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<Polygon> polygons;
  std::set<std::array<std::uint32_t, 3>> seen;
  std::size_t degenerate = 0, repeated = 0;
  for (std::size_t t = 0; t < merged.mesh.triangles.size(); ++t) {
    const auto& tri = merged.mesh.triangles[t];
    const auto& V = merged.mesh.vertices;
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
  step("dropped degenerate triangles", degenerate);
  step("dropped repeated triangles", repeated);
  if (polygons.empty()) {
    r.mesh = TriangleMesh{};
    r.after = analyze_mesh(r.mesh);
    return r;
  }

  // 3. Non-manifold vertices split, faces oriented consistently (per component).
  const std::size_t points_before = points.size();
  const std::vector<Polygon> polygons_before = polygons;
  PMP::orient_polygon_soup(points, polygons);
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < polygons.size() && i < polygons_before.size(); ++i)
    flipped += polygons[i] != polygons_before[i] && same_cycle_reversed(polygons[i], polygons_before[i]);
  step("split non-manifold vertices and edges", points.size() - points_before,
       "added " + std::to_string(points.size() - points_before) + " vertices");
  step("reversed triangles to orient consistently", flipped);

  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, m);

  // 4. Borders that run along each other with equal vertices, stitched.
  step("stitched border edges", PMP::stitch_borders(m));

  // 5. Holes: every boundary cycle triangulated (minimum-weight, Delaunay-restricted).
  {
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
      // The minimum-weight search found nothing: a fan from the loop's centroid.
      K::Vector_3 c(0, 0, 0);
      std::size_t n = 0;
      for (auto g : CGAL::halfedges_around_face(h, m)) c = c + (m.point(m.target(g)) - CGAL::ORIGIN), ++n;
      CGAL::Euler::fill_hole(h, m);
      const auto centre = CGAL::Euler::add_center_vertex(h, m);
      m.point(m.target(centre)) = CGAL::ORIGIN + c / static_cast<double>(n);
      ++fanned, added += n;
    }
    step("filled holes", filled + fanned,
         "added " + std::to_string(added) + " triangles" +
             (fanned ? ", " + std::to_string(fanned) + " as fans from the centroid" : ""));
  }

  // 6. Degenerate triangles left by stitching or filling: collapsed.
  {
    std::size_t before = 0;
    for (auto f : m.faces()) before += PMP::is_degenerate_triangle_face(f, m);
    if (before > 0) {
      try {
        PMP::remove_degenerate_faces(m);
      } catch (const std::exception&) {
      }
      m.collect_garbage();
      std::size_t after = 0;
      for (auto f : m.faces()) after += PMP::is_degenerate_triangle_face(f, m);
      step("collapsed degenerate triangles", before - std::min(before, after));
    }
  }
  TriangleMesh current = to_triangles(m);

  // 7. Closed shells that enclose nothing (flat patches closed by the hole filling)
  //    dropped when other shells enclose a volume.
  MeshReport now = analyze_mesh(current);
  {
    std::vector<TriangleMesh> shells = connected_shells(current);
    double total = 0;
    std::vector<double> volumes;
    for (const auto& c : shells) total += std::abs(volumes.emplace_back(signed_volume(c)));
    std::size_t dropped = 0;
    TriangleMesh kept;
    for (std::size_t i = 0; i < shells.size(); ++i) {
      if (shells.size() > 1 && std::abs(volumes[i]) <= 1e-9 * total) ++dropped;
      else append(kept, shells[i]);
    }
    if (dropped > 0 && !kept.triangles.empty()) {
      step("dropped shells that enclose no volume", dropped);
      current = std::move(kept);
      now = analyze_mesh(current);
    }
  }

  // 7b. Shells nested in a shell of the same orientation (a volume covered twice): their
  //     union, which is the outer shell alone.
  if (now.nested_shells > 0) {
    const std::vector<TriangleMesh> shells = connected_shells(current);
    const std::vector<char> nested = nested_same_orientation(shells);
    TriangleMesh kept;
    std::size_t dropped = 0;
    for (std::size_t j = 0; j < shells.size(); ++j) {
      if (nested[j]) ++dropped;
      else append(kept, shells[j]);
    }
    const MeshReport check = analyze_mesh(kept);
    if (dropped > 0 && check.nested_shells == 0) {
      step("united nested shells of the same orientation (kept the outer)", dropped);
      current = std::move(kept);
      now = check;
    }
  }

  // Pinched vertices (two fans touching at a point, e.g. where a duplicate vertex was
  // merged): one vertex per fan, each moved 1e-3 of the way into its fan.
  if (now.closed && !now.manifold && now.nonmanifold_edges == 0) {
    TriangleMesh separated = current;
    const std::size_t pinched = separate_pinched_vertices(separated);
    const MeshReport check = analyze_mesh(separated);
    if (pinched > 0 && check.manifold && check.closed) {
      step("separated pinched vertices", pinched, "one vertex per fan, moved 1e-3 of the way into it");
      current = std::move(separated);
      now = check;
    }
  }

  // 8. Self-intersections. Shells that are solids each but overlap: their union,
  //    one exact corefinement at a time. Otherwise: autorefinement (exact
  //    constructions), the patches inside the volume removed, accepted only if it
  //    leaves a solid that keeps at least half the volume.
  if (now.self_intersections > 0 && now.closed) {
    TriangleMesh joined;
    std::size_t shells = 0;
    if (union_of_shells(current, joined, shells)) {
      const MeshReport check = analyze_mesh(joined);
      if (check.solid() && check.volume > 0) {
        step("resolved self-intersecting triangle pairs", now.self_intersections,
             "union of " + std::to_string(shells) + " overlapping shells");
        current = std::move(joined);
        now = check;
      }
    }
  }
  // CGAL's experimental autorefinement crashed on flat shells (a patch closed by its own
  // hole filling, two coplanar sheets) in CGAL 5.5: only volumes go there.
  const Point3 ext = now.box.hi - now.box.lo;
  const bool flat = !(std::abs(now.volume) > 1e-9 * ext.x * ext.y * ext.z) || has_repeated_triangle(current);
  if (now.self_intersections > 0 && now.closed && !flat) {
    ExactMesh em;
    to_mesh(current, em);
    try {
      const bool fixed = PMP::experimental::autorefine_and_remove_self_intersections(
          em, CGAL::parameters::visitor(DeadlineVisitor<ExactMesh>(kAutorefineSeconds)));
      em.collect_garbage();
      TriangleMesh refined = to_triangles(em);
      const MeshReport check = analyze_mesh(refined);
      if (fixed && check.self_intersections == 0 && check.closed &&
          std::abs(check.volume) >= 0.5 * std::abs(now.volume)) {
        step("resolved self-intersecting triangle pairs", now.self_intersections,
             "autorefined, inner patches removed");
        current = std::move(refined);
        now = check;
      }
    } catch (const std::exception&) {
      // Autorefinement gave up (or ran out of time): the report below says what remains.
    }
  }

  // Otherwise the winding-number solid (the region with winding number >= 1/2), when it
  // is a solid.
  if (now.self_intersections > 0 && now.closed && !flat) {
    WindingSolid ws = winding_number_solid(current, kAutorefineSeconds);
    if (ws.ok) {
      // Where the solid touches itself at a point (intersection curves crossing), the
      // pinched vertex is separated.
      MeshReport check = analyze_mesh(ws.mesh);
      std::size_t pinched = 0;
      if (check.closed && !check.manifold && check.nonmanifold_edges == 0) {
        pinched = separate_pinched_vertices(ws.mesh);
        check = analyze_mesh(ws.mesh);
      }
      if (check.solid() && check.volume > 0) {
        step("resolved self-intersecting triangle pairs", now.self_intersections,
             "winding-number solid: " + std::to_string(ws.kept + ws.reversed) + " of " +
                 std::to_string(ws.patches) + " patches kept" +
                 (ws.reversed ? " (" + std::to_string(ws.reversed) + " reversed)" : ""));
        step("separated pinched vertices", pinched);
        current = std::move(ws.mesh);
        now = check;
      }
    }
  }

  // 9. Every shell oriented so that the mesh bounds a volume (outer shells outward,
  //    cavities inward).
  if (now.closed && now.manifold && now.self_intersections == 0 && now.degenerate_triangles == 0) {
    Mesh o;
    to_mesh(current, o);
    const TriangleMesh before = to_triangles(o);
    PMP::orient_to_bound_a_volume(o);
    TriangleMesh oriented = to_triangles(o);
    std::size_t reversed = 0;
    for (std::size_t t = 0; t < oriented.triangles.size() && t < before.triangles.size(); ++t)
      reversed += same_cycle_reversed({oriented.triangles[t][0], oriented.triangles[t][1], oriented.triangles[t][2]},
                                      {before.triangles[t][0], before.triangles[t][1], before.triangles[t][2]});
    step("reversed triangles to bound a volume", reversed);
    current = std::move(oriented);
  }

  r.mesh = std::move(current);
  r.after = analyze_mesh(r.mesh);
  return r;
}

}  // namespace dtlab
