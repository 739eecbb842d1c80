#pragma once
// The checker, templated on the predicate backend (the library instantiates it
// with FilteredExact; tests may instantiate it with others). Stages, in order:
//   1. indices: four distinct vertices per tet, all in range;
//   2. orientation of every tet (inverted / flat);
//   3. facet table: no facet in three tets, the two tets of a facet on opposite sides;
//   4. insphere on every interior facet (non-delaunay), cospherical facets recorded;
//   5. boundary: closed 2-manifold, one component, every edge convex, Euler numbers;
//   6. global: one tet's vertices on the inner side of every boundary facet, and the
//      boundary wraps once around a point of that tet (oracle/check/hull_degree.hpp);
//   7. points: each input point a vertex or an exact duplicate of one;
//   8. exact volume enclosed by the boundary; optionally (volume_identity) also the
//      identity sum over tets == that volume, a cross-check implied by stage 3.
// Stage 6 and 8 rely on stages 2-5 being clean and are skipped otherwise. A report
// with no defect always has the single cover proven (else: `unproven`).
#include <algorithm>
#include <chrono>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "kernel/parallel_for.hpp"
#include "kernel/progress.hpp"
#include "oracle/check/boundary.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/exact_volume.hpp"
#include "oracle/check/facet_table.hpp"
#include "oracle/check/hull_degree.hpp"
#include "predicates/backend.hpp"

namespace dtlab {

namespace check_detail {

// Counts every defect, keeps the first witnesses of each kind, and writes vertex ids
// in the caller's numbering: `original[v]` when the checker runs on a renumbered copy
// (check.cpp), v itself when `original` is empty.
class Collector {
 public:
  Collector(CheckReport& r, std::size_t per_kind, std::span<const std::uint32_t> original)
      : r_(r), per_kind_(per_kind), original_(original) {}
  void add(DefectKind k, std::vector<std::uint32_t> tets, std::vector<std::uint32_t> vertices, int sign,
           std::string detail) {
    const auto i = static_cast<std::size_t>(k);
    if (r_.counts[i]++ < per_kind_) {
      for (auto& v : vertices) v = id(v);
      r_.defects.push_back({k, std::move(tets), std::move(vertices), sign, std::move(detail)});
    }
  }
  std::uint64_t count(DefectKind k) const { return r_.counts[static_cast<std::size_t>(k)]; }
  std::uint32_t id(std::uint32_t v) const { return original_.empty() ? v : original_[v]; }
  std::string name(std::uint32_t v) const { return std::to_string(id(v)); }

