#include "sampling/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace dtlab {

Bvh::Bvh(const TriangleMesh& mesh) : mesh_(&mesh) {
  const auto n = static_cast<std::uint32_t>(mesh.triangles.size());
  if (n == 0) return;
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  tri_boxes_.resize(n);
  std::vector<Point3> centroids(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    for (int k = 0; k < 3; ++k) tri_boxes_[t].add(mesh.corner(t, k));
    centroids[t] = tri_boxes_[t].center();
  }
  nodes_.reserve(2 * n / kLeafSize + 2);
  build(0, n, centroids);
}

std::uint32_t Bvh::build(std::uint32_t begin, std::uint32_t end, std::vector<Point3>& centroids) {
  const auto id = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Box3 box, cbox;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.add(tri_boxes_[order_[i]]);
    cbox.add(centroids[order_[i]]);
  }
  nodes_[id].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[id].first = begin;
    nodes_[id].count = end - begin;
    return id;
  }
  const int axis = cbox.longest_axis();
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t s, std::uint32_t t) {
                     return coord(centroids[s], axis) < coord(centroids[t], axis);
                   });
  build(begin, mid, centroids);
  const std::uint32_t right = build(mid, end, centroids);
  nodes_[id].right = right;
  return id;
}

bool Bvh::ray_hits_box(const Box3& b, const Point3& o, const Point3& inv, double t_max) const {
  // Slab test; NaN from 0 * inf (ray in a slab's plane) is dropped by std::min/max order.
  double t0 = 0, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    const double ta = (coord(b.lo, k) - coord(o, k)) * coord(inv, k);
    const double tb = (coord(b.hi, k) - coord(o, k)) * coord(inv, k);
    const double lo = std::min(ta, tb), hi = std::max(ta, tb);
    if (lo > t0) t0 = lo;
    if (hi < t1) t1 = hi;
  }
  // Slightly widened so that rays grazing a box face are not lost to rounding.
  return t0 <= t1 * (1 + 1e-12) + 1e-300;
}

ClosestHit Bvh::closest_point(const Point3& q) const {
  ClosestHit best;
  if (nodes_.empty()) return best;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t id = stack[--top];
    const BvhNode& n = nodes_[id];
    if (n.box.distance2(q) >= best.distance2) continue;
    if (n.leaf()) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const std::uint32_t t = order_[i];
        const auto c = closest_on_triangle(q, mesh_->corner(t, 0), mesh_->corner(t, 1), mesh_->corner(t, 2));
        const double d2 = norm2(c.point - q);
        if (d2 < best.distance2) best = {t, c.point, c.feature, d2};
      }
      continue;
    }
    // Push the farther child first so the nearer one is searched first.
    const std::uint32_t l = id + 1, r = n.right;
    const double dl = nodes_[l].box.distance2(q), dr = nodes_[r].box.distance2(q);
    if (dl <= dr) {
      stack[top++] = r;
      stack[top++] = l;
    } else {
      stack[top++] = l;
      stack[top++] = r;
    }
  }
  return best;
}

}  // namespace dtlab
