// CGAL's dual as a Voronoi peer: Delaunay_triangulation_3 over EPICK (exact
// predicates, inexact constructions), each finite vertex's cell from `dual(cell)`
// (the circumcentres) of the cells around each incident edge, in CGAL's circulation
// order; faces turned outward by CGAL's exact orientation predicate (not by the
// rounded centres) and the cell clipped to the box by the adapter
// (voronoi/convex_cell.hpp). A hull vertex's cell is unbounded: the adapter clips the
// box with the bisectors of CGAL's neighbours of it instead (its topology is
// CGAL's, its vertices ours); so it does for a bounded cell whose wall clip broke a
// cell the shape rule accepts (clip_to_box). One vertex per set of duplicated sites.
//
// Cospherical sites (lattices) make several Delaunay cells share one circumcentre,
// which CGAL's dual gives once per cell, rounded differently: the adapter merges the
// cells around a vertex whose shared facet and two apexes are cospherical (CGAL's exact
// side_of_sphere is ON_BOUNDARY) into one Voronoi vertex, at the dual of one of them;
// a face left with fewer than 3 distinct vertices has zero area and is dropped. The
// cells are so judged on the topology CGAL's exact predicates give, not on its
// rounding of coincident centres.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "voronoi/cell_check.hpp"
#include "voronoi/convex_cell.hpp"
#include "voronoi/rounding_bound.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/voronoi_peer_programs.hpp"

namespace dtlab {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using DT = CGAL::Delaunay_triangulation_3<K, Tds>;

struct Scratch {
  std::map<DT::Cell_handle, std::uint32_t> index;  // Voronoi vertex of each incident cell
  std::vector<DT::Cell_handle> cells;
  std::vector<std::uint32_t> parent;  // union-find over `cells`
  std::vector<Point3> v;
  std::vector<std::uint32_t> offsets, corners;
  std::vector<std::int32_t> tags;
};

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// One Voronoi vertex per class of the cells around interior vertex h whose
// circumcentres coincide exactly (adjacent, shared facet and both apexes cospherical).
void merge_coincident_centres(const DT& dt, DT::Vertex_handle h, Scratch& s) {
  s.index.clear();
  s.v.clear();
  s.cells.clear();
  dt.incident_cells(h, std::back_inserter(s.cells));
  std::map<DT::Cell_handle, std::uint32_t> slot;
  for (std::uint32_t i = 0; i < s.cells.size(); ++i) slot[s.cells[i]] = i;
  s.parent.resize(s.cells.size());
  std::iota(s.parent.begin(), s.parent.end(), 0u);
  for (std::uint32_t i = 0; i < s.cells.size(); ++i) {
    const DT::Cell_handle c = s.cells[i];
    for (int f = 0; f < 4; ++f) {
      if (c->vertex(f) == h) continue;  // the facet opposite h does not contain it
      const DT::Cell_handle d = c->neighbor(f);
      const auto it = slot.find(d);
      if (it == slot.end() || it->second < i) continue;
      const auto& apex = d->vertex(d->index(c))->point();
      if (dt.side_of_sphere(c, apex) == CGAL::ON_BOUNDARY)
        s.parent[find_root(s.parent, it->second)] = find_root(s.parent, i);
    }
  }
  std::vector<std::uint32_t> vertex_of_root(s.cells.size(), 0xFFFFFFFFu);
  for (std::uint32_t i = 0; i < s.cells.size(); ++i) {
    std::uint32_t& v = vertex_of_root[find_root(s.parent, i)];
    if (v == 0xFFFFFFFFu) {
      v = static_cast<std::uint32_t>(s.v.size());
      const auto q = dt.dual(s.cells[i]);
      s.v.push_back({q.x(), q.y(), q.z()});
    }
    s.index[s.cells[i]] = v;
  }
}

// Whether CGAL's circulation c around edge (h, w) turns positively about h -> w.
bool turns_positively(DT::Vertex_handle h, DT::Vertex_handle w, DT::Cell_circulator c) {
  const DT::Cell_handle c0 = c, c1 = ++c;
  DT::Vertex_handle x, y;
  for (int k = 0; k < 4; ++k) {
    const DT::Vertex_handle v = c0->vertex(k);
    if (v == h || v == w) continue;
    (c1->has_vertex(v) ? y : x) = v;
  }
  return CGAL::orientation(h->point(), w->point(), x->point(), y->point()) == CGAL::POSITIVE;
}

// The bounded dual cell of interior vertex h, faces outward, tagged by neighbour.
void dual_cell(const DT& dt, DT::Vertex_handle h, Scratch& s) {
  merge_coincident_centres(dt, h, s);
  s.offsets.assign(1, 0);
  s.corners.clear();
  s.tags.clear();
  std::vector<DT::Edge> edges;
  dt.finite_incident_edges(h, std::back_inserter(edges));
  for (const auto& e : edges) {
    const auto a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    const auto w = a == h ? b : a;
    const std::size_t first = s.corners.size();
    auto c = dt.incident_cells(e), done = c;
    do {
      const std::uint32_t v = s.index.at(c);
      if (s.corners.size() == first || s.corners.back() != v) s.corners.push_back(v);
    } while (++c != done);
    if (s.corners.size() > first + 1 && s.corners.back() == s.corners[first]) s.corners.pop_back();
    std::vector<std::uint32_t> distinct(s.corners.begin() + static_cast<std::ptrdiff_t>(first), s.corners.end());
    std::sort(distinct.begin(), distinct.end());
    if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3) {  // zero area: no face
      s.corners.resize(first);
      continue;
    }
    // Outward: the loop turns positively about the edge h -> w. The Voronoi vertices
    // turn as their tets do around the edge, so the sign is combinatorial and exact:
    // stepping from tet (h, w, x, y) to its neighbour across (h, w, y) turns from x
    // towards y, positively when orientation(h, w, x, y) > 0. (The rounded centres'
    // own normal is no guide where the cell spans a few ulps, as on far_translate.)
    if (!turns_positively(h, w, dt.incident_cells(e)))
      std::reverse(s.corners.begin() + static_cast<std::ptrdiff_t>(first), s.corners.end());
    s.offsets.push_back(static_cast<std::uint32_t>(s.corners.size()));
    s.tags.push_back(static_cast<std::int32_t>(w->info()));
  }
}

