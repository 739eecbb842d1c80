#pragma once
// Structural checks of one cell: closed and consistently oriented (every directed
// edge once, its reverse once), Euler characteristic 2, no degenerate edge or face,
// convex (every vertex behind every face plane) and planar faces, within `tol`
// (absolute length). The first two parts are also used alone by the Voronoi checker
// (voronoi_check/), which judges other tools' cells.
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "voronoi/above_plane.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

// A cell's incidence, built once per cell for both the closedness check and the vertex
// test (voronoi_check/cell_geometry.hpp); the arrays are reused, no allocation once warm.
// Two forms. Bit sets, for a cell of at most 64 vertices and 64 faces with no vertex
// twice in one face (nearly every cell): per vertex u the heads of the edges out of u
// (`out`), the tails of the edges into u (`in`) and the faces at u (`faces`), plus
// whether some directed edge is listed twice (`repeated`). Otherwise compressed rows:
// the edges out of v are k in [off[v], off[v+1]), each with its head vertex and its
// face, in face order.
struct CellIncidence {
  bool bits = false;  // the sets hold the incidence (else the rows)
  bool repeated = false;
  std::uint64_t out[64], in[64], faces[64];
  std::vector<std::uint32_t> off, head, face;
  std::vector<std::uint32_t> fill;  // cell_rows' cursor per vertex
  // The edges out of v (rows only).
  std::span<const std::uint32_t> heads(std::uint32_t v) const {
    return std::span<const std::uint32_t>(head).subspan(off[v], off[v + 1] - off[v]);
  }
  // The faces at v in the order the cell lists them, each given to visit(f), which
  // returns false to stop.
  template <class Visit>
  void visit_faces(std::uint32_t v, Visit&& visit) const {
    if (bits) {
      for (std::uint64_t m = faces[v]; m != 0; m &= m - 1)
        if (!visit(static_cast<std::uint32_t>(__builtin_ctzll(m)))) return;
      return;
    }
    for (auto k = off[v]; k < off[v + 1]; ++k)
      if (!visit(face[k])) return;
  }
};

// The rows form. Requires every face vertex id below c.vertices.size() (ToolCells and
// our cells keep it).
inline void cell_rows(const VoronoiCell& c, CellIncidence& in) {
  const std::size_t nf = c.face_count(), nv = c.vertices.size();
  in.bits = false;
  in.off.assign(nv + 1, 0);
  for (auto v : c.face_vertices) ++in.off[v + 1];
  for (std::size_t v = 0; v < nv; ++v) in.off[v + 1] += in.off[v];
  in.head.resize(c.face_vertices.size());
  in.face.resize(c.face_vertices.size());
  in.fill.assign(in.off.begin(), in.off.end() - 1);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    for (auto k = b; k < e; ++k) {
      const auto slot = in.fill[c.face_vertices[k]]++;
      in.head[slot] = c.face_vertices[k + 1 < e ? k + 1 : b];
      in.face[slot] = static_cast<std::uint32_t>(f);
    }
  }
}

// The bit sets form where the cell allows it (one pass over the faces' corners, no
// branch on the data), else the rows. The same requirement.
inline void cell_incidence(const VoronoiCell& c, CellIncidence& in) {
  const std::size_t nf = c.face_count(), nv = c.vertices.size();
  if (nv > 64 || nf > 64) return cell_rows(c, in);
  std::fill_n(in.out, nv, 0), std::fill_n(in.in, nv, 0), std::fill_n(in.faces, nv, 0);
  // Each face's edges from its last corner round: u -> v, u's set bit `bu`.
  std::uint64_t twice = 0, face_twice = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    if (b == e) continue;
    const std::uint64_t bf = std::uint64_t{1} << f;
    std::uint32_t u = c.face_vertices[e - 1];
    std::uint64_t bu = std::uint64_t{1} << u, seen = 0;
    for (auto k = b; k < e; ++k) {
      const std::uint32_t v = c.face_vertices[k];
      const std::uint64_t bv = std::uint64_t{1} << v;
      face_twice |= seen & bv;
      seen |= bv;
      twice |= in.out[u] & bv;
      in.out[u] |= bv;
      in.in[v] |= bu;
      in.faces[v] |= bf;
      u = v, bu = bv;
    }
  }
  if (face_twice != 0) return cell_rows(c, in);
  in.bits = true;
  in.repeated = twice != 0;
}

