#pragma once
// A certified double-precision filter in front of the vertex test's long double
// solve (cell_geometry.cpp): for a vertex on exactly three planes it bounds from above
// the distance the long double solve would compute, so that a vertex certified to lie
// no farther than the largest distance already measured (and within the tolerance)
// needs no long double work: the reported numbers stay those of the long double path,
// bit for bit. The bound and its derivation: vertex_filter.cpp.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/box.hpp"

namespace dtlab {

// A face plane n . (x - site) = c in doubles, as the long double path builds it
// (bisector: n = q - site, c = n.n / 2; wall of axis k: n = e_k, c = wall - site_k),
// with the rounded norm of n. `ok`: finite and in the range where the bound holds.
struct FilterPlane {
  double n[3];
  double c;
  double norm;
  bool ok;
};

// The plane of the face with neighbour `tag` (a site id, or -1..-6 for the walls of
// `box`) relative to `site`; false when the tag is no site and no wall.
bool filter_plane(std::int32_t tag, std::span<const Point3> sites, const Point3& site, const vor::Box& box,
                  FilterPlane& out);

// Where planes a, b, d meet (relative to their site), in doubles: x, and per
// coordinate a bound on its error against the exact point (the planes of the exact
// inputs). False when the bound does not hold or the planes are too ill-conditioned
// for it (then the exact point may not even exist). det: |det(n_a, n_b, n_d)|
// rounded, det_error its error bound (at most det / 1024, so the exact det is not 0),
// norms: the product of the planes' norms.
struct PlanesMeet {
  double x[3], error[3];
  double det, det_error, norms;
};
bool planes_meet(const FilterPlane& a, const FilterPlane& b, const FilterPlane& d, PlanesMeet& out);

// An upper bound on the distance (max norm) that the long double solve of the three
// planes a, b, d (in that order) gives for vertex p of the cell of `site`, valid when
// that solve also finds the triple well-conditioned (`decided`); the bound is returned
// only when both are certain, else a negative value (the caller then runs the solve).
double vertex_distance_bound(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b,
                             const FilterPlane& d);

// vertex_distance_bound for many vertices at once: the lanes are stored field by field
// and bounds() runs them through one loop, several lanes per instruction (SSE2, or
// AVX2 where the machine has it), each lane bit for bit vertex_distance_bound's value.
class BoundBatch {
 public:
  // Empties the batch, with room for `lanes` lanes (no allocation once it is large enough).
  void start(std::size_t lanes);
  // A lane, when there is room (false: the batch is full).
  bool add(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b, const FilterPlane& d);
  std::size_t size() const { return size_; }
  // out[k]: the bound of the k-th lane added (out holds at least size() values).
  void bounds(std::span<double> out) const;

 private:
  static constexpr int count_ = 16;  // a, b, d normals (9), offsets (3), norms, p - site (3)
  std::vector<double> data_;         // field f of lane k at f * room_ + k
  std::size_t room_ = 0, size_ = 0;
};

// Inline: called per vertex. The norms' product as planes_meet forms it ((a b) d).
inline bool BoundBatch::add(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b,
                            const FilterPlane& d) {
  if (size_ == room_) return false;
  double* f = data_.data() + size_++;
  const std::size_t r = room_;
  for (int j = 0; j < 3; ++j) f[j * r] = a.n[j], f[(3 + j) * r] = b.n[j], f[(6 + j) * r] = d.n[j];
  f[9 * r] = a.c, f[10 * r] = b.c, f[11 * r] = d.c;
  f[12 * r] = a.ok && b.ok && d.ok ? a.norm * b.norm * d.norm : NAN;  // a plane not ok: NaN fails every test
  f[13 * r] = p.x - site.x, f[14 * r] = p.y - site.y, f[15 * r] = p.z - site.z;
  return true;
}

}  // namespace dtlab
