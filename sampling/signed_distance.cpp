#include "sampling/signed_distance.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/ids.hpp"

namespace dtlab {

namespace {
Point3 unit(const Point3& v) {
  const double l = norm(v);
  return l > 0 ? (1.0 / l) * v : Point3{0, 0, 0};
}
double angle(const Point3& u, const Point3& v) { return std::atan2(norm(cross(u, v)), dot(u, v)); }
}  // namespace

SignedDistance::SignedDistance(const Bvh& bvh) : bvh_(bvh) {
  const TriangleMesh& m = bvh.mesh();
  const std::size_t nt = m.triangles.size();
  face_.resize(nt);
  edge_.assign(3 * nt, Point3{0, 0, 0});
  vertex_.assign(m.vertices.size(), Point3{0, 0, 0});
  struct Use {
    std::uint32_t lo, hi, slot;
  };
  std::vector<Use> uses;
  uses.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t) {
    face_[t] = unit(m.area_normal(t));
    for (int k = 0; k < 3; ++k) {
      const Point3& p = m.corner(t, k);
      vertex_[m.triangles[t][k]] += angle(m.corner(t, (k + 1) % 3) - p, m.corner(t, (k + 2) % 3) - p) * face_[t];
      const std::uint32_t u = m.triangles[t][k], v = m.triangles[t][(k + 1) % 3];
      uses.push_back({std::min(u, v), std::max(u, v), static_cast<std::uint32_t>(3 * t + k)});
    }
  }
  // Edge pseudonormal: the sum of the normals of every face using the edge.
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) { return a.lo != b.lo ? a.lo < b.lo : a.hi < b.hi; });
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    Point3 sum{0, 0, 0};
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) sum += face_[uses[j++].slot / 3];
    for (std::size_t k = i; k < j; ++k) edge_[uses[k].slot] = sum;
    i = j;
  }
}

double SignedDistance::operator()(const Point3& q) const {
  const ClosestHit h = bvh_.closest_point(q);
  if (h.triangle == kNone) return INFINITY;
  const auto& tri = bvh_.mesh().triangles[h.triangle];
  Point3 n{0, 0, 0};
  switch (h.feature) {
    case TriFeature::face: n = face_[h.triangle]; break;
    case TriFeature::vertex_a: n = vertex_[tri[0]]; break;
    case TriFeature::vertex_b: n = vertex_[tri[1]]; break;
    case TriFeature::vertex_c: n = vertex_[tri[2]]; break;
    case TriFeature::edge_ab: n = edge_[3 * h.triangle]; break;
    case TriFeature::edge_bc: n = edge_[3 * h.triangle + 1]; break;
    case TriFeature::edge_ca: n = edge_[3 * h.triangle + 2]; break;
  }
  const double d = std::sqrt(h.distance2);
  return dot(q - h.point, n) < 0 ? -d : d;
}

}  // namespace dtlab