namespace detail {

// Whether every directed edge is used once, its reverse once, no edge joins a vertex to
// itself and every vertex is used, from the bit sets: no edge listed twice, and per
// vertex u an edge out, none to itself, and the heads of its edges out the tails of its
// edges in. No branch on the data; a false answer is explained by closed_search, which
// names the first defect.
inline bool sets_paired(std::size_t nv, const CellIncidence& in) {
  bool ok = !in.repeated;
  for (std::size_t u = 0; u < nv; ++u) ok &= (in.out[u] != 0) & (((in.out[u] >> u) & 1) == 0) & (in.out[u] == in.in[u]);
  return ok;
}

// The first defect of a cell on rows, else the Euler test (what sets_paired decides at
// once, searched; for the cells without bit sets and defective ones).
inline std::string closed_search(const VoronoiCell& c, const CellIncidence& in, long euler) {
  const std::size_t nv = c.vertices.size();
  for (std::uint32_t u = 0; u < nv; ++u) {
    const auto out = in.heads(u);
    for (std::size_t i = 0; i < out.size(); ++i)
      if (std::find(out.begin() + static_cast<std::ptrdiff_t>(i) + 1, out.end(), out[i]) != out.end())
        return "directed edge used twice";
  }
  for (std::uint32_t u = 0; u < nv; ++u)
    for (auto v : in.heads(u)) {
      if (u == v) return "edge from a vertex to itself";
      const auto back = in.heads(v);
      if (std::find(back.begin(), back.end(), u) == back.end()) return "edge without its reverse";
    }
  for (std::size_t v = 0; v < nv; ++v)
    if (in.off[v + 1] == in.off[v]) return "unused vertex";
  if (euler != 2) return "Euler characteristic " + std::to_string(euler);
  return {};
}

}  // namespace detail

// Closed and consistently oriented: at least 4 faces of 3+ corners, every directed
// edge once and its reverse once, no edge from a vertex to itself, every vertex used,
// V - E + F = 2. Exact (no tolerance). `in`: the cell's incidence (cell_incidence).
inline std::string check_cell_closed(const VoronoiCell& c, const CellIncidence& in) {
  const std::size_t nf = c.face_count(), nv = c.vertices.size();
  if (nf < 4) return "fewer than 4 faces";
  for (std::size_t f = 0; f < nf; ++f)
    if (c.face_offsets[f + 1] - c.face_offsets[f] < 3) return "face with fewer than 3 vertices";
  const long euler = long(nv) - long(c.face_vertices.size() / 2) + long(nf);
  if (!in.bits) return detail::closed_search(c, in, euler);
  if (detail::sets_paired(nv, in)) return euler == 2 ? std::string{} : "Euler characteristic " + std::to_string(euler);
  thread_local CellIncidence rows;  // the search reads rows; a defective cell is rare
  cell_rows(c, rows);
  return detail::closed_search(c, rows, euler);
}

// The same, building the incidence in an array kept by the thread.
inline std::string check_cell_closed(const VoronoiCell& c) {
  thread_local CellIncidence in;
  cell_incidence(c, in);
  return check_cell_closed(c, in);
}

// The most a vertex of a cell can lie beyond a face's computed plane when each vertex is
// within e (Euclidean) of a convex cell's with the same faces (a correctly rounded
// cell): with R >= |v - o| for the face's corners v and its first corner o, D >= |p - o|
// for every vertex p of the cell, and the face's Newell normal n over T fan triangles,
// the true normal differs from n by at most T (4 e R + 4 e^2) (each cross product of
// two fan edges moved by 2 e), so the unit normal by theta = 2 T (4 e R + 4 e^2) / |n|,
// and n.(p - o) by 2 e + theta D; 8 ulps of D more for the test's own rounding. A thin
// face (theta >= 2) cannot fail: its plane is not defined at that rounding.
inline double rounded_plane_tolerance(double e, double R, double D, double area2, std::size_t triangles) {
  const double theta = 2 * static_cast<double>(triangles) * (4 * e * R + 4 * e * e) / area2;
  return (2 * e + theta * D) * (1 + 1e-12) + 0x1p-50 * D;
}

// How check_cell_convex tests a cell. `tol`: absolute length. `skip_tiny`: faces of area
// below tol^2 (whose plane rounding does not define) are not tested; otherwise they are a
// defect ("zero-area face"). `vertex_error` e > 0: a face's tolerance is max(tol,
// rounded_plane_tolerance(e, ...)) (R: the face's farthest corner from its first, D: the
// diagonal of the cell's vertices' bounding box); e = 0 tests with tol alone.
struct ConvexTest {
  double tol = 0;
  bool skip_tiny = false;
  double vertex_error = 0;
};

// What check_cell_convex found beside its verdict. `skipped`: a tiny face was not tested;
// `widened`: some tested face's tolerance was above tol; `volume`: with every face
// measured (the cell passed), the cell's volume from the faces' normals (sum over faces of
// (o_f - v0) . n_f / 6, o_f the face's first corner, n_f its fan normal: cell_volume's
// fans, voronoi_check/tool_cells.hpp, summed in another order); NaN when the test stopped
// early.
struct ConvexFindings {
  bool skipped = false, widened = false;
  double volume = NAN;
};