 private:
  CheckReport& r_;
  std::size_t per_kind_;
  std::span<const std::uint32_t> original_;
};

std::vector<std::uint32_t> tet_vertices(const Tet& k);
// Stage 7 (no predicates): missing points and duplicate vertices.
void check_points(const Tetrahedralization& t, const std::vector<char>& used, std::span<const std::uint32_t> reported,
                  Collector& out, CheckStats& stats);
// The affine hull of the points, exactly, with affinely independent input points that
// span it (points[0..dimension], the first ones in the array that do).
struct SpanWitness {
  AffineSpan span = AffineSpan::no_points;
  std::array<std::uint32_t, 4> points{};
};
SpanWitness affine_span(std::span<const Point3> pts);

// The numbered stages of check_tetrahedralization_with, each adding its defects to `out`.

// 1. indices: four distinct vertices per tet, all in range; marks the used vertices.
// False when some tet is broken (nothing else can then be checked).
inline bool check_indices(std::span<const Tet> T, std::size_t n, std::vector<char>& used, Collector& out) {
  if (T.size() >= (1u << 30)) throw std::length_error("check: more than 2^30 tets");
  if (n >= (1u << 31)) throw std::length_error("check: more than 2^31 points");
  bool indices_ok = true;
  for (std::size_t i = 0; i < T.size(); ++i) {
    const Tet& k = T[i];
    bool ok = true;
    for (int a = 0; a < 4; ++a) {
      if (k[a] >= n) ok = false;
      for (int b = a + 1; b < 4; ++b)
        if (k[a] == k[b]) ok = false;
    }
    if (!ok) {
      indices_ok = false;
      out.add(DefectKind::broken_adjacency, {static_cast<std::uint32_t>(i)}, tet_vertices(k), 0,
              "tet has a repeated or out-of-range vertex");
      continue;
    }
    for (auto v : k) used[v] = 1;
  }
  return indices_ok;
}

// 2. orientation: signs in parallel, witnesses collected in tet order.
template <PredicateBackend B>
std::vector<signed char> check_orientation(std::span<const Point3> P, std::span<const Tet> T, unsigned threads,
                                           const B& pred, Collector& out) {
  std::vector<signed char> sign(T.size());
  parallel_chunks(T.size(), threads, 1 << 14, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t i = b; i < e; ++i) {
      const Tet& k = T[i];
      sign[i] = static_cast<signed char>(pred.orient3d(P[k[0]], P[k[1]], P[k[2]], P[k[3]]));
    }
  });
  for (std::size_t i = 0; i < T.size(); ++i) {
    const int s = sign[i];
    if (s < 0)
      out.add(DefectKind::inverted, {static_cast<std::uint32_t>(i)}, tet_vertices(T[i]), s, "orient3d < 0");
    else if (s == 0)
      out.add(DefectKind::flat, {static_cast<std::uint32_t>(i)}, tet_vertices(T[i]), 0, "orient3d == 0");
  }
  return sign;
}

// 3. facet table, and 4. Delaunay: insphere on each facet shared by two positive
// tets, as the table finds it (no adjacency array is kept), on any worker; the
// non-Delaunay and cospherical ones are recorded in the table's order. Then the
// facets in three tets or more and the pairs on the same side of their facet.
template <PredicateBackend B>
FacetTable check_facets_and_delaunay(std::span<const Point3> P, std::span<const Tet> T,
                                     std::span<const std::uint32_t> rank, const std::vector<signed char>& sign,
                                     const CheckOptions& opt, const B& pred, CheckReport& report, Collector& out) {
  enum PairCode : int { kDelaunay = 0, kNonDelaunay = 1, kCospherical = 2 };
  auto positive_order = [](const FacetPair& f) {
    // A positive order of tet r1/4 from the facet's own data (no tet lookup).
    return std::array<std::uint32_t, 5>{f.odd1 ? f.v[1] : f.v[0], f.odd1 ? f.v[0] : f.v[1], f.v[2], f.apex1, f.apex2};
  };
  auto classify = [&](const FacetPair& f) -> int {
    if (sign[f.r1 / 4] <= 0 || sign[f.r2 / 4] <= 0) return kDelaunay;
    const auto k = positive_order(f);
    const int s = pred.insphere(P[k[0]], P[k[1]], P[k[2]], P[k[3]], P[k[4]]);
    return s > 0 ? kNonDelaunay : s == 0 ? kCospherical : kDelaunay;
  };
  auto record = [&](const FacetPair& f, int code) {
    const std::uint32_t t1 = f.r1 / 4, t2 = f.r2 / 4;
    const auto k = positive_order(f);
    if (code == kNonDelaunay)
      out.add(DefectKind::non_delaunay, {t1, t2}, {k[0], k[1], k[2], k[3], k[4]}, 1,
              "insphere(tet " + std::to_string(t1) + ", opposite vertex " + out.name(k[4]) + ") > 0");
    else
      report.cospherical_pairs.emplace_back(t1, t2);
  };
  FacetTable table = opt.delaunay ? build_facet_table(T, rank, classify, record, opt.threads)
                                  : build_facet_table(T, rank, {}, {}, opt.threads);
  CheckStats& st = report.stats;
  st.cospherical_facets = report.cospherical_pairs.size();
  st.interior_facets = table.interior;
  st.boundary_facets = table.boundary;
  for (const auto& refs : table.overshared) {
    // A witness names at most 16 of the tets (a facet may be shared by all of them).
    constexpr std::size_t kListed = 16;
    std::vector<std::uint32_t> tets;
    for (auto r : refs)
      if (tets.size() < kListed) tets.push_back(r / 4);
    const auto f = facet_vertices(T[refs[0] / 4], static_cast<int>(refs[0] % 4));
    out.add(DefectKind::broken_adjacency, std::move(tets), {f[0], f[1], f[2]}, 0,
            "facet shared by " + std::to_string(refs.size()) + " tets" +
                (refs.size() > kListed ? " (the first 16 listed)" : ""));
  }
  for (const auto& [r1, r2] : table.same_side) {
    const auto f = facet_vertices(T[r1 / 4], static_cast<int>(r1 % 4));
    out.add(DefectKind::overlap, {r1 / 4, r2 / 4}, {f[0], f[1], f[2], T[r1 / 4][r1 % 4], T[r2 / 4][r2 % 4]}, 0,
            "both tets lie on the same side of their shared facet");
  }
  return table;
}

