#pragma once
// Replace a few tets by others covering the same region, and glue the new ones to
// each other and to the outside, matching facets by their vertices. The inserter
// uses it for the rare flip 4-4 only (the 1-4, 2-3 and 3-2 flips write their
// adjacency out); start() uses facet_key too.
//
// The outer facets of the old tets (those whose neighbour is not old) keep their
// outside neighbours; each new facet either matches one of them (same three
// vertices) or is shared by two new tets. Flips touch at most 4 old and 4 new tets,
// so linear scans over a dozen facets beat any hashing.
#include <algorithm>
#include <array>
#include <cstdint>

#include "kernel/ids.hpp"
#include "kernel/tet_mesh.hpp"

namespace dtlab {

struct FacetKey {
  std::uint32_t v[3];
  bool operator==(const FacetKey&) const = default;
};

inline FacetKey facet_key(const std::uint32_t* tv, int f) {
  std::uint32_t a = tv[(f + 1) & 3], b = tv[(f + 2) & 3], c = tv[(f + 3) & 3];
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {{a, b, c}};
}

// Replaces old_tets[0..n_old) by new tets with vertices new_tets[0..n_new) (each
// positively oriented). Writes the new tet ids into out. Returns false if the facets
// did not match up (the mesh was inconsistent); the mesh is then left changed.
inline bool retriangulate(TetMesh& m, const std::uint32_t* old_tets, int n_old,
                          const std::array<std::uint32_t, 4>* new_tets, int n_new,
                          std::uint32_t* out) {
  FacetKey outer_key[16];
  std::uint32_t outer_adj[16];
  bool outer_used[16] = {};
  int n_outer = 0;
  for (int i = 0; i < n_old; ++i) {
    const std::uint32_t t = old_tets[i];
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t nb = m.adj(4 * t + f);
      bool internal = false;
      if (nb != kNone)
        for (int j = 0; j < n_old; ++j) internal |= (nb >> 2) == old_tets[j];
      if (internal) continue;
      outer_key[n_outer] = facet_key(m.verts(t), f);
      outer_adj[n_outer++] = nb;
    }
  }
  for (int i = 0; i < n_old; ++i) m.destroy(old_tets[i]);

  FacetKey inner_key[16];
  std::uint32_t inner_facet[16];
  bool inner_open[16];
  int n_inner = 0;
  for (int i = 0; i < n_new; ++i) {
    const auto& v = new_tets[i];
    out[i] = m.create(v[0], v[1], v[2], v[3]);
  }
  for (int i = 0; i < n_new; ++i) {
    const std::uint32_t t = out[i];
    for (int f = 0; f < 4; ++f) {
      const FacetKey key = facet_key(m.verts(t), f);
      bool done = false;
      for (int j = 0; j < n_outer && !done; ++j)
        if (!outer_used[j] && outer_key[j] == key) {
          m.link(4 * t + f, outer_adj[j]);
          outer_used[j] = done = true;
        }
      for (int j = 0; j < n_inner && !done; ++j)
        if (inner_open[j] && inner_key[j] == key) {
          m.link(4 * t + f, inner_facet[j]);
          inner_open[j] = false;
          done = true;
        }
      if (!done) {
        if (n_inner == 16) return false;
        inner_key[n_inner] = key;
        inner_facet[n_inner] = 4 * t + f;
        inner_open[n_inner++] = true;
      }
    }
  }
  for (int j = 0; j < n_outer; ++j)
    if (!outer_used[j]) return false;
  for (int j = 0; j < n_inner; ++j)
    if (inner_open[j]) return false;
  return true;
}

}  // namespace dtlab
