// CGAL's dual as a Voronoi peer: Delaunay_triangulation_3 over EPICK (exact
// predicates, inexact constructions), each finite vertex's cell from `dual(cell)`
// (the circumcentres) of the cells around each incident edge, in CGAL's circulation
// order; faces turned outward and the cell clipped to the box by the adapter
// (voronoi/convex_cell.hpp). A hull vertex's cell is unbounded: the adapter clips the
// box with the bisectors of CGAL's neighbours of it instead (its topology is
// CGAL's, its vertices ours). One vertex per set of duplicated sites.
#include <map>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "voronoi/convex_cell.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/voronoi_peer_programs.hpp"

namespace dtlab {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using DT = CGAL::Delaunay_triangulation_3<K, Tds>;

struct Scratch {
  std::map<DT::Cell_handle, std::uint32_t> index;
  std::vector<Point3> v;
  std::vector<std::uint32_t> offsets, corners;
  std::vector<std::int32_t> tags;
};

// The bounded dual cell of interior vertex h, faces outward, tagged by neighbour.
void dual_cell(const DT& dt, DT::Vertex_handle h, Scratch& s) {
  s.index.clear();
  s.v.clear();
  s.offsets.assign(1, 0);
  s.corners.clear();
  s.tags.clear();
  std::vector<DT::Edge> edges;
  dt.finite_incident_edges(h, std::back_inserter(edges));
  const auto& p = h->point();
  for (const auto& e : edges) {
    const auto a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    const auto w = a == h ? b : a;
    const std::size_t first = s.corners.size();
    auto c = dt.incident_cells(e), done = c;
    do {
      auto [it, fresh] = s.index.try_emplace(c, static_cast<std::uint32_t>(s.v.size()));
      if (fresh) {
        const auto q = dt.dual(c);
        s.v.push_back({q.x(), q.y(), q.z()});
      }
      s.corners.push_back(it->second);
    } while (++c != done);
    // Outward: the face's normal points from h towards w.
    Point3 n{0, 0, 0};
    const Point3 o = s.v[s.corners[first]];
    for (std::size_t k = first + 1; k + 1 < s.corners.size(); ++k)
      n = n + cross(s.v[s.corners[k]] - o, s.v[s.corners[k + 1]] - o);
    const Point3 d{w->point().x() - p.x(), w->point().y() - p.y(), w->point().z() - p.z()};
    if (dot(n, d) < 0) std::reverse(s.corners.begin() + first, s.corners.end());
    s.offsets.push_back(static_cast<std::uint32_t>(s.corners.size()));
    s.tags.push_back(static_cast<std::int32_t>(w->info()));
  }
}

// Clips a cell (relative to site s) by the box walls it crosses.
void clip_to_box(vor::ConvexCell& cell, const Point3& s, const vor::Box& box) {
  const double lo[3] = {box.lo.x - s.x, box.lo.y - s.y, box.lo.z - s.z};
  const double hi[3] = {box.hi.x - s.x, box.hi.y - s.y, box.hi.z - s.z};
  for (int axis = 0; axis < 3 && !cell.empty(); ++axis) {
    Point3 n{0, 0, 0};
    (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = 1;
    cell.clip(n, hi[axis], -2 * axis - 2, 0);
    if (!cell.empty()) cell.clip(-1 * n, -lo[axis], -2 * axis - 1, 0);
  }
}

}  // namespace

PeerCells peer_cgal_dual(const std::vector<Point3>& sites, const vor::Box& box) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::pair<K::Point_3, std::uint32_t>> in;
  in.reserve(sites.size());
  for (std::uint32_t i = 0; i < sites.size(); ++i) in.push_back({{sites[i].x, sites[i].y, sites[i].z}, i});
  DT dt(in.begin(), in.end());
  if (dt.dimension() < 3) throw PeerRefusal("CGAL: the sites span fewer than 3 dimensions");
  PeerCells out;
  Scratch s;
  vor::ConvexCell cell;
  std::vector<std::uint32_t> nb;
  for (auto h = dt.finite_vertices_begin(); h != dt.finite_vertices_end(); ++h) {
    const std::uint32_t id = h->info();
    const Point3 site = sites[id];
    std::vector<DT::Cell_handle> cells;
    dt.incident_cells(h, std::back_inserter(cells));
    bool hull = false;
    for (auto c : cells) hull |= dt.is_infinite(c);
    if (hull) {
      std::vector<DT::Vertex_handle> adj;
      dt.finite_adjacent_vertices(h, std::back_inserter(adj));
      nb.clear();
      for (auto w : adj) nb.push_back(w->info());
      compute_cell(cell, sites, id, nb, box, 0);
    } else {
      dual_cell(dt, h, s);
      cell.assign(s.v, s.offsets, s.corners, s.tags, site);
      clip_to_box(cell, site, box);
      cell.translate(site);
    }
    if (cell.empty()) continue;
    out.cells.add_cell(id, cell.vertices(), cell.face_offsets(), cell.face_vertices(), cell.face_tags());
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace dtlab