// 5a. boundary surface: edges and vertices where it is no 2-manifold.
inline void check_boundary_manifold(const BoundarySurface& bs, Collector& out) {
  for (const auto& e : bs.bad_edges)
    out.add(DefectKind::broken_adjacency, {},
            out.id(e[0]) < out.id(e[1]) ? std::vector{e[0], e[1]} : std::vector{e[1], e[0]}, 0,
            "boundary edge not shared by exactly two boundary facets in opposite directions");
  for (auto v : bs.bad_vertices)
    out.add(DefectKind::broken_adjacency, {}, {v}, 0, "boundary is not a 2-manifold at this vertex");
}

// 5b. one component: every component but the largest is a gap (a cavity or a piece).
inline void check_boundary_components(const BoundarySurface& bs, Collector& out) {
  if (bs.components <= 1) return;
  // The component of facet 0 is the outer one when it holds the most facets.
  std::vector<std::uint64_t> size(bs.components, 0);
  for (auto c : bs.component) ++size[c];
  const auto outer = static_cast<std::uint32_t>(std::max_element(size.begin(), size.end()) - size.begin());
  std::vector<char> reported(bs.components, 0);
  for (std::size_t f = 0; f < bs.facets.size(); ++f) {
    const auto c = bs.component[f];
    if (c == outer || reported[c]) continue;
    reported[c] = 1;
    out.add(DefectKind::gap, {bs.tet_of[f]}, {bs.facets[f][0], bs.facets[f][1], bs.facets[f][2]}, 0,
            "boundary component " + std::to_string(c) + " of " + std::to_string(bs.components) + " (" +
                std::to_string(size[c]) + " facets): a cavity or a separate piece");
  }
}

// 5c. edge convexity: the apex of the facet across each edge is on the inner side
// of (or on) the facet's plane.
template <PredicateBackend B>
void check_edge_convexity(std::span<const Point3> P, const BoundarySurface& bs, const B& pred, Collector& out) {
  for (std::size_t f = 0; f < bs.facets.size(); ++f) {
    const auto& F = bs.facets[f];
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t g = bs.across[f][e];
      if (g == kNone || g < f) continue;
      const auto& G = bs.facets[g];
      std::uint32_t apex = G[0];
      for (auto v : G)
        if (v != F[e] && v != F[(e + 1) % 3]) apex = v;
      const int s = pred.orient3d(P[F[0]], P[F[1]], P[F[2]], P[apex]);
      if (s < 0)
        out.add(DefectKind::hull_not_convex, {bs.tet_of[f], bs.tet_of[g]}, {F[0], F[1], F[2], apex}, s,
                "reflex boundary edge (" + out.name(F[e]) + "," + out.name(F[(e + 1) % 3]) +
                    "): orient3d(facet, apex of neighbour facet) < 0");
    }
  }
}

