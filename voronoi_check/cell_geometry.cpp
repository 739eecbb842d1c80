#include "voronoi_check/cell_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "voronoi_check/vertex_filter.hpp"

namespace dtlab {

using namespace vor;

double face_area(const VoronoiCell& c, std::size_t f) {
  const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
  const Point3 o = c.vertices[c.face_vertices[b]];
  Point3 n{0, 0, 0};
  for (auto k = b + 1; k + 1 < e; ++k)
    n = n + cross(c.vertices[c.face_vertices[k]] - o, c.vertices[c.face_vertices[k + 1]] - o);
  return 0.5 * std::hypot(n.x, n.y, n.z);  // |n|^2 overflows for faces at 1e100
}

namespace {

using L = long double;
struct Plane {
  std::array<L, 3> n;
  L c;  // n . (x - site) = c
};

std::array<L, 3> lcross(const std::array<L, 3>& a, const std::array<L, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
L ldot(const std::array<L, 3>& a, const std::array<L, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
L lnorm(const std::array<L, 3>& a) { return std::sqrt(ldot(a, a)); }

// The plane of a face with neighbour `tag` (a site id or a wall), relative to site s.
bool plane_of(std::int32_t tag, std::span<const Point3> sites, const Point3& s, const Box& box, Plane& out) {
  if (tag >= 0) {
    if (static_cast<std::size_t>(tag) >= sites.size()) return false;
    const Point3& q = sites[tag];
    out.n = {L(q.x) - L(s.x), L(q.y) - L(s.y), L(q.z) - L(s.z)};
    out.c = ldot(out.n, out.n) / 2;
    return true;
  }
  if (tag < -6) return false;
  const int axis = (-tag - 1) / 2;
  const bool hi = (-tag - 1) % 2;
  const double lo_c[3] = {box.lo.x, box.lo.y, box.lo.z}, hi_c[3] = {box.hi.x, box.hi.y, box.hi.z};
  const double sc[3] = {s.x, s.y, s.z};
  out.n = {0, 0, 0};
  out.n[axis] = 1;
  out.c = L(hi ? hi_c[axis] : lo_c[axis]) - L(sc[axis]);
  return true;
}

// The per-cell arrays of vertex_errors, kept per thread (no allocation per cell).
struct VertexScratch {
  std::vector<Plane> face_plane;  // long double, built on first use (face_ld)
  std::vector<L> face_norm;
  std::vector<char> face_ok, face_ld;
  std::vector<FilterPlane> filter;
  std::array<std::uint32_t, 8> plane_at{};  // the faces at one vertex with a plane (at most 8) ...
  std::size_t plane_count = 0;              // ... so many of them
  std::span<const std::uint32_t> planes() const { return {plane_at.data(), plane_count}; }
  BoundBatch batch;                 // the vertices on three planes, for the filter
  std::vector<std::uint32_t> batched;
  std::vector<double> bound;
};

// The distance of vertex p (relative to the site) to the point where the three
// best-conditioned planes of s.planes meet; nullopt when they do not fix a point.
std::optional<L> vertex_error(const Point3& p, const Point3& site, const VertexScratch& s) {
  L best = 0, det = 0;
  std::array<L, 3> bd{};
  std::array<std::size_t, 3> pick{};
  const auto pl = s.planes();
  if (pl.size() == 3) {
    // The one triple (a simple vertex: nearly all of them), as the loop below takes it.
    bd = lcross(s.face_plane[pl[1]].n, s.face_plane[pl[2]].n);
    det = ldot(s.face_plane[pl[0]].n, bd);
    best = std::abs(det) / (s.face_norm[pl[0]] * s.face_norm[pl[1]] * s.face_norm[pl[2]]);
    pick = {pl[0], pl[1], pl[2]};
  } else
    for (std::size_t i = 0; i < pl.size(); ++i)
      for (std::size_t j = i + 1; j < pl.size(); ++j)
        for (std::size_t k = j + 1; k < pl.size(); ++k) {
          const auto jk = lcross(s.face_plane[pl[j]].n, s.face_plane[pl[k]].n);
          const L dt = ldot(s.face_plane[pl[i]].n, jk);
          const L d = std::abs(dt) / (s.face_norm[pl[i]] * s.face_norm[pl[j]] * s.face_norm[pl[k]]);
          if (d > best) best = d, det = dt, bd = jk, pick = {pl[i], pl[j], pl[k]};
        }
  if (!(best > 1e-9L)) return std::nullopt;
  // Cramer's rule with the chosen triple's determinant and first cross product kept.
  const Plane &a = s.face_plane[pick[0]], &b = s.face_plane[pick[1]], &d = s.face_plane[pick[2]];
  const auto da = lcross(d.n, a.n), ab = lcross(a.n, b.n);
  const L x[3] = {(a.c * bd[0] + b.c * da[0] + d.c * ab[0]) / det, (a.c * bd[1] + b.c * da[1] + d.c * ab[1]) / det,
                  (a.c * bd[2] + b.c * da[2] + d.c * ab[2]) / det};
  return std::max(
      {std::abs(L(p.x) - L(site.x) - x[0]), std::abs(L(p.y) - L(site.y) - x[1]), std::abs(L(p.z) - L(site.z) - x[2])});
}

}  // namespace

void prefetch_face_sites(const VoronoiCell& c, std::span<const Point3> sites) {
  for (auto tag : c.face_neighbor)
    if (tag >= 0 && static_cast<std::size_t>(tag) < sites.size()) __builtin_prefetch(&sites[tag]);
}

void vertex_errors(const VoronoiCell& c, const CellIncidence& in, std::span<const Point3> sites, std::uint32_t site,
                   const Box& box, std::span<VertexError> out, double below) {
  thread_local VertexScratch s;
  const Point3 st = sites[site];
  const std::size_t nf = c.face_count();
  s.face_plane.resize(nf);
  s.face_norm.resize(nf);
  s.face_ok.resize(nf);
  s.face_ld.assign(nf, 0);
  s.filter.resize(nf);
  filter_planes(c.face_neighbor, sites, st, box, s.filter.data(), s.face_ok.data());
  // The faces with a plane at vertex v (at most 8), into s.planes().
  const char* face_ok = s.face_ok.data();
  const auto gather_planes = [&](std::size_t v) {
    std::size_t n = 0;
    in.visit_faces(static_cast<std::uint32_t>(v), [&](std::uint32_t f) {
      if (n == s.plane_at.size()) return false;
      s.plane_at[n] = f;
      n += face_ok[f] != 0;
      return true;
    });
    s.plane_count = n;
  };
  // A vertex on exactly three faces, each with a plane (nearly all), from its face set:
  // gather_planes' answer without the visit (false: gather_planes decides).
  const auto three_planes = [&](std::uint64_t m, std::uint32_t(&pl)[3]) {
    for (auto& f : pl) f = static_cast<std::uint32_t>(__builtin_ctzll(m | std::uint64_t{1} << 63)), m &= m - 1;
    return m == 0 && pl[2] < 63 && face_ok[pl[0]] && face_ok[pl[1]] && face_ok[pl[2]];
  };
  // The filter first, on the vertices of three planes of a block of vertices at once
  // (one batch: every cell but a huge one is one block); the solve for the rest.
  const std::size_t nv = c.vertices.size();
  s.batched.resize(BoundBatch::kLanes);
  s.bound.resize(BoundBatch::kLanes);
  for (std::size_t v0 = 0; v0 < nv; v0 += BoundBatch::kLanes) {
    const std::size_t v1 = std::min(nv, v0 + BoundBatch::kLanes);
    s.batch.start();
    std::size_t batched = 0;
    if (below >= 0)
      for (std::size_t v = v0; v < v1; ++v) {
        std::uint32_t pl[3];
        if (!(in.bits && three_planes(in.faces[v], pl))) {
          gather_planes(v);
          if (s.plane_count != 3) continue;
          std::copy_n(s.plane_at.begin(), 3, pl);
        }
        s.batch.add(c.vertices[v], st, s.filter[pl[0]], s.filter[pl[1]], s.filter[pl[2]]);
        s.batched[batched++] = static_cast<std::uint32_t>(v);
      }
    s.batch.bounds(s.bound);
    std::size_t next = 0;  // the next batched vertex
    for (std::size_t v = v0; v < v1; ++v) {
      if (next < batched && s.batched[next] == v) {
        const double u = s.bound[next++];
        if (u >= 0 && u <= below) {
          out[v] = VertexError{0, true, true};
          continue;
        }
      }
      gather_planes(v);
      for (auto f : s.planes())
        if (!s.face_ld[f]) {
          plane_of(c.face_neighbor[f], sites, st, box, s.face_plane[f]);
          s.face_norm[f] = lnorm(s.face_plane[f].n);
          s.face_ld[f] = 1;
        }
      const auto e = vertex_error(c.vertices[v], st, s);
      out[v] = e ? VertexError{static_cast<double>(*e), true} : VertexError{};
    }
  }
}

void vertex_errors(const VoronoiCell& c, std::span<const Point3> sites, std::uint32_t site, const Box& box,
                   std::span<VertexError> out, double below) {
  thread_local CellIncidence in;
  cell_incidence(c, in);
  vertex_errors(c, in, sites, site, box, out, below);
}

}  // namespace dtlab