namespace detail {

// Whether a corner of face f (past its first) lies beyond plane `pl` as beyond(distance) says.
template <class Beyond>
bool corner_beyond(const VoronoiCell& c, std::size_t f, const FacePlane& pl, Beyond&& beyond) {
  const Point3* const V = c.vertices.data();
  for (auto k = c.face_offsets[f] + 1; k < c.face_offsets[f + 1]; ++k)
    if (beyond(dot(pl.n, V[c.face_vertices[k]] - pl.o))) return true;
  return false;
}

// A face's tolerance: tol, or rounded_plane_tolerance where that is more. It can exceed
// tol only where rounded_plane_tolerance(e, D, D, area2, T) > tol, i.e. where theta D =
// T K / area2 (K = 2 (4 e D + 4 e^2) D) exceeds `room`, less 1e-9 of the terms (far more
// than the roundings of either side). So that bound is computed only for faces with
// T K >= room area2 / 2, or any face when room <= 0 (or NaN); a face let through is
// decided as before, so the result is the same.
struct FaceTolerance {
  double tol, e, D, K, room;
  FaceTolerance(double tol_, double e_, double D_)
      : tol(tol_),
        e(e_),
        D(D_),
        K(2 * (4 * e_ * D_ + 4 * e_ * e_) * D_),
        room((tol_ - 0x1p-50 * D_) / (1 + 1e-12) - 2 * e_ - 1e-9 * (tol_ + 2 * e_ + 0x1p-50 * D_)) {}
  // r2: the face's largest squared distance from its first corner, asked only when
  // needed. Above tol exactly when widened.
  template <class R2>
  double at(double area2, std::size_t triangles, R2&& r2) const {
    if (!(e > 0) || (room > 0 && static_cast<double>(triangles) * K < 0.5 * room * area2) ||
        !(rounded_plane_tolerance(e, D, D, area2, triangles) > tol))
      return tol;
    // R <= D: the face's own R only where the bound with D exceeds tol (thin faces).
    const double r = rounded_plane_tolerance(e, std::min(D, std::sqrt(r2()) * (1 + 1e-15)), D, area2, triangles);
    return r > tol ? r : tol;
  }
};

// The convexity test's first pass over the faces in order: each face's plane (the
// normalized fan normal at its first corner) and tolerance into plane[np] and face_of[np],
// and its planarity below the plane; stops at a face that fails. Tiny
// faces (area <= tol^2) make no plane: skipped, or the stop when !skip_tiny.
struct FacePlanes {
  std::size_t np = 0, first_tiny, stop_face;  // planes made; the first tiny face; the stop's face
  const char* stop = nullptr;                 // the defect it stopped at
  bool stop_planar = false;                   // the stop is a face's planarity (its plane made)
  double six_volume = 0;                      // sum over faces of (o_f - v0) . n_f
};
inline FacePlanes face_planes(const VoronoiCell& c, const ConvexTest& test, const FaceTolerance& tolerance,
                              FacePlane* plane, std::uint32_t* face_of) {
  // The cell's arrays as raw pointers, read once (stores to the planes could alias the
  // spans' members for the compiler, which then reloads them per face).
  const Point3* const V = c.vertices.data();
  const std::uint32_t* const offsets = c.face_offsets.data();
  const std::uint32_t* const corners = c.face_vertices.data();
  const std::size_t nf = c.face_count();
  const double tol = test.tol;
  FacePlanes out;
  out.first_tiny = out.stop_face = nf;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto b = offsets[f], e = offsets[f + 1];
    const Point3 o = V[corners[b]];
    // The fan from the first corner, each corner's difference to it carried to the next triangle.
    Point3 n{0, 0, 0};
    if (e - b >= 3) {
      Point3 prev = V[corners[b + 1]] - o;
      for (auto k = b + 2; k < e; ++k) {
        const Point3 next = V[corners[k]] - o;
        n = n + cross(prev, next);
        prev = next;
      }
    }
    out.six_volume += dot(o - V[0], n);
    const double area2 = norm(n);
    if (area2 <= tol * tol) {
      if (!test.skip_tiny) {
        out.stop = "zero-area face", out.stop_face = f;
        return out;
      }
      out.first_tiny = std::min(out.first_tiny, f);
      continue;
    }
    const auto r2 = [&] {
      double r = 0;
      for (auto k = b + 1; k < e; ++k) r = std::max(r, norm2(V[corners[k]] - o));
      return r;
    };
    const double t = tolerance.at(area2, e - b > 2 ? e - b - 2 : 1, r2);
    plane[out.np] = {1.0 / area2 * n, o, t};
    face_of[out.np] = static_cast<std::uint32_t>(f);
    // Planar below the plane (the first corner is on it; above: the second pass).
    if (corner_beyond(c, f, plane[out.np++], [t](double d) { return d < -t; })) {
      out.stop = "non-planar face", out.stop_face = f, out.stop_planar = true;
      return out;
    }
  }
  return out;
}

}  // namespace detail