// 5d. Euler numbers: a ball (V-E+F-T = 1) bounded by a sphere (V-E+F = 2), judged
// when the surface is locally sound and connected.
inline void check_euler(std::span<const Tet> T, std::span<const std::uint32_t> rank, const BoundarySurface& bs,
                        bool local_ok, unsigned threads, CheckStats& st, Collector& out) {
  st.edges = count_edges(T, rank, threads);
  const auto F = static_cast<std::int64_t>(st.interior_facets + st.boundary_facets);
  st.euler = static_cast<std::int64_t>(st.vertices) - static_cast<std::int64_t>(st.edges) + F -
             static_cast<std::int64_t>(T.size());
  st.boundary_euler = static_cast<std::int64_t>(bs.vertices) - static_cast<std::int64_t>(bs.edges) +
                      static_cast<std::int64_t>(bs.facets.size());
  if (local_ok && bs.components == 1) {
    if (st.boundary_euler != 2)
      out.add(DefectKind::euler, {}, {}, 0,
              "boundary V-E+F = " + std::to_string(st.boundary_euler) + ", expected 2 (a sphere)");
    if (st.euler != 1)
      out.add(DefectKind::euler, {}, {}, 0, "V-E+F-T = " + std::to_string(st.euler) + ", expected 1 (a ball)");
  }
}

// 6. global convexity and single covering: one tet's vertices on the inner side of
// every boundary facet, and the boundary's degree around a point of that tet.
template <PredicateBackend B>
void check_single_cover(std::span<const Point3> P, std::span<const Tet> T, const BoundarySurface& bs, const B& pred,
                        CheckStats& st, Collector& out) {
  if (bs.facets.empty()) {
    out.add(DefectKind::unproven, {}, {}, 0, "no boundary facets: the covering cannot be decided");
    return;
  }
  const std::uint32_t f0 = 0, t0 = bs.tet_of[f0];
  const Tet& k0 = T[t0];
  bool inside = true;
  for (std::size_t f = 0; f < bs.facets.size(); ++f) {
    const auto& G = bs.facets[f];
    for (auto v : k0) {
      const int s = pred.orient3d(P[G[0]], P[G[1]], P[G[2]], P[v]);
      if (s < 0) {
        inside = false;
        out.add(DefectKind::hull_not_convex, {bs.tet_of[f], t0}, {G[0], G[1], G[2], v}, s,
                "vertex " + out.name(v) + " lies outside the plane of a boundary facet");
      }
    }
  }
  if (!inside) return;
  const HullDegree deg = hull_degree(P, bs.facets, k0, f0);
  st.degree_checked = deg.decided;
  st.cover_proven = deg.decided && deg.crossed.size() == 1;
  if (!deg.decided) {
    out.add(DefectKind::unproven, {t0}, tet_vertices(k0), 0,
            "the covering degree of the boundary around tet " + std::to_string(t0) + " was not decided");
  } else if (deg.crossed.size() != 1) {
    std::vector<std::uint32_t> tets, verts;
    for (auto f : deg.crossed) {
      tets.push_back(bs.tet_of[f]);
      verts.insert(verts.end(), bs.facets[f].begin(), bs.facets[f].end());
    }
    out.add(DefectKind::overlap, std::move(tets), std::move(verts), 0,
            "a ray from inside tet " + std::to_string(t0) + " crosses " + std::to_string(deg.crossed.size()) +
                " boundary facets: the tets cover the hull " + std::to_string(deg.crossed.size()) + " times");
  }
}

