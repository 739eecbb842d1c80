#pragma once
// build_delaunay for one backend: insertion order, the starting tetrahedron, the
// boundary (infinite vertex or big enclosing tetrahedron), the insertion loop and
// the compaction of the result. Instantiated once per backend in build.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "kernel/build.hpp"
#include "kernel/enclosing_tet.hpp"
#include "kernel/inserter.hpp"
#include "kernel/spatial_order.hpp"

namespace dtlab {

namespace detail {

template <PredicateBackend B>
bool collinear(const B& pred, const Point3& a, const Point3& b, const Point3& c) {
  // Collinear iff all three coordinate projections are (orient3d on zeroed copies).
  const auto proj = [&](auto get) {
    return pred.orient3d(get(a), get(b), get(c), Point3{0, 0, 1});
  };
  return proj([](const Point3& p) { return Point3{p.x, p.y, 0}; }) == 0 &&
         proj([](const Point3& p) { return Point3{p.y, p.z, 0}; }) == 0 &&
         proj([](const Point3& p) { return Point3{p.z, p.x, 0}; }) == 0;
}

inline void compact(const TetMesh& m, std::uint32_t n, Tetrahedralization& out) {
  out.tets.clear();
  for (std::uint32_t t = 0; t < m.size(); ++t) {
    if (m.dead(t)) continue;
    const std::uint32_t* v = m.verts(t);
    if (v[0] >= n || v[1] >= n || v[2] >= n || v[3] >= n) continue;
    out.tets.push_back({v[0], v[1], v[2], v[3]});
  }
}

}  // namespace detail

template <PredicateBackend B>
BuildResult build_with(std::span<const Point3> input, const B& pred, const BuildOptions& opt) {
  BuildResult res;
  const auto n = static_cast<std::uint32_t>(input.size());
  std::vector<std::uint32_t> order;
  if (opt.order == InsertionOrder::brio) {
    order = brio_order(input, opt.seed);
  } else {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
  }
  auto lower_dimensional = [&](const char* why) {
    res.failure = BuildFailure{FailureKind::lower_dimensional, -1, why};
    res.skipped = order;
    std::sort(res.skipped.begin(), res.skipped.end());
    res.mesh.points.assign(input.begin(), input.end());
    return res;
  };

  std::vector<Point3> pts;
  pts.reserve(input.size() + 4);  // room for the infinite vertex or the bigtet corners
  pts.assign(input.begin(), input.end());
  std::uint32_t inf = Inserter<B>::kNoVertex;
  std::uint32_t first[4];
  // The first four affinely independent points in insertion order (either boundary:
  // a lower-dimensional input has no Delaunay tetrahedralization).
  std::size_t k = 0;
  const auto next = [&](auto accept) {
    for (; k < order.size(); ++k)
      if (accept(input[order[k]])) return true;
    return false;
  };
  if (n < 4) return lower_dimensional("fewer than 4 points");
  first[0] = order[0];
  k = 1;
  const Point3 a = input[first[0]];
  if (!next([&](const Point3& q) { return !(q == a); })) return lower_dimensional("all points coincide");
  first[1] = order[k++];
  const Point3 b = input[first[1]];
  if (!next([&](const Point3& q) { return !detail::collinear(pred, a, b, q); }))
    return lower_dimensional("all points are collinear");
  first[2] = order[k++];
  const Point3 c = input[first[2]];
  if (!next([&](const Point3& q) { return pred.orient3d(a, b, c, q) != 0; }))
    return lower_dimensional("all points are coplanar");
  first[3] = order[k];
  if (opt.boundary == Boundary::infinite) {
    if (pred.orient3d(a, b, c, input[first[3]]) < 0) std::swap(first[0], first[1]);
    pts.push_back(a);  // the infinite vertex's slot: its coordinates are never read
    inf = n;
  } else {
    // The thesis's big enclosing tetrahedron, proven to hold every point (exactly).
    const EnclosingTet big = enclosing_tet(input, opt.bigtet_factor);
    if (!big.valid()) {
      res.failure = BuildFailure{FailureKind::outside_boundary, -1, big.defect};
      res.skipped = order;
      std::sort(res.skipped.begin(), res.skipped.end());
      res.mesh.points.assign(input.begin(), input.end());
      return res;
    }
    for (const Point3& q : big.corners) pts.push_back(q);
    first[0] = n, first[1] = n + 1, first[2] = n + 2, first[3] = n + 3;
    if (pred.orient3d(pts[n], pts[n + 1], pts[n + 2], pts[n + 3]) < 0) std::swap(first[0], first[1]);
  }

  Inserter<B> ins(pts, pred, inf, opt.seed);
  ins.reserve(n);
  ins.start(first[0], first[1], first[2], first[3]);
  const auto t0 = std::chrono::steady_clock::now();
  const bool infinite = opt.boundary == Boundary::infinite;
  if (infinite) ins.stats().inserted = 4;
  std::vector<char> is_first(infinite ? n : 0, 0);
  if (infinite)
    for (std::uint32_t v : first) is_first[v] = 1;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t p = order[k];
    if (infinite && is_first[p]) continue;
    const auto outcome = ins.insert(p);
    if (outcome == Inserter<B>::Outcome::duplicate) {
      res.duplicates.push_back(p);
    } else if (outcome == Inserter<B>::Outcome::failed) {
      res.failure = BuildFailure{ins.failure(), p, ins.failure_detail()};
      for (std::size_t j = k; j < order.size(); ++j)
        if (!(infinite && is_first[order[j]])) res.skipped.push_back(order[j]);
      std::sort(res.skipped.begin(), res.skipped.end());
      break;
    }
  }
  res.stats = ins.stats();
  res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.stats.orient3d_calls = ins.geometry().orient_calls;
  res.stats.insphere_calls = ins.geometry().insphere_calls;
  res.peak_tets = ins.mesh().size();
  std::sort(res.duplicates.begin(), res.duplicates.end());
  ins.release_adjacency();  // the output needs only the vertices: lower the peak memory
  detail::compact(ins.mesh(), n, res.mesh);
  pts.resize(n);
  res.mesh.points = std::move(pts);
  return res;
}

}  // namespace dtlab