// Planar faces and convex (every vertex behind every face plane) as `test` says; "" or
// the defect, that of the first face (in the cell's order) that shows one. Two passes:
// each face's plane, tolerance and planarity below it (detail::face_planes, which stops
// at a face that fails), then every vertex against the planes before that face at once
// (first_plane_exceeded, the vertices copied into per-thread coordinate arrays), which
// also covers planarity above. `found` (if given) receives the findings above, of the
// faces up to the one that failed.
inline std::string check_cell_convex(const VoronoiCell& c, const ConvexTest& test, ConvexFindings* found = nullptr) {
  using namespace vor;
  thread_local std::vector<double> xs, ys, zs;
  thread_local std::vector<FacePlane> planes;
  thread_local std::vector<std::uint32_t> plane_face;  // the face of each plane
  const std::size_t nv = c.vertices.size(), nf = c.face_count();
  xs.resize(nv), ys.resize(nv), zs.resize(nv);
  double *X = xs.data(), *Y = ys.data(), *Z = zs.data();
  Point3 lo = nv > 0 ? c.vertices[0] : Point3{0, 0, 0}, hi = lo;
  for (std::size_t i = 0; i < nv; ++i) {
    const Point3& v = c.vertices[i];
    X[i] = v.x, Y[i] = v.y, Z[i] = v.z;
    lo = min3(lo, v), hi = max3(hi, v);
  }
  const double D = test.vertex_error > 0 ? norm(hi - lo) : 0;
  planes.resize(nf), plane_face.resize(nf);
  // Raw pointers: the thread's vectors are not reread per face.
  FacePlane* const plane = planes.data();
  std::uint32_t* const face_of = plane_face.data();
  const detail::FacePlanes made = detail::face_planes(c, test, {test.tol, test.vertex_error, D}, plane, face_of);
  // The planes before the stop (a face stopped at by planarity is tested there: its
  // corners lie beyond below, the defect named is the same).
  const std::size_t tested = made.stop_planar ? made.np - 1 : made.np;
  const std::size_t g = first_plane_exceeded(X, Y, Z, nv, plane, tested);
  // The findings of the faces up to the first defect (the old single pass stopped there).
  const std::size_t last_face = g < tested ? face_of[g] : made.stop_face;
  if (found) {
    found->skipped = made.first_tiny < last_face;
    for (std::size_t i = 0; i < made.np && face_of[i] <= last_face; ++i)
      found->widened = found->widened || plane[i].t > test.tol;
  }
  if (g < tested) {
    const double t = plane[g].t;
    return detail::corner_beyond(c, face_of[g], plane[g], [t](double d) { return d > t; }) ? "non-planar face"
                                                                                           : "not convex";
  }
  if (made.stop) return made.stop;
  if (found) found->volume = made.six_volume / 6;
  return {};
}

// Whether an edge of `c` has length <= tol (tol = 0: two corners rounded to one point).
inline bool has_edge_within(const VoronoiCell& c, double tol) {
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    for (auto k = b; k < e; ++k) {
      const auto u = c.face_vertices[k], v = c.face_vertices[k + 1 < e ? k + 1 : b];
      if (norm(c.vertices[u] - c.vertices[v]) <= tol) return true;
    }
  }
  return false;
}

// A cell as `dtlab voronoi --check`, the VTU `defect` flag and the exact Voronoi checker
// judge it: closed, and planar and convex within tol, each face plane's tolerance
// widened by what vertices within `vertex_error` of their true places allow
// (check_cell_convex); faces of area below tol^2, whose planes rounding does not
// define, are not tested. Short edges and small faces are no defect: a Voronoi edge may
// be arbitrarily short (four sites nearly cospherical), and whether it belongs there is
// for the exact checker to say (`--against dtlab:exact`). An earlier rule called every
// edge of length <= tol "zero-length", real ones included (has_edge_within).
inline std::string check_cell(const VoronoiCell& c, double tol, double vertex_error = 0) {
  if (std::string why = check_cell_closed(c); !why.empty()) return why;
  return check_cell_convex(c, {tol, true, vertex_error});
}

}  // namespace dtlab