// The clipping band of our own cells, relative to cell_scale (voronoi/voronoi.hpp).
const double kBand = VoronoiOptions{}.tolerance;

// The dual cell (relative to site s) clipped by the box walls it crosses, in our
// cells' band; false when that clip broke a dual that `dtlab voronoi --check`'s shape
// rule accepts (closed, convex within the ulp floor: voronoi/cell_check.hpp's
// check_cell): where a cell spans a few ulps (far_translate) its rounded centres are
// convex only up to rounding, the wall's cut then chains faces that do not close, and
// the caller clips the cell from CGAL's neighbours instead, as our own cells do (with
// their exact fallback). A dual the rule refuses (CGAL's centres far off, not finite)
// is kept as the clip left it: that is the answer to judge, not the adapter's clip.
bool clip_to_box(vor::ConvexCell& cell, const Point3& s, const vor::Box& box, double scale, const Scratch& dual) {
  const double lo[3] = {box.lo.x - s.x, box.lo.y - s.y, box.lo.z - s.z};
  const double hi[3] = {box.hi.x - s.x, box.hi.y - s.y, box.hi.z - s.z};
  const double band = kBand * scale;
  bool cut = false;
  for (int axis = 0; axis < 3 && !cell.empty(); ++axis) {
    Point3 n{0, 0, 0};
    (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = 1;
    cut |= cell.clip(n, hi[axis], -2 * axis - 2, band);
    if (!cell.empty()) cut |= cell.clip(-1 * n, -lo[axis], -2 * axis - 1, band);
  }
  if (!cut || cell.empty() || check_cell_closed(cell_view(cell)).empty()) return true;
  for (const Point3& v : dual.v)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return true;
  const VoronoiCell before = cell_view(dual.v, dual.offsets, dual.corners, dual.tags);
  return !check_cell(before, 1e-9 * scale, rounding_floor_distance(box)).empty();
}

}  // namespace

PeerCells peer_cgal_dual(const std::vector<Point3>& sites, const vor::Box& box) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::pair<K::Point_3, std::uint32_t>> in;
  in.reserve(sites.size());
  for (std::uint32_t i = 0; i < sites.size(); ++i) in.push_back({{sites[i].x, sites[i].y, sites[i].z}, i});
  DT dt(in.begin(), in.end());
  if (dt.dimension() < 3) throw PeerRefusal("CGAL: the sites span fewer than 3 dimensions");
  const double scale = cell_scale(box, sites);
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
    bool clipped_dual = false;
    if (!hull) {
      dual_cell(dt, h, s);
      cell.assign(s.v, s.offsets, s.corners, s.tags, site);
      clipped_dual = clip_to_box(cell, site, box, scale, s);
      if (clipped_dual) cell.translate(site);
    }
    if (!clipped_dual) {
      std::vector<DT::Vertex_handle> adj;
      dt.finite_adjacent_vertices(h, std::back_inserter(adj));
      nb.clear();
      for (auto w : adj) nb.push_back(w->info());
      compute_cell(cell, sites, id, nb, box, kBand, scale);
    }
    if (cell.empty()) continue;
    out.cells.add_cell(id, cell.vertices(), cell.face_offsets(), cell.face_vertices(), cell.face_tags());
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace dtlab
