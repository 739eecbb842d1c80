#include "voronoi_check/cell_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace dtlab {

using namespace vor;

double face_area(const VoronoiCell& c, std::size_t f) {
  const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
  const Point3 o = c.vertices[c.face_vertices[b]];
  Point3 n{0, 0, 0};
  for (auto k = b + 1; k + 1 < e; ++k)
    n = n + cross(c.vertices[c.face_vertices[k]] - o, c.vertices[c.face_vertices[k + 1]] - o);
  return 0.5 * norm(n);
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

}  // namespace

void vertex_errors(const VoronoiCell& c, std::span<const Point3> sites, std::uint32_t site, const Box& box,
                   std::span<VertexError> out) {
  const Point3 s = sites[site];
  const std::size_t nv = c.vertices.size();
  std::vector<std::uint32_t> off(nv + 1, 0), inc(c.face_vertices.size());
  for (auto v : c.face_vertices) ++off[v + 1];
  for (std::size_t v = 0; v < nv; ++v) off[v + 1] += off[v];
  std::vector<std::uint32_t> fill(off.begin(), off.end() - 1);
  for (std::size_t f = 0; f < c.face_count(); ++f)
    for (auto k = c.face_offsets[f]; k < c.face_offsets[f + 1]; ++k) inc[fill[c.face_vertices[k]]++] = f;
  std::vector<Plane> planes;
  for (std::size_t v = 0; v < nv; ++v) {
    planes.clear();
    for (auto k = off[v]; k < off[v + 1] && planes.size() < 8; ++k) {
      Plane p;
      if (plane_of(c.face_neighbor[inc[k]], sites, s, box, p)) planes.push_back(p);
    }
    // The best-conditioned triple of planes decides the point.
    L best = 0;
    std::array<std::size_t, 3> pick{};
    for (std::size_t i = 0; i < planes.size(); ++i)
      for (std::size_t j = i + 1; j < planes.size(); ++j)
        for (std::size_t k = j + 1; k < planes.size(); ++k) {
          const L d = std::abs(ldot(planes[i].n, lcross(planes[j].n, planes[k].n))) /
                      (lnorm(planes[i].n) * lnorm(planes[j].n) * lnorm(planes[k].n));
          if (d > best) best = d, pick = {i, j, k};
        }
    out[v] = {};
    if (!(best > 1e-9L)) continue;
    const Plane &a = planes[pick[0]], &b = planes[pick[1]], &d = planes[pick[2]];
    const L det = ldot(a.n, lcross(b.n, d.n));
    const auto bd = lcross(b.n, d.n), da = lcross(d.n, a.n), ab = lcross(a.n, b.n);
    const Point3& p = c.vertices[v];
    const L x[3] = {(a.c * bd[0] + b.c * da[0] + d.c * ab[0]) / det, (a.c * bd[1] + b.c * da[1] + d.c * ab[1]) / det,
                    (a.c * bd[2] + b.c * da[2] + d.c * ab[2]) / det};
    const L e = std::max({std::abs(L(p.x) - L(s.x) - x[0]), std::abs(L(p.y) - L(s.y) - x[1]),
                          std::abs(L(p.z) - L(s.z) - x[2])});
    out[v] = {static_cast<double>(e), true};
  }
}

}  // namespace dtlab