// 8. volumes: the exact volume inside the boundary (the hull's, once the cover is
// proven); with opt.volume_identity also the exact sum over the tets, compared.
inline void check_volumes(std::span<const Point3> P, std::span<const Tet> T, const BoundarySurface& bs,
                          const CheckOptions& opt, CheckStats& st, Collector& out) {
  const VolumeSums v = exact_volume_sums(P, opt.volume_identity ? T : std::span<const Tet>{}, bs.facets);
  st.volume_hull = v.hull;
  if (opt.volume_identity) {
    st.volume_checked = true;
    st.volume_equal = v.equal;
    st.volume_tets = v.tets;
    if (!v.equal)
      out.add(v.tets > v.hull ? DefectKind::overlap : DefectKind::gap, {}, {}, 0,
              "exact sum of tet volumes differs from the exact volume inside the boundary");
  }
}

}  // namespace check_detail

// `original`: when not empty, t is a renumbering of the caller's tetrahedralization
// and original[v] is vertex v's id there (defects and their texts use those ids).
template <PredicateBackend B>
CheckReport check_tetrahedralization_with(const Tetrahedralization& t, const CheckOptions& opt, const B& pred,
                                          std::span<const std::uint32_t> original = {}) {
  using namespace check_detail;
  const auto start = std::chrono::steady_clock::now();
  CheckReport report;
  CheckStats& st = report.stats;
  Collector out(report, opt.witnesses_per_kind, original);
  const auto& P = t.points;
  const auto& T = t.tets;
  const std::size_t n = P.size();
  st.points = n;
  st.tets = T.size();
  auto finish = [&] {
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  };

  Progress* const progress = thread_progress();  // stage "check": the steps done, of 8
  progress_begin(progress, "check", 8);
  std::vector<char> used(n, 0);
  if (!check_indices(T, n, used, out)) return finish();
  progress_advance(progress, 1);
  st.vertices = static_cast<std::uint64_t>(std::count(used.begin(), used.end(), 1));
  if (T.empty()) {
    // Right only for an input that spans no volume (fewer than 4 points, or flat).
    const SpanWitness s = affine_span(P);
    st.input_span = s.span;
    if (s.span == AffineSpan::volume)
      out.add(DefectKind::gap, {}, {s.points[0], s.points[1], s.points[2], s.points[3]}, 1,
              "no tets, but these input points span a tetrahedron");
    return finish();
  }
  const std::vector<signed char> sign = check_orientation(P, T, opt.threads, pred, out);
  progress_advance(progress, 2);
  const std::vector<std::uint32_t> rank = first_appearance(T, n);
  const FacetTable table = check_facets_and_delaunay(P, T, rank, sign, opt, pred, report, out);
  progress_advance(progress, 4);

  const BoundarySurface bs = build_boundary(T, table, n);
  st.boundary_vertices = bs.vertices;
  st.boundary_edges = bs.edges;
  st.boundary_components = bs.components;
  check_boundary_manifold(bs, out);
  const bool local_ok = out.count(DefectKind::inverted) == 0 && out.count(DefectKind::flat) == 0 &&
                        out.count(DefectKind::broken_adjacency) == 0 && out.count(DefectKind::overlap) == 0;
  check_boundary_components(bs, out);
  check_edge_convexity(P, bs, pred, out);
  check_euler(T, rank, bs, local_ok, opt.threads, st, out);
  progress_advance(progress, 5);

  // Stage 6 runs whenever the surface is a closed, connected, locally convex
  // 2-manifold (non-Delaunay facets do not matter here).
  const bool surface_ok = local_ok && bs.components == 1 && out.count(DefectKind::hull_not_convex) == 0 &&
                          out.count(DefectKind::gap) == 0 && out.count(DefectKind::euler) == 0;
  if (surface_ok) check_single_cover(P, T, bs, pred, st, out);
  progress_advance(progress, 6);
  check_points(t, used, opt.duplicates, out, st);
  progress_advance(progress, 7);
  if (local_ok) check_volumes(P, T, bs, opt, st, out);
  // "valid" needs the single cover proven; no path may reach here without it.
  if (report.ok() && !st.cover_proven)
    out.add(DefectKind::unproven, {}, {}, 0, "the single cover of the hull was not proven");
  progress_advance(progress, 8);
  return finish();
}

}  // namespace dtlab
