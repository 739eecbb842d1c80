#pragma once
// Generalized winding number of a triangle soup (Jacobson et al. 2013): the sum of
// the signed solid angles of the triangles over 4 pi. 1 inside and 0 outside a
// closed outward-oriented mesh; on meshes with holes it degrades smoothly, so
// thresholding at 1/2 still classifies well.
#include <cmath>
#include <cstdint>
#include <vector>

#include "sampling/bvh.hpp"

namespace dtlab {

// Brute-force sum over every triangle: no approximation.
double winding_number_exact(const TriangleMesh& mesh, const Point3& q);

// Barill et al. 2018: far from a BVH node (distance > beta * node radius) its
// triangles are replaced by the Taylor expansion of the dipole field at their
// area-weighted centroid, up to first-order terms; near nodes are summed exactly.
class FastWindingNumber {
 public:
  // order 0 keeps only the dipole sum N; order 1 adds the first-order moments M.
  explicit FastWindingNumber(const Bvh& bvh, double beta = 2.0, int order = 1);
  double operator()(const Point3& q) const;
  // |w| > 1/2, so that a mesh oriented inward throughout (w = -1 inside) works too.
  bool inside(const Point3& q) const { return std::abs((*this)(q)) > 0.5; }
  double beta() const { return beta_; }
  const TriangleMesh& mesh() const { return bvh_.mesh(); }

 private:
  // Far-field data of one node, in single precision: one 64-byte cache line. The
  // approximation error (about 1e-3) dwarfs the rounding of floats.
  struct alignas(64) FarField {
    float center[3];  // area-weighted centroid of the node's triangles
    float radius2;    // squared distance from center to the farthest corner in the node
    float normal[3];  // N = sum of A_i n_i
    float trace;      // trace of M
    float m[6];       // symmetric part of M = sum A_i n_i (c_i - center)^T: xx yy zz xy yz zx
    // The tree, copied here so that a query touches one cache line per node: for a
    // leaf, its first slot in the leaf order and its triangle count; for an inner
    // node, its right child (the left one is the next node) and 0.
    std::uint32_t link;
    std::uint32_t count;
  };
  const Bvh& bvh_;
  double beta2_, beta_;
  int order_;
  std::vector<FarField> far_;
  std::vector<Point3> corners_;  // three per triangle, in BVH leaf order
};

// Classifies q[i] as inside (|winding number| > 1/2) for every point, in parallel.
// Reproducible: each answer depends on its point only.
std::vector<char> inside_flags(const FastWindingNumber& w, const std::vector<Point3>& q);

// The reference classifier for quality checks: the tree evaluation with a strict
// beta, re-done exactly (brute force) wherever it lands within `margin` of 1/2.
std::vector<char> inside_flags_robust(const Bvh& bvh, const std::vector<Point3>& q, double margin = 0.2);

}  // namespace dtlab
