#pragma once
// A convex polyhedron stored as polygons over a shared vertex array, built by
// clipping a box with half-spaces: the one geometric engine of the Voronoi cells.
//
// A clip by the half-space n.x <= c classifies each vertex by d = n.x - c with a
// tolerance band |d| <= tol*|n| ("on"). Only vertices strictly outside are removed
// and only edges with one end strictly inside and one strictly outside get a new
// vertex, so no new vertex lies within the band of an old one: a plane through an
// existing vertex, edge or face (cospherical inputs: lattices) reuses it instead of
// making a zero-length edge. A clip with no vertex strictly outside changes nothing.
// The new face is chained from the polygon edges that lie on the plane (each such
// edge a->b of a kept face contributes b->a), so the result stays closed.
//
// A band decision can be wrong: a vertex at 1e-12 from the plane, exactly outside,
// kept as "on" loses a whole face of a close pair of sites. So clip() also bounds
// each vertex's distance to the exact vertex and flags the cell ambiguous() when a
// vertex lies within band plus error of a plane: the caller then recomputes it
// exactly (voronoi/exact_cell.hpp), which drives the same topology through
// clip_signs() with exact signs. A vertex of reset()'s box and its clips is the meet
// of three known planes (walls, clip planes), so its bound comes from its residuals
// to them (meet_error, not compounded over the cuts); a vertex on a face of assign()'s
// polytope (planes unknown) grows its ends' bound by how obliquely the edge meets the
// plane.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "voronoi/box.hpp"

namespace dtlab::vor {

// A clip plane n.x <= c, within a few roundings of an exact one: a box wall moved by
// the site (c = hi - s rounded once), or the bisector of two double sites, n = p - s
// and c = |n|^2 / 2 rounded as computed in doubles.
struct ClipPlane {
  Point3 n;
  double c = 0;
};
// A bound on |fl(n.x - c) - (n*.x - c*)| at a double point x, (n*, c*) the exact plane.
double plane_error(const ClipPlane& p, const Point3& x);
// A bound on the distance from x to the common point of the exact planes near p, q
// and r, from x's residuals to them; infinite when they nearly fail to meet in a point.
double meet_error(const ClipPlane& p, const ClipPlane& q, const ClipPlane& r, const Point3& x);
// A bound on |fl(n.x - c) - (n*.x* - c*)| for a double x within err of x*: the sign of
// fl(n.x - c) is x*'s exact side of the exact plane when its magnitude is larger.
double side_error(const ClipPlane& p, const Point3& x, double err);

class ConvexCell {
 public:
  // The box as a cell; face tags -1..-6 for the walls x-lo, x-hi, y-lo, y-hi, z-lo, z-hi
  // (voro++'s numbering, negative so they never clash with a neighbour id).
  void reset(const Box& box);
  // A given convex polytope (faces counter-clockwise from outside, offsets as in
  // VoronoiCell), every vertex moved by -origin; to be clipped further.
  void assign(std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
              std::span<const std::uint32_t> face_vertices, std::span<const std::int32_t> tags,
              const Point3& origin);

  // Keeps the part with n.x <= c (a ClipPlane); the new face gets `tag`. Returns true
  // if it cut.
  bool clip(const Point3& n, double c, std::int32_t tag, double tol);
  // The same clip with each vertex's side given (-1 in, 0 on, 1 out; exact callers).
  // New vertices are provisional midpoints, to be placed with set_vertex.
  bool clip_signs(std::span<const signed char> side, std::int32_t tag);
  // Some clip since reset/assign decided a side within its band or error bound.
  bool ambiguous() const { return ambiguous_; }
  // After a clip that cut: the old vertex vertex v was (kNone for a new one) and, for a
  // new one, the tags of the two faces whose edge it cut.
  std::uint32_t kept_from(std::size_t v) const { return vs_[v].from; }
  std::pair<std::int32_t, std::int32_t> cut_faces(std::size_t v) const { return vs_[v].cut_tags; }
  void set_vertex(std::size_t v, const Point3& p) { v_[v] = p; }
  // The bound on vertex v's distance to its exact position (clip, before translate).
  double vertex_error(std::size_t v) const { return vs_[v].err; }
  // The last clip's new face was ordered by angle (its on-plane edges made no loop).
  bool cap_sorted() const { return cap_sorted_; }

  bool empty() const { return face_tag_.size() < 4; }
  std::size_t vertex_count() const { return v_.size(); }
  std::size_t face_count() const { return face_tag_.size(); }
  const std::vector<Point3>& vertices() const { return v_; }
  std::span<const std::uint32_t> face(std::size_t f) const {
    return {fv_.data() + fo_[f], fo_[f + 1] - fo_[f]};
  }
  std::int32_t face_tag(std::size_t f) const { return face_tag_[f]; }
  // All faces at once: offsets (face_count() + 1, from 0), corners, tags.
  std::span<const std::uint32_t> face_offsets() const { return fo_; }
  std::span<const std::uint32_t> face_vertices() const { return fv_; }
  std::span<const std::int32_t> face_tags() const { return face_tag_; }
  std::size_t edge_count() const { return (fv_.size()) / 2; }  // each edge in two faces

  double volume() const;
  Point3 centroid() const;  // centre of mass
  void translate(const Point3& t);

 private:
  using PlaneIds = std::array<std::uint32_t, 3>;  // into planes_, kNone: unknown
  // What a vertex carries besides its point (v_[i] goes with vs_[i], nv_[i] with nvs_[i]).
  struct VertexState {
    double err;                                      // bound on the position error
    PlaneIds planes;                                 // the three planes it meets
    std::uint32_t from;                              // after a clip: the old vertex it was, kNone for a new one
    std::pair<std::int32_t, std::int32_t> cut_tags;  // a new one: the faces of its cut edge
    bool on;                                         // during a clip: lies on the clip plane
  };
  bool apply_sides(std::int32_t tag);
  std::uint32_t cut_vertex(std::uint32_t in, std::uint32_t out, std::size_t face);
  void bound_new_vertices();
  void build_cap(std::int32_t tag);
  void clear();

  std::vector<Point3> v_, nv_;
  std::vector<VertexState> vs_, nvs_;
  std::vector<std::uint32_t> fv_, nfv_, fo_, nfo_;
  std::vector<std::int32_t> face_tag_, nface_tag_;
  std::vector<double> d_;
  double norm_n_ = 0, tol_ = 0;     // |n| and band of the clip in progress
  std::vector<ClipPlane> planes_;   // walls, then the clips that cut
  std::uint32_t plane_ = 0;         // the clip in progress in planes_ (kNone: signs)
  std::vector<std::uint32_t> face_plane_, nface_plane_;
  bool ambiguous_ = false, cap_sorted_ = false;
  std::vector<signed char> side_;
  std::vector<std::uint32_t> remap_;
  std::vector<std::uint64_t> cut_key_;          // edge (in,out) -> new vertex, small
  std::vector<std::uint32_t> cut_val_;
  std::vector<std::uint32_t> cap_from_, cap_to_;
  std::vector<std::uint32_t> poly_;
};

}  // namespace dtlab::vor
