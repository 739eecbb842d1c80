#pragma once
// The truth about a (mutated) tetrahedralization, decided without the checker: plain
// GMP rational arithmetic, brute force, and CGAL's Delaunay tetrahedralization of the
// same points as the reference. M is the Delaunay tetrahedralization of P iff
//   1. its tets have four distinct in-range vertices, no two vertices share
//      coordinates, and every input point has the coordinates of a vertex;
//   2. every tet is positive (exact orient3d);
//   3. every tet's vertices lie in one cell of the Delaunay complex (CGAL's tets
//      merged across exactly cospherical facets): its circumsphere is empty;
//   4. in each cell, M's tets have the cell's exact volume and pairwise disjoint
//      interiors (separating-axis test, exact), so they tile the cell;
//   5. every triangle of M is in two tets, or in one and on a supporting plane of P.
// 3-5 make M a face-to-face tiling of the hull by empty-sphere tets.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "kernel/ids.hpp"
#include "kernel/tetrahedralization.hpp"

namespace dtlab::test {

struct Truth {
  bool valid = false;
  std::string why;  // the first failed condition
};

namespace truth_detail {

using Q3 = std::array<mpq_class, 3>;

inline Q3 sub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// 6 x signed volume, Shewchuk's sign convention: det [a-d; b-d; c-d].
inline mpq_class orient(const Q3& a, const Q3& b, const Q3& c, const Q3& d) {
  return dot(sub(a, d), cross(sub(b, d), sub(c, d)));
}

// > 0 iff e is inside the sphere through a, b, c, d when orient(a,b,c,d) > 0.
inline int insphere(const Q3& a, const Q3& b, const Q3& c, const Q3& d, const Q3& e) {
  const Q3 r[4] = {sub(a, e), sub(b, e), sub(c, e), sub(d, e)};
  mpq_class lift[4];
  for (int i = 0; i < 4; ++i) lift[i] = dot(r[i], r[i]);
  // Expand along the lift column: sum (-1)^i lift_i * det(rows without i).
  mpq_class det = 0;
  for (int i = 0; i < 4; ++i) {
    Q3 m[3];
    for (int j = 0, k = 0; j < 4; ++j)
      if (j != i) m[k++] = r[j];
    const mpq_class minor = dot(m[0], cross(m[1], m[2]));
    det += (i % 2 == 0 ? -1 : 1) * lift[i] * minor;
  }
  return sgn(det);
}

// Closed tets a and b (vertex coordinates) have disjoint interiors iff a plane
// separates them weakly; for two tetrahedra it can be taken normal to a face of
// one or to an edge of each.
inline bool interiors_disjoint(const std::array<Q3, 4>& a, const std::array<Q3, 4>& b) {
  std::vector<Q3> axes;
  auto faces = [&](const std::array<Q3, 4>& t) {
    for (int i = 0; i < 4; ++i) {
      const Q3& p = t[(i + 1) % 4];
      axes.push_back(cross(sub(t[(i + 2) % 4], p), sub(t[(i + 3) % 4], p)));
    }
  };
  faces(a);
  faces(b);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = k + 1; l < 4; ++l) axes.push_back(cross(sub(a[j], a[i]), sub(b[l], b[k])));
  for (const Q3& n : axes) {
    if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) continue;
    mpq_class amin = dot(n, a[0]), amax = amin, bmin = dot(n, b[0]), bmax = bmin;
    for (int i = 1; i < 4; ++i) {
      const mpq_class x = dot(n, a[i]), y = dot(n, b[i]);
      amin = std::min(amin, x), amax = std::max(amax, x);
      bmin = std::min(bmin, y), bmax = std::max(bmax, y);
    }
    if (amax <= bmin || bmax <= amin) return true;
  }
  return false;
}

inline std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace truth_detail

