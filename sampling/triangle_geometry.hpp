#pragma once
// Point-triangle and ray-triangle geometry in floating point, for the samplers.
#include "sampling/box3.hpp"

namespace dtlab {

// Which feature of triangle abc holds the closest point: the pseudonormal used for the
// sign of the distance depends on it.
enum class TriFeature : unsigned char { face, vertex_a, vertex_b, vertex_c, edge_ab, edge_bc, edge_ca };

struct ClosestOnTriangle {
  Point3 point;
  TriFeature feature;
};

// Closest point of triangle abc to p, classified by the Voronoi region of p
// (barycentric tests on the dot products of the edge vectors).
inline ClosestOnTriangle closest_on_triangle(const Point3& p, const Point3& a, const Point3& b,
                                             const Point3& c) {
  const Point3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {a, TriFeature::vertex_a};
  const Point3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {b, TriFeature::vertex_b};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {a + t * ab, TriFeature::edge_ab};
  }
  const Point3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {c, TriFeature::vertex_c};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {a + t * ac, TriFeature::edge_ca};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + t * (c - b), TriFeature::edge_bc};
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) return {a, TriFeature::vertex_a};  // degenerate triangle
  const double v = vb / denom, w = vc / denom;
  return {a + v * ab + w * ac, TriFeature::face};
}

// Parameter t of the hit of ray o + t d with triangle abc (Moller-Trumbore, no
// culling: both sides hit), or a negative value when the ray misses. This is the
// plain floating-point test the thesis's ray method uses: a ray through an edge may
// count the hit twice or not at all.
inline double ray_triangle(const Point3& o, const Point3& d, const Point3& a, const Point3& b,
                           const Point3& c) {
  const Point3 e1 = b - a, e2 = c - a;
  const Point3 h = cross(d, e2);
  const double det = dot(e1, h);
  if (det == 0) return -1;
  const double inv = 1.0 / det;
  const Point3 s = o - a;
  const double u = inv * dot(s, h);
  if (u < 0 || u > 1) return -1;
  const Point3 q = cross(s, e1);
  const double v = inv * dot(d, q);
  if (v < 0 || u + v > 1) return -1;
  const double t = inv * dot(e2, q);
  return t >= 0 ? t : -1;
}

// Signed solid angle of triangle abc seen from q, over 4 pi: its contribution to the
// winding number (Van Oosterom and Strackee's formula, tan(omega/2) = det / denom).
// Positive when q sees abc clockwise, i.e. q is behind an outward-facing triangle.
inline double triangle_winding(const Point3& q, const Point3& a, const Point3& b, const Point3& c) {
  const Point3 qa = a - q, qb = b - q, qc = c - q;
  const double la = norm(qa), lb = norm(qb), lc = norm(qc);
  const double det = dot(qa, cross(qb, qc));
  const double den = la * lb * lc + dot(qa, qb) * lc + dot(qb, qc) * la + dot(qc, qa) * lb;
  return std::atan2(det, den) * (0.5 / 3.14159265358979323846);
}

}  // namespace dtlab
