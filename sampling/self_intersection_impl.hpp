#pragma once
// Implementation of self_intersection.hpp (templates on the predicate backend).
#include <array>

namespace dtlab::detail {

// Sign of the 2D orientation of the projections of a, b, c onto the plane that drops
// coordinate `drop`, through the backend: the projections, lifted to z = 0 against the
// apex (0, 0, 1), give orient2d = -orient3d (the coordinates are copied, not rounded).
template <class P>
int orient2d_dropping(const Point3& a, const Point3& b, const Point3& c, int drop, const P& pred) {
  auto lift = [drop](const Point3& p) {
    return Point3{drop == 0 ? p.y : p.x, drop == 2 ? p.y : p.z, 0.0};
  };
  return -pred.orient3d(lift(a), lift(b), lift(c), Point3{0, 0, 1});
}

// Closed segments pq and ab in the plane intersect (collinear overlap included).
template <class P>
bool segments_meet_2d(const Point3& p, const Point3& q, const Point3& a, const Point3& b, int drop, const P& pred) {
  const int o1 = orient2d_dropping(p, q, a, drop, pred), o2 = orient2d_dropping(p, q, b, drop, pred);
  const int o3 = orient2d_dropping(a, b, p, drop, pred), o4 = orient2d_dropping(a, b, q, drop, pred);
  if (o1 * o2 > 0 || o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
  // All four collinear: compare intervals on the projected axes (exact comparisons).
  auto u = [drop](const Point3& x) { return drop == 0 ? x.y : x.x; };
  auto v = [drop](const Point3& x) { return drop == 2 ? x.y : x.z; };
  auto overlap = [](double a0, double a1, double b0, double b1) {
    return std::max(std::min(a0, a1), std::min(b0, b1)) <= std::min(std::max(a0, a1), std::max(b0, b1));
  };
  return overlap(u(p), u(q), u(a), u(b)) && overlap(v(p), v(q), v(a), v(b));
}

template <class P>
bool point_in_triangle_2d(const Point3& p, const Point3& a, const Point3& b, const Point3& c, int drop, const P& pred) {
  const int s1 = orient2d_dropping(a, b, p, drop, pred), s2 = orient2d_dropping(b, c, p, drop, pred),
            s3 = orient2d_dropping(c, a, p, drop, pred);
  return !((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0));
}

// Are a, b, c collinear (or repeated)? Exact: all three coordinate projections are flat.
template <class P>
bool collinear(const Point3& a, const Point3& b, const Point3& c, const P& pred) {
  for (int drop = 0; drop < 3; ++drop)
    if (orient2d_dropping(a, b, c, drop, pred) != 0) return false;
  return true;
}

inline int dominant_axis(const Point3& n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

// Does closed segment pq meet closed triangle abc? Coplanar configurations return
// false here; the caller handles coplanar triangle pairs separately.
template <class P>
bool segment_meets_triangle(const Point3& p, const Point3& q, const Point3& a, const Point3& b,
                            const Point3& c, const P& pred) {
  const int sp = pred.orient3d(a, b, c, p), sq = pred.orient3d(a, b, c, q);
  if (sp == sq) return false;  // same side, or both in the plane (coplanar case)
  const int o1 = pred.orient3d(p, q, a, b), o2 = pred.orient3d(p, q, b, c), o3 = pred.orient3d(p, q, c, a);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

}  // namespace dtlab::detail

namespace dtlab {

template <PredicateBackend P>
bool triangles_intersect(const TriangleMesh& mesh, std::uint32_t s, std::uint32_t t, const P& pred) {
  const auto& ts = mesh.triangles[s];
  const auto& tt = mesh.triangles[t];
  auto repeats = [](const std::array<std::uint32_t, 3>& x) { return x[0] == x[1] || x[1] == x[2] || x[2] == x[0]; };
  if (repeats(ts) || repeats(tt)) return false;  // index-degenerate: reported elsewhere
  const auto& W = mesh.vertices;
  if (detail::collinear(W[ts[0]], W[ts[1]], W[ts[2]], pred) || detail::collinear(W[tt[0]], W[tt[1]], W[tt[2]], pred))
    return false;  // zero-area: reported as degenerate
  // Rotate both triangles so that their shared vertices come first, in the same order.
  std::array<std::uint32_t, 3> a = ts, b = tt;
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ts[i] == tt[j]) {
        std::swap(a[shared], a[static_cast<std::size_t>(std::find(a.begin(), a.end(), ts[i]) - a.begin())]);
        std::swap(b[shared], b[static_cast<std::size_t>(std::find(b.begin(), b.end(), tt[j]) - b.begin())]);
        ++shared;
      }
  const auto& V = mesh.vertices;
  const Point3 &a0 = V[a[0]], &a1 = V[a[1]], &a2 = V[a[2]];
  const Point3 &b0 = V[b[0]], &b1 = V[b[1]], &b2 = V[b[2]];
  if (shared == 3) return true;  // the same triangle twice
  const bool coplanar = pred.orient3d(a0, a1, a2, b0) == 0 && pred.orient3d(a0, a1, a2, b1) == 0 &&
                        pred.orient3d(a0, a1, a2, b2) == 0;
  if (coplanar) {
    // Project along the dominant normal axis; the rounded normal only suggests it, so
    // fall back to any axis whose projection of the triangle is not flat (exact).
    int drop = detail::dominant_axis(cross(a1 - a0, a2 - a0));
    for (int k = 0; k < 3 && detail::orient2d_dropping(a0, a1, a2, drop, pred) == 0; ++k) drop = k;
    if (shared == 2) {
      // Folded onto each other iff the two free corners lie on the same side of the shared edge.
      return detail::orient2d_dropping(a0, a1, a2, drop, pred) * detail::orient2d_dropping(a0, a1, b2, drop, pred) > 0;
    }
    if (shared == 1) {
      // Overlap beyond the common corner: a free edge crosses the other triangle's edges,
      // or one triangle's free corner lies inside the other.
      return detail::segments_meet_2d(a1, a2, b0, b1, drop, pred) || detail::segments_meet_2d(a1, a2, b0, b2, drop, pred) ||
             detail::segments_meet_2d(b1, b2, a0, a1, drop, pred) || detail::segments_meet_2d(b1, b2, a0, a2, drop, pred) ||
             detail::segments_meet_2d(a1, a2, b1, b2, drop, pred) ||
             detail::point_in_triangle_2d(a1, b0, b1, b2, drop, pred) ||
             detail::point_in_triangle_2d(b1, a0, a1, a2, drop, pred);
    }
    const std::array<const Point3*, 3> A{&a0, &a1, &a2}, B{&b0, &b1, &b2};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (detail::segments_meet_2d(*A[i], *A[(i + 1) % 3], *B[j], *B[(j + 1) % 3], drop, pred)) return true;
    return detail::point_in_triangle_2d(a0, b0, b1, b2, drop, pred) || detail::point_in_triangle_2d(b0, a0, a1, a2, drop, pred);
  }
  if (shared == 2) return false;  // two planes through a common edge meet only on it
  if (shared == 1) {
    // Beyond the common corner a0 = b0: the free edge of one must cross the other.
    return detail::segment_meets_triangle(a1, a2, b0, b1, b2, pred) ||
           detail::segment_meets_triangle(b1, b2, a0, a1, a2, pred);
  }
  return detail::segment_meets_triangle(a0, a1, b0, b1, b2, pred) ||
         detail::segment_meets_triangle(a1, a2, b0, b1, b2, pred) ||
         detail::segment_meets_triangle(a2, a0, b0, b1, b2, pred) ||
         detail::segment_meets_triangle(b0, b1, a0, a1, a2, pred) ||
         detail::segment_meets_triangle(b1, b2, a0, a1, a2, pred) ||
         detail::segment_meets_triangle(b2, b0, a0, a1, a2, pred);
}

template <PredicateBackend P>
std::uint64_t count_self_intersections(const Bvh& bvh, const P& pred, std::uint64_t limit) {
  std::uint64_t count = 0;
  bvh.for_each_overlapping_pair([&](std::uint32_t s, std::uint32_t t) {
    if (count < limit && triangles_intersect(bvh.mesh(), s, t, pred)) ++count;
  });
  return count;
}

}  // namespace dtlab