// `dt` is a Delaunay tetrahedralization of the same points from another program (CGAL).
inline Truth delaunay_truth(const std::vector<Point3>& P, const std::vector<Tet>& tets, const std::vector<Tet>& dt) {
  using namespace truth_detail;
  const std::size_t n = P.size();
  std::vector<Q3> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = {mpq_class(P[i].x), mpq_class(P[i].y), mpq_class(P[i].z)};
  // Canonical id: the smallest index with the same coordinates.
  std::vector<std::uint32_t> canon(n);
  {
    std::map<std::array<double, 3>, std::uint32_t> first;
    for (std::uint32_t i = 0; i < n; ++i) canon[i] = first.emplace(std::array{P[i].x, P[i].y, P[i].z}, i).first->second;
  }
  // 1. indices, duplicate vertices, missing points
  std::vector<std::uint32_t> vertex_of(n, kNone);  // canonical id -> the vertex id using it
  for (const Tet& k : tets)
    for (int a = 0; a < 4; ++a) {
      if (k[a] >= n) return {false, "vertex out of range"};
      for (int b = a + 1; b < 4; ++b)
        if (k[a] == k[b]) return {false, "repeated vertex"};
      auto& v = vertex_of[canon[k[a]]];
      if (v != kNone && v != k[a]) return {false, "two vertices with the same coordinates"};
      v = k[a];
    }
  if (dt.empty()) return tets.empty() ? Truth{true, ""} : Truth{false, "tets for a flat input"};
  for (std::size_t i = 0; i < n; ++i)
    if (vertex_of[canon[i]] == kNone) return {false, "input point is no vertex"};
  auto C = [&](const Tet& k) { return Tet{canon[k[0]], canon[k[1]], canon[k[2]], canon[k[3]]}; };
  // 2. orientation
  for (const Tet& k : tets)
    if (sgn(orient(q[k[0]], q[k[1]], q[k[2]], q[k[3]])) <= 0) return {false, "tet not positive"};
  // Cells of the reference: its tets merged across cospherical facets.
  std::vector<std::uint32_t> parent(dt.size());
  std::iota(parent.begin(), parent.end(), 0u);
  {
    std::map<std::array<std::uint32_t, 3>, std::vector<std::uint32_t>> facets;
    for (std::uint32_t t = 0; t < dt.size(); ++t) {
      const Tet k = C(dt[t]);
      for (int f = 0; f < 4; ++f) {
        std::array<std::uint32_t, 3> key = {k[(f + 1) % 4], k[(f + 2) % 4], k[(f + 3) % 4]};
        std::sort(key.begin(), key.end());
        facets[key].push_back(t);
      }
    }
    for (const auto& [key, ts] : facets) {
      if (ts.size() != 2) continue;
      const Tet k = C(dt[ts[0]]), o = C(dt[ts[1]]);
      std::uint32_t apex = o[0];
      for (auto v : o)
        if (v != key[0] && v != key[1] && v != key[2]) apex = v;
      if (insphere(q[k[0]], q[k[1]], q[k[2]], q[k[3]], q[apex]) == 0) parent[find(parent, ts[0])] = find(parent, ts[1]);
    }
  }
  std::map<std::uint32_t, std::set<std::uint32_t>> cell_vertices;
  std::map<std::uint32_t, mpq_class> cell_volume;
  for (std::uint32_t t = 0; t < dt.size(); ++t) {
    const Tet k = C(dt[t]);
    const std::uint32_t c = find(parent, t);
    cell_vertices[c].insert(k.begin(), k.end());
    cell_volume[c] += orient(q[k[0]], q[k[1]], q[k[2]], q[k[3]]);
  }
  std::vector<std::vector<std::uint32_t>> cells_of(n);
  for (const auto& [c, vs] : cell_vertices)
    for (auto v : vs) cells_of[v].push_back(c);
  // 3. each tet inside one cell; 4. cells tiled
  std::map<std::uint32_t, std::vector<std::uint32_t>> members;
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    const Tet k = C(tets[t]);
    std::uint32_t cell = kNone;
    for (auto c : cells_of[k[0]]) {
      const auto& vs = cell_vertices[c];
      if (vs.count(k[1]) && vs.count(k[2]) && vs.count(k[3])) cell = c;
    }
    if (cell == kNone) return {false, "tet with a non-empty circumsphere"};
    members[cell].push_back(t);
  }
  for (const auto& [c, vol] : cell_volume) {
    mpq_class sum = 0;
    const auto& ts = members[c];
    std::vector<std::array<Q3, 4>> corners;
    for (auto t : ts) {
      const Tet& k = tets[t];
      sum += orient(q[k[0]], q[k[1]], q[k[2]], q[k[3]]);
      corners.push_back({q[k[0]], q[k[1]], q[k[2]], q[k[3]]});
    }
    if (sum != vol) return {false, "a Delaunay cell's volume is not covered exactly"};
    for (std::size_t i = 0; i < corners.size(); ++i)
      for (std::size_t j = i + 1; j < corners.size(); ++j)
        if (!interiors_disjoint(corners[i], corners[j])) return {false, "two tets overlap"};
  }
  // 5. face to face
  std::map<std::array<std::uint32_t, 3>, std::vector<std::pair<std::uint32_t, int>>> tris;
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      const Tet& k = tets[t];
      std::array<std::uint32_t, 3> key = {k[(f + 1) % 4], k[(f + 2) % 4], k[(f + 3) % 4]};
      std::sort(key.begin(), key.end());
      tris[key].push_back({t, f});
    }
  for (const auto& [key, users] : tris) {
    if (users.size() == 2) continue;
    if (users.size() > 2) return {false, "a triangle in three tets"};
    const Tet& k = tets[users[0].first];
    const std::uint32_t apex = k[users[0].second];
    const int inner = sgn(orient(q[key[0]], q[key[1]], q[key[2]], q[apex]));
    for (std::size_t i = 0; i < n; ++i)
      if (sgn(orient(q[key[0]], q[key[1]], q[key[2]], q[i])) == -inner)
        return {false, "an unmatched triangle inside the hull"};
  }
  return {true, ""};
}

}  // namespace dtlab::test
