#pragma once
// Bounding-volume hierarchy over the triangles of a mesh: flat node array in
// depth-first order (left child = node + 1), median split on the longest axis of the
// triangle centroids, at most kLeafSize triangles per leaf.
#include <cstdint>
#include <vector>

#include "kernel/ids.hpp"
#include "sampling/triangle_geometry.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct BvhNode {
  Box3 box;
  std::uint32_t first = 0;  // leaf: first slot in Bvh::order()
  std::uint32_t count = 0;  // leaf: triangle count; 0 for an inner node
  std::uint32_t right = 0;  // inner: right child (left child is this node + 1)
  bool leaf() const { return count > 0; }
};

struct ClosestHit {
  std::uint32_t triangle = kNone;  // kNone when the mesh is empty
  Point3 point{0, 0, 0};
  TriFeature feature = TriFeature::face;
  double distance2 = INFINITY;
};

class Bvh {
 public:
  static constexpr std::uint32_t kLeafSize = 4;

  // Keeps a reference to `mesh`, which must outlive the hierarchy.
  explicit Bvh(const TriangleMesh& mesh);

  const TriangleMesh& mesh() const { return *mesh_; }
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& order() const { return order_; }

  ClosestHit closest_point(const Point3& q) const;

  // Calls hit(triangle, t) for every triangle that ray o + t d meets with 0 <= t <= t_max.
  template <class F>
  void for_each_ray_hit(const Point3& o, const Point3& d, double t_max, F&& hit) const;

  // Calls pair(s, t) once for every pair s < t of distinct triangles whose boxes overlap.
  template <class F>
  void for_each_overlapping_pair(F&& pair) const;

 private:
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::vector<Point3>& centroids);
  bool ray_hits_box(const Box3& b, const Point3& o, const Point3& inv_d, double t_max) const;

  const TriangleMesh* mesh_;
  std::vector<BvhNode> nodes_;
  std::vector<std::uint32_t> order_;
  std::vector<Box3> tri_boxes_;
};

template <class F>
void Bvh::for_each_ray_hit(const Point3& o, const Point3& d, double t_max, F&& hit) const {
  if (nodes_.empty()) return;
  const Point3 inv{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& n = nodes_[stack[--top]];
    if (!ray_hits_box(n.box, o, inv, t_max)) continue;
    if (n.leaf()) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const std::uint32_t t = order_[i];
        const double s = ray_triangle(o, d, mesh_->corner(t, 0), mesh_->corner(t, 1), mesh_->corner(t, 2));
        if (s >= 0 && s <= t_max) hit(t, s);
      }
    } else {
      stack[top++] = n.right;
      stack[top++] = static_cast<std::uint32_t>(&n - nodes_.data()) + 1;
    }
  }
}

template <class F>
void Bvh::for_each_overlapping_pair(F&& pair) const {
  if (nodes_.empty()) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    auto [a, b] = stack.back();
    stack.pop_back();
    const BvhNode& na = nodes_[a];
    const BvhNode& nb = nodes_[b];
    if (a != b && !na.box.overlaps(nb.box)) continue;
    if (na.leaf() && nb.leaf()) {
      for (std::uint32_t i = na.first; i < na.first + na.count; ++i)
        for (std::uint32_t j = (a == b ? i + 1 : nb.first); j < nb.first + nb.count; ++j) {
          const std::uint32_t s = order_[i], t = order_[j];
          if (tri_boxes_[s].overlaps(tri_boxes_[t])) pair(std::min(s, t), std::max(s, t));
        }
    } else if (a == b) {
      // Pairs inside one inner node: within each child, and across the two.
      stack.push_back({a + 1, a + 1});
      stack.push_back({na.right, na.right});
      stack.push_back({a + 1, na.right});
    } else if (nb.leaf() || (!na.leaf() && na.box.half_area() >= nb.box.half_area())) {
      stack.push_back({a + 1, b});
      stack.push_back({na.right, b});
    } else {
      stack.push_back({a, b + 1});
      stack.push_back({a, nb.right});
    }
  }
}

}  // namespace dtlab
