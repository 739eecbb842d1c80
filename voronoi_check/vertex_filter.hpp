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
// with the rounded norm of n (NaN when not ok, so that a product of norms is NaN too).
// `ok`: finite and in the range where the bound holds.
struct FilterPlane {
  double n[3];
  double c;
  double norm;
  bool ok;
};

// The bisector of `site` and site q (filter_plane's plane for a site's tag); inline, as
// tet_spheres builds three per tet. Only for files compiled with -ffp-contract=off (the
// bound counts one rounding per operation: a fused n.n would not be the long double
// path's sum).
inline void bisector_plane(const Point3& q, const Point3& site, FilterPlane& out) {
  out.n[0] = q.x - site.x, out.n[1] = q.y - site.y, out.n[2] = q.z - site.z;
  const double nn = (out.n[0] * out.n[0] + out.n[1] * out.n[1]) + out.n[2] * out.n[2];
  out.c = nn / 2;
  out.ok = nn >= 0x1p-1000 && nn <= 0x1p1000;
  out.norm = out.ok ? std::sqrt(nn) : NAN;
}

// The plane of the face with neighbour `tag` (a site id, or -1..-6 for the walls of
// `box`) relative to `site`; false when the tag is no site and no wall.
bool filter_plane(std::int32_t tag, std::span<const Point3> sites, const Point3& site, const vor::Box& box,
                  FilterPlane& out);

// filter_plane for every face of a cell: out[f] and found[f] (its return value) for the
// neighbour tags[f]; one call per cell.
void filter_planes(std::span<const std::int32_t> tags, std::span<const Point3> sites, const Point3& site,
                   const vor::Box& box, FilterPlane* out, char* found);

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

// What the bound reads of one vertex, in one layout for vertex_distance_bound and for
// BoundBatch's lanes: the three normals, their offsets, the product of the norms as
// planes_meet forms it ((a b) d; NaN when a plane is not ok, which fails every test of
// the bound) and p - site.
struct BoundInputs {
  static constexpr int kFields = 16;
  static constexpr int kPlaneFields = 13;  // the planes' (0-12): all that planes_meet reads
  double f[kFields];  // a.n (0-2), b.n (3-5), d.n (6-8), a.c, b.c, d.c (9-11), norms (12), p - site (13-15)
};

// The fields of BoundInputs for one vertex, each given to put(field, value): the one
// place the layout is written, for a BoundInputs and for a BoundBatch lane alike.
template <class Put>
[[gnu::always_inline]] inline void put_bound_inputs(const Point3& p, const Point3& site, const FilterPlane& a,
                                                    const FilterPlane& b, const FilterPlane& d, Put&& put) {
  for (int j = 0; j < 3; ++j) put(j, a.n[j]), put(3 + j, b.n[j]), put(6 + j, d.n[j]);
  put(9, a.c), put(10, b.c), put(11, d.c);
  put(12, a.norm * b.norm * d.norm);  // NaN when a plane is not ok
  put(13, p.x - site.x), put(14, p.y - site.y), put(15, p.z - site.z);
}

inline BoundInputs bound_inputs(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b,
                                const FilterPlane& d) {
  BoundInputs in;
  put_bound_inputs(p, site, a, b, d, [&](int j, double v) { in.f[j] = v; });
  return in;
}

// vertex_distance_bound (or planes_meet) for many vertices at once: the lanes are stored
// field by field and bounds() (meets()) runs them through one loop, several lanes per
// instruction (SSE2, or AVX2 where the machine has it), each lane bit for bit the scalar
// function's value.
class BoundBatch {
 public:
  // The lanes a batch holds: fixed, so that a lane's fields lie at constant offsets
  // (one store each in add; 32 KB of fields, of which a cell's few lanes touch a few KB).
  static constexpr std::size_t kLanes = 256;
  BoundBatch() : data_(BoundInputs::kFields * kLanes) {}
  // Empties the batch.
  void start() { size_ = 0; }
  // A lane, when there is room (false: the batch is full).
  bool add(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b, const FilterPlane& d);
  std::size_t size() const { return size_; }
  // out[k]: the bound of the k-th lane added (out holds at least size() values).
  void bounds(std::span<double> out) const;
  // out[k] and found[k]: planes_meet of the k-th lane's planes and its return value, bit
  // for bit (the lane's point is not read; out and found hold at least size() values).
  void meets(std::span<PlanesMeet> out, std::span<char> found) const;

 private:
  // f[j]: the first lane's field j.
  void fields(const double* (&f)[BoundInputs::kFields]) const;
  std::vector<double> data_;  // field j of lane k at j * kLanes + k
  std::size_t size_ = 0;
};

// Inline: called per vertex.
inline bool BoundBatch::add(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b,
                            const FilterPlane& d) {
  if (size_ == kLanes) return false;
  double* lane = data_.data() + size_++;
  put_bound_inputs(p, site, a, b, d, [&](int j, double v) { lane[j * kLanes] = v; });
  return true;
}

}  // namespace dtlab
