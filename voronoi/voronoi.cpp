#include "voronoi/voronoi.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace dtlab {

using namespace vor;

std::vector<std::uint32_t> VoronoiCell::neighbors() const {
  std::vector<std::uint32_t> n;
  for (auto t : face_neighbor)
    if (t >= 0) n.push_back(static_cast<std::uint32_t>(t));
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

Adjacency delaunay_neighbors(const Tetrahedralization& dt) {
  const std::size_t n = dt.points.size();
  Adjacency a;
  // Each tet lists its 6 edges both ways; rows are then sorted and deduplicated.
  a.off.assign(n + 1, 0);
  for (const auto& t : dt.tets)
    for (auto v : t) a.off[v + 1] += 3;
  for (std::size_t i = 0; i < n; ++i) a.off[i + 1] += a.off[i];
  std::vector<std::uint32_t> fill(a.off.begin(), a.off.end() - 1);
  std::vector<std::uint32_t> raw(a.off[n]);
  for (const auto& t : dt.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != j) raw[fill[t[i]]++] = t[j];
  a.adj.clear();
  a.adj.reserve(raw.size() / 2);
  std::vector<std::uint32_t> off(n + 1, 0);
  std::vector<std::pair<double, std::uint32_t>> row;
  for (std::size_t v = 0; v < n; ++v) {
    auto b = raw.begin() + a.off[v], e = raw.begin() + a.off[v + 1];
    std::sort(b, e);
    e = std::unique(b, e);
    row.clear();
    for (auto it = b; it != e; ++it) {
      const Point3 d = vsub(dt.points[*it], dt.points[v]);
      row.push_back({vdot(d, d), *it});
    }
    std::sort(row.begin(), row.end());
    for (auto& r : row) a.adj.push_back(r.second);
    off[v + 1] = static_cast<std::uint32_t>(a.adj.size());
  }
  a.off = std::move(off);
  return a;
}

Box default_box(std::span<const Point3> sites, double margin) {
  Box b{sites[0], sites[0]};
  for (const auto& p : sites) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  // A flat input (all sites on a plane or line) still gets a box with volume.
  const Point3 e = vsub(b.hi, b.lo);
  const double big = std::max({e.x, e.y, e.z, 1.0});
  auto grow = [&](double& lo, double& hi, double ext) {
    const double g = ext > 0 ? margin * ext : margin * big;
    lo -= g;
    hi += g;
  };
  grow(b.lo.x, b.hi.x, e.x);
  grow(b.lo.y, b.hi.y, e.y);
  grow(b.lo.z, b.hi.z, e.z);
  return b;
}

void compute_cell(ConvexCell& cell, std::span<const Point3> sites, std::uint32_t i,
                  std::span<const std::uint32_t> neighbors, const Box& box, double tol,
                  double shrink) {
  const Point3 s = sites[i];
  cell.reset({vsub(box.lo, s), vsub(box.hi, s)});
  const double band = tol * box.diagonal();
  for (auto j : neighbors) {
    // Bisector of s and sites[j], relative to s: n.x <= |n|^2 / 2 with n = p_j - s.
    const Point3 n = vsub(sites[j], s);
    cell.clip(n, 0.5 * vdot(n, n) - shrink * vnorm(n), static_cast<std::int32_t>(j), band);
    if (cell.empty()) break;
  }
  cell.translate(s);
}

namespace {

std::vector<std::int64_t> find_duplicates(std::span<const Point3> p) {
  std::vector<std::uint32_t> idx(p.size());
  std::iota(idx.begin(), idx.end(), 0u);
  std::stable_sort(idx.begin(), idx.end(), [&](auto a, auto b) { return lex_less(p[a], p[b]); });
  std::vector<std::int64_t> dup(p.size(), -1);
  for (std::size_t k = 1; k < idx.size(); ++k) {
    const auto first = dup[idx[k - 1]] >= 0 ? dup[idx[k - 1]] : idx[k - 1];
    if (p[idx[k]] == p[idx[k - 1]]) dup[idx[k]] = first;
  }
  return dup;
}

void store(const ConvexCell& c, VoronoiCell& out) {
  out.vertices = c.vertices();
  out.face_offsets.assign(1, 0);
  out.face_vertices.clear();
  out.face_neighbor.clear();
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    auto fv = c.face(f);
    out.face_vertices.insert(out.face_vertices.end(), fv.begin(), fv.end());
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_vertices.size()));
    out.face_neighbor.push_back(c.face_tag(f));
  }
  out.volume = c.volume();
  out.centroid = c.centroid();
}

}  // namespace

VoronoiDiagram compute_voronoi(std::span<const Point3> sites, const VoronoiOptions& o) {
  if (sites.empty()) throw std::invalid_argument("no sites");
  VoronoiDiagram vd;
  vd.sites.assign(sites.begin(), sites.end());
  vd.box = o.box ? *o.box : default_box(sites, o.margin);
  vd.cells.resize(sites.size());
  const auto dup = find_duplicates(sites);

  Adjacency adj;
  BuildResult r = build_delaunay(sites, o.predicates);
  vd.tets = r.mesh.tets.size();
  if (r.failure && r.failure->kind != FailureKind::lower_dimensional)
    throw std::runtime_error("Delaunay build failed: " + r.failure->detail);
  if (r.failure) {
    // Fewer than four distinct or coplanar sites: every other site is a candidate.
    if (sites.size() > 4096) throw std::runtime_error("coplanar input too large for all-pairs cells");
    adj.off.assign(sites.size() + 1, 0);
    for (std::uint32_t v = 0; v < sites.size(); ++v) {
      std::vector<std::pair<double, std::uint32_t>> row;
      for (std::uint32_t w = 0; w < sites.size(); ++w)
        if (w != v && dup[w] < 0) {
          const Point3 d = vsub(sites[w], sites[v]);
          row.push_back({vdot(d, d), w});
        }
      std::sort(row.begin(), row.end());
      for (auto& x : row) adj.adj.push_back(x.second);
      adj.off[v + 1] = static_cast<std::uint32_t>(adj.adj.size());
    }
  } else {
    adj = delaunay_neighbors(r.mesh);
  }

  ConvexCell cell;
  for (std::uint32_t i = 0; i < sites.size(); ++i) {
    if (dup[i] >= 0) {
      vd.cells[i].duplicate_of = dup[i];
      continue;
    }
    std::span<const std::uint32_t> nb(adj.adj.data() + adj.off[i], adj.off[i + 1] - adj.off[i]);
    compute_cell(cell, sites, i, nb, vd.box, o.tolerance, o.shrink);
    store(cell, vd.cells[i]);
  }
  return vd;
}

}  // namespace dtlab
