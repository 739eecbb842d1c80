#pragma once
// check_combinatorics: the invariants of the tet mesh, checked over the whole mesh (as
// geogram's check_combinatorics). Debug builds run it after every flip when asked
// (BuildOptions::check_combinatorics or DTLAB_CHECK_COMBINATORICS=1, the inserter's
// `checked`); release builds compile that call out. The function itself is always
// there, for tests. The invariants:
//
//   records      a live tet has four distinct vertices, each a point id or the
//                infinite vertex, and no tet has the infinite vertex twice;
//   adjacency    adj(adj(f)) == f, the neighbour is live, and the two tets share the
//                three vertices of the facet (so their apexes are the two others);
//                no neighbour (kNoFacet) only on the outside of a bigtet;
//   facets       every facet (three vertices) belongs to exactly two live tets, or to
//                one on the outside of a bigtet: no third tet claims a shared facet;
//   orientation  no live tet is negative by the backend's sign (Geometry, with the
//                symbolic inner point for infinite tets); with `all_positive` none is
//                flat either (between insertions; a flip may leave flat tets that a
//                later flip of the same insertion removes).
//
// There is no vertex-to-tet map in the mesh to check (a walk starts at the last tet
// touched); the vertices are checked through the tets that hold them.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/facet_key.hpp"
#include "kernel/ids.hpp"
#include "predicates/sign.hpp"

namespace dtlab {

#if !defined(NDEBUG) || defined(DTLAB_MESH_CHECKS)
inline constexpr bool kMeshChecksCompiled = true;
#else
inline constexpr bool kMeshChecksCompiled = false;
#endif

namespace mesh_check_detail {

inline std::string where(std::uint32_t t, int f) {
  return "tet " + std::to_string(t) + (f < 0 ? "" : " facet " + std::to_string(f));
}

// Records: distinct vertices, each below `points` or the infinite vertex `inf`.
template <class Mesh>
std::string check_records(const Mesh& mesh, std::uint32_t points, std::uint32_t inf) {
  for (std::uint32_t t = 0; t < mesh.size(); ++t) {
    if (mesh.dead(t)) continue;
    const std::uint32_t* v = mesh.verts(t);
    for (int i = 0; i < 4; ++i) {
      if (v[i] >= points && v[i] != inf) return where(t, -1) + ": vertex " + std::to_string(v[i]) + " is no point";
      for (int j = i + 1; j < 4; ++j)
        if (v[i] == v[j]) return where(t, -1) + ": vertex " + std::to_string(v[i]) + " twice";
    }
  }
  return {};
}

// Adjacency: symmetric, onto live tets, across the same three vertices.
template <class Mesh>
std::string check_adjacency(const Mesh& mesh, bool outside_allowed) {
  for (std::uint32_t t = 0; t < mesh.size(); ++t) {
    if (mesh.dead(t)) continue;
    for (int f = 0; f < 4; ++f) {
      const Facet here(t, f), there = mesh.adj(here);
      if (there.none()) {
        if (!outside_allowed) return where(t, f) + ": no neighbour";
        continue;
      }
      if (there.tet() >= mesh.size() || mesh.dead(there.tet()))
        return where(t, f) + ": neighbour " + std::to_string(there.tet()) + " is not a live tet";
      if (mesh.adj(there) != here) return where(t, f) + ": adjacency not symmetric";
      if (!(facet_key(mesh.verts(t), f) == facet_key(mesh.verts(there.tet()), there.face())))
        return where(t, f) + ": neighbour " + std::to_string(there.tet()) + " across other vertices";
    }
  }
  return {};
}

// Facets: each set of three vertices on exactly two live tets (one with no neighbour).
template <class Mesh>
std::string check_facets(const Mesh& mesh) {
  struct Entry {
    FacetKey key;
    std::uint32_t t;
    int f;
  };
  std::vector<Entry> all;
  for (std::uint32_t t = 0; t < mesh.size(); ++t)
    if (!mesh.dead(t))
      for (int f = 0; f < 4; ++f) all.push_back({facet_key(mesh.verts(t), f), t, f});
  const auto less = [](const Entry& a, const Entry& b) {
    return std::lexicographical_compare(a.key.v, a.key.v + 3, b.key.v, b.key.v + 3);
  };
  std::sort(all.begin(), all.end(), less);
  for (std::size_t i = 0, j; i < all.size(); i = j) {
    for (j = i + 1; j < all.size() && all[j].key == all[i].key;) ++j;
    const std::size_t expected = mesh.adj(Facet(all[i].t, all[i].f)).none() ? 1 : 2;
    if (j - i != expected)
      return where(all[i].t, all[i].f) + ": its three vertices are a facet of " + std::to_string(j - i) + " tets";
  }
  return {};
}

// Orientation: no live tet negative; with all_positive none flat.
template <class Mesh, class Geo>
std::string check_orientation(const Mesh& mesh, Geo& geo, bool all_positive) {
  for (std::uint32_t t = 0; t < mesh.size(); ++t) {
    if (mesh.dead(t)) continue;
    const Sign s = geo.orientation(mesh.verts(t));
    if (s == Sign::negative) return where(t, -1) + ": negatively oriented";
    if (all_positive && s == Sign::zero) return where(t, -1) + ": flat";
  }
  return {};
}

}  // namespace mesh_check_detail

// The first broken invariant of the mesh (header), or "" when all hold. `points`: the
// number of point ids; geo: the build's Geometry (its infinite vertex, or kNone for a
// bigtet, whose outside is the only place without a neighbour).
template <class Mesh, class Geo>
std::string check_combinatorics(const Mesh& mesh, Geo& geo, std::uint32_t points, bool all_positive) {
  using namespace mesh_check_detail;
  const std::uint32_t inf = geo.infinite();
  std::string e = check_records(mesh, points, inf);
  if (e.empty()) e = check_adjacency(mesh, inf == kNone);
  if (e.empty()) e = check_facets(mesh);
  if (e.empty()) e = check_orientation(mesh, geo, all_positive);
  return e;
}

}  // namespace dtlab
