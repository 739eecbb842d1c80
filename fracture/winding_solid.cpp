// Autorefinement (CGAL) and the patch classification by the fast winding number
// (sampling/winding_number).
#include "fracture/winding_solid.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include "fracture/deadline_visitor.hpp"
#include "fracture/surface_mesh_convert.hpp"
#include "kernel/ids.hpp"
#include "sampling/bvh.hpp"
#include "sampling/winding_number.hpp"

namespace PMP = CGAL::Polygon_mesh_processing;

namespace dtlab {

namespace {
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<EK::Point_3>;

struct ExactLess {
  bool operator()(const EK::Point_3& a, const EK::Point_3& b) const {
    return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
  }
};

struct DisjointSets {
  std::vector<std::uint32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Which side of triangle t of `m` lies in the solid: +1 the side behind it (keep as
// is), -1 the side in front (keep reversed), 0 both or neither (drop), 2 undecided (the
// winding numbers just off the triangle are not near integers, or it is a sliver).
// `sign` -1 for a mesh oriented inward (winding number -1 inside).
int classify(const TriangleMesh& m, std::size_t t, const FastWindingNumber& w, double sign, double min_offset) {
  const Point3 n2 = m.area_normal(t);
  const double area2 = norm(n2);
  const Point3 &a = m.corner(t, 0), &b = m.corner(t, 1), &c = m.corner(t, 2);
  const double longest = std::sqrt(std::max({norm2(b - a), norm2(c - b), norm2(a - c)}));
  if (!(area2 > 0) || longest <= 0) return 2;
  const double altitude = area2 / longest;  // the smallest one
  const double offset = 1e-3 * altitude;
  if (offset < min_offset) return 2;
  const Point3 centre = (1.0 / 3) * (a + b + c);
  const Point3 step = (offset / area2) * n2;
  const double front = sign * w(centre + step), behind = sign * w(centre - step);
  const double rf = std::round(front), rb = std::round(behind);
  if (std::abs(front - rf) > 0.1 || std::abs(behind - rb) > 0.1) return 2;
  const bool in_front = rf >= 1, in_behind = rb >= 1;
  if (in_front == in_behind) return 0;
  return in_behind ? 1 : -1;
}

// The refined faces over vertices merged by exact equality (the two sheets of a
// self-intersection curve get the same vertices).
TriangleMesh merged_faces(const ExactMesh& em) {
  std::map<EK::Point_3, std::uint32_t, ExactLess> index;
  TriangleMesh refined;
  for (auto f : em.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(em.halfedge(f), em)) {
      if (k == 3) break;
      const auto& p = em.point(v);
      const auto [it, fresh] = index.emplace(p, static_cast<std::uint32_t>(refined.vertices.size()));
      if (fresh)
        refined.vertices.push_back({surface_mesh_convert::coordinate(p.x()), surface_mesh_convert::coordinate(p.y()),
                                    surface_mesh_convert::coordinate(p.z())});
      t[k++] = it->second;
    }
    if (k == 3 && t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) refined.triangles.push_back(t);
  }
  return refined;
}

// Patches: faces joined across edges that have exactly two faces, by root face.
std::map<std::uint32_t, std::vector<std::uint32_t>> patches_of(const TriangleMesh& refined) {
  const std::size_t nt = refined.triangles.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;
  edges.reserve(3 * nt);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const auto [u, v] = std::minmax(refined.triangles[t][k], refined.triangles[t][(k + 1) % 3]);
      edges.emplace_back((std::uint64_t{u} << 32) | v, t);
    }
  std::sort(edges.begin(), edges.end());
  DisjointSets sets(nt);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    if (j - i == 2) sets.join(edges[i].second, edges[i + 1].second);
    i = j;
  }
  std::map<std::uint32_t, std::vector<std::uint32_t>> patches;
  for (std::uint32_t t = 0; t < nt; ++t) patches[sets.find(t)].push_back(t);
  return patches;
}

// Each patch classified by its largest faces (majority of up to three decided ones):
// side[t] = 1 kept, -1 kept reversed, 0 dropped. False (out.why set) when a patch
// could not be classified.
bool classify_patches(const TriangleMesh& mesh, const TriangleMesh& refined,
                      std::map<std::uint32_t, std::vector<std::uint32_t>>& patches, std::vector<int>& side,
                      WindingSolid& out) {
  const Bvh bvh(mesh);
  const FastWindingNumber w(bvh);
  const Box3 box = bounding_box(mesh);
  const double min_offset = 1e-13 * norm(box.hi - box.lo);
  const double sign = signed_volume(mesh) < 0 ? -1 : 1;
  side.assign(refined.triangles.size(), 0);
  for (auto& [root, faces] : patches) {
    std::sort(faces.begin(), faces.end(),
              [&](std::uint32_t a, std::uint32_t b) { return refined.triangle_area(a) > refined.triangle_area(b); });
    int votes[3] = {0, 0, 0};  // -1, 0, +1
    int decided = 0;
    for (std::size_t i = 0; i < faces.size() && i < 16 && decided < 3; ++i) {
      const int s = classify(refined, faces[i], w, sign, min_offset);
      if (s == 2) continue;
      ++votes[s + 1], ++decided;
    }
    if (decided == 0) {
      out.why = "a patch of " + std::to_string(faces.size()) + " triangles could not be classified";
      return false;
    }
    const int s = votes[2] >= votes[0] && votes[2] >= votes[1] ? 1 : votes[0] >= votes[1] ? -1 : 0;
    out.kept += s == 1, out.reversed += s == -1;
    for (auto t : faces) side[t] = s;
  }
  return true;
}

// Kept faces into out.mesh, reversed where needed; a face kept twice at the same place
// (coincident sheets) stays once if both face the same way, and goes if they face each
// other.
void keep_faces(const TriangleMesh& refined, const std::vector<int>& side, WindingSolid& out) {
  std::map<std::array<std::uint32_t, 3>, std::vector<std::array<std::uint32_t, 3>>> by_corners;
  for (std::uint32_t t = 0; t < refined.triangles.size(); ++t) {
    if (side[t] == 0) continue;
    auto tri = refined.triangles[t];
    if (side[t] < 0) std::swap(tri[1], tri[2]);
    auto key = tri;
    std::sort(key.begin(), key.end());
    by_corners[key].push_back(tri);
  }
  std::vector<std::uint32_t> id(refined.vertices.size(), kNone);
  for (const auto& [key, tris] : by_corners) {
    const auto same = [&](const std::array<std::uint32_t, 3>& a) {
      for (int s = 0; s < 3; ++s)
        if (a[0] == tris[0][s] && a[1] == tris[0][(s + 1) % 3]) return true;
      return false;
    };
    if (!std::all_of(tris.begin(), tris.end(), same)) continue;
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      auto& v = id[tris[0][k]];
      if (v == kNone) {
        v = static_cast<std::uint32_t>(out.mesh.vertices.size());
        out.mesh.vertices.push_back(refined.vertices[tris[0][k]]);
      }
      t[k] = v;
    }
    out.mesh.triangles.push_back(t);
  }
}

}  // namespace

WindingSolid winding_number_solid(const TriangleMesh& mesh, double seconds) {
  WindingSolid out;
  ExactMesh em;
  surface_mesh_convert::to_mesh(mesh, em);
  if (em.number_of_faces() != mesh.triangles.size()) {
    out.why = "not an oriented surface";
    return out;
  }
  try {
    PMP::experimental::autorefine(em, CGAL::parameters::visitor(DeadlineVisitor<ExactMesh>(seconds)));
  } catch (const BooleanTimeout&) {
    out.why = "autorefinement exceeded its time budget of " + std::to_string(static_cast<int>(seconds)) + " s";
    return out;
  } catch (const std::exception& e) {
    out.why = std::string("autorefinement failed: ") + e.what();
    return out;
  }
  const TriangleMesh refined = merged_faces(em);
  auto patches = patches_of(refined);
  out.patches = patches.size();
  std::vector<int> side;
  if (!classify_patches(mesh, refined, patches, side, out)) return out;
  keep_faces(refined, side, out);
  out.ok = !out.mesh.triangles.empty();
  if (!out.ok) out.why = "no patch bounds the region of winding number >= 1/2";
  return out;
}

}  // namespace dtlab
