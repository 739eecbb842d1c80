#pragma once
// A small, slow, obviously-right validity check for kernel tests (the full exact
// checker lives in oracle/): positive orientation, every facet shared by at most two
// tets with the boundary a closed surface, every interior facet locally Delaunay,
// every non-duplicate point a vertex. All signs from the exact backend.
#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "kernel/build.hpp"
#include "predicates/exact.hpp"

namespace dtlab::test {

inline std::string validate(const BuildResult& r) {
  const auto& P = r.mesh.points;
  ExactPredicates ex;
  std::map<std::array<std::uint32_t, 3>, std::vector<std::pair<std::uint32_t, std::uint32_t>>> facets;
  std::set<std::uint32_t> verts;
  for (std::uint32_t t = 0; t < r.mesh.tets.size(); ++t) {
    const auto& k = r.mesh.tets[t];
    if (ex.orient3d(P[k[0]], P[k[1]], P[k[2]], P[k[3]]) <= 0) return "tet " + std::to_string(t) + " not positive";
    for (int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> key = {k[(f + 1) & 3], k[(f + 2) & 3], k[(f + 3) & 3]};
      std::sort(key.begin(), key.end());
      facets[key].push_back({t, k[f]});
      verts.insert(k[f]);
    }
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> boundary_edges;
  for (auto& [key, users] : facets) {
    if (users.size() > 2) return "facet shared by more than two tets";
    if (users.size() == 2) {
      const auto& k = r.mesh.tets[users[0].first];
      if (ex.insphere(P[k[0]], P[k[1]], P[k[2]], P[k[3]], P[users[1].second]) > 0)
        return "non-delaunay facet";
    } else {
      for (int i = 0; i < 3; ++i)
        ++boundary_edges[{std::min(key[i], key[(i + 1) % 3]), std::max(key[i], key[(i + 1) % 3])}];
    }
  }
  for (auto& [e, c] : boundary_edges)
    if (c != 2) return "boundary is not a closed surface";
  std::set<std::uint32_t> dups(r.duplicates.begin(), r.duplicates.end());
  for (std::uint32_t i = 0; i < P.size(); ++i)
    if (!verts.count(i) && !dups.count(i)) return "point " + std::to_string(i) + " missing";
  for (std::uint32_t d : r.duplicates)
    if (verts.count(d)) return "duplicate " + std::to_string(d) + " is a vertex";
  return "";
}

}  // namespace dtlab::test
