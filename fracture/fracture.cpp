#include "fracture/fracture.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <thread>

#include "fracture/anisotropic_cells.hpp"
#include "fracture/cell_weld.hpp"
#include "fracture/islands.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Level {
  std::vector<Piece> pieces;
  std::size_t booleans = 0, skipped = 0;
};

// The level's sites: the top level's from the chosen source, a recursion's sampled.
std::vector<Point3> level_sites(const MeshClipper& clipper, const FractureOptions& o, const SiteOptions& source,
                                std::uint64_t seed, std::size_t count) {
  MeshSampler sampler(clipper.mesh());
  SampleRequest req;
  req.method = o.sampler;
  req.count = count;
  req.seed = seed;
  req.blue_noise = o.blue_noise;
  std::vector<Point3> sites = choose_sites(sampler, clipper.mesh(), source, req);
  if (sites.empty()) throw std::runtime_error("the sampler found no site inside the mesh");
  return sites;
}

// The cells only need to cover the mesh (its box, grown a little) and hold every site.
ScaledCells level_cells(const MeshClipper& clipper, const FractureOptions& o, const std::vector<Point3>& sites) {
  VoronoiOptions vo;
  vo.margin = 0.05;
  Box3 mb = bounding_box(clipper.mesh());
  for (const auto& s : sites) mb.add(s);
  const Point3 g = 0.05 * mb.extent() + Point3{1e-9, 1e-9, 1e-9};
  vo.box = vor::Box{mb.lo - g, mb.hi + g};
  vo.shrink = 0.5 * o.margin;
  ScaledCells cells = o.cell_scale.x == 1 && o.cell_scale.y == 1 && o.cell_scale.z == 1
                          ? ScaledCells{compute_voronoi(sites, vo), {}}
                          : anisotropic_voronoi(sites, vo, o.cell_scale);
  // Shared corners bit-identical (a few ulps apart where a cell was clipped in its site's
  // frame), so the cells tile the box exactly; not with a gap (no shared corners).
  if (o.margin == 0) weld_shared_corners(cells, 1e-12 * norm(vo.box->hi - vo.box->lo));
  return cells;
}

// Site i's piece, split into its islands (or kept whole), tags naming islands.
std::vector<Piece> level_islands(std::vector<PieceMesh> geometry, const std::vector<Point3>& sites, bool split) {
  std::vector<PieceMesh> islands;
  std::vector<IslandRef> refs;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    if (geometry[i].mesh.triangles.empty()) continue;  // the cell misses the mesh
    std::vector<PieceMesh> parts = split ? split_islands(geometry[i]) : std::vector<PieceMesh>{std::move(geometry[i])};
    for (std::size_t k = 0; k < parts.size(); ++k) {
      refs.push_back({i, k});
      islands.push_back(std::move(parts[k]));
    }
  }
  retag_to_islands(islands, refs, sites.size());
  std::vector<std::size_t> count(sites.size(), 0);
  for (const auto& r : refs) ++count[r.site];
  std::vector<Piece> pieces(islands.size());
  for (std::size_t k = 0; k < islands.size(); ++k) {
    pieces[k].geometry = std::move(islands[k]);
    pieces[k].site = sites[refs[k].site];
    pieces[k].site_index = static_cast<std::int64_t>(refs[k].site);
    pieces[k].island = static_cast<std::int64_t>(refs[k].island);
    pieces[k].site_islands = count[refs[k].site];
  }
  return pieces;
}

// One level of fracture of `clipper`'s mesh: one piece per island of each site's cell
// (cells that miss the mesh give none); cut tags name pieces of the level.
Level fracture_once(const MeshClipper& clipper, const FractureOptions& o, const SiteOptions& source,
                    std::uint64_t seed, std::size_t count, FractureResult& timing) {
  auto t0 = Clock::now();
  const std::vector<Point3> sites = level_sites(clipper, o, source, seed, count);
  timing.seconds_sampling += since(t0);

  t0 = Clock::now();
  const ScaledCells cells = level_cells(clipper, o, sites);
  timing.seconds_voronoi += since(t0);

  t0 = Clock::now();
  std::vector<PieceMesh> geometry = clipper.intersect_all(cells.diagram.cells, o.threads);
  timing.seconds_boolean += since(t0);
  if (timing.exact_tiling_checked) {
    const MeshClipper::ExactTally t = clipper.exact_tally();
    timing.exact_tiling = timing.exact_tiling && t.holds;
    if (std::abs(t.difference) > std::abs(timing.exact_tiling_difference))
      timing.exact_tiling_difference = t.difference;
  }
  Level level;
  for (const auto& g : geometry)
    if (!g.mesh.triangles.empty()) ++(g.boolean_skipped ? level.skipped : level.booleans);
  level.pieces = level_islands(std::move(geometry), sites, o.island_split);
  for (auto& p : level.pieces) measure_piece(p);
  std::vector<char> has_piece(sites.size(), 0);
  for (const auto& p : level.pieces)
    if (p.site_index >= 0) has_piece[static_cast<std::size_t>(p.site_index)] = 1;
  timing.sites += sites.size();
  for (std::size_t i = 0; i < sites.size(); ++i)
    if (cells.diagram.cells[i].duplicate_of >= 0)
      ++timing.duplicate_sites;
    else if (!has_piece[i])
      ++timing.sites_without_piece;
  return level;
}
}  // namespace

void measure_piece(Piece& p) {
  const TriangleMesh& m = p.geometry.mesh;
  double vol = 0, area = 0;
  Point3 c{0, 0, 0};
  const Point3 o = m.vertices.empty() ? Point3{0, 0, 0} : m.vertices[0];
  std::vector<std::uint32_t> nb;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Point3 a = m.corner(t, 0) - o, b = m.corner(t, 1) - o, d = m.corner(t, 2) - o;
    const double w = dot(a, cross(b, d));
    vol += w;
    c += w * (a + b + d);
    if (p.geometry.cut[t]) {
      area += m.triangle_area(t);
      if (p.geometry.cut_tag[t] >= 0) nb.push_back(static_cast<std::uint32_t>(p.geometry.cut_tag[t]));
    }
  }
  p.volume = vol / 6;
  p.centroid = vol != 0 ? o + (1.0 / (4 * vol)) * c : o;
  // Second moments about o, tetrahedron by tetrahedron (o, a, b, d): for a tetrahedron
  // with one corner at the origin, integral of x x^T = det/120 (s s^T + a a^T + b b^T + d d^T)
  // with s = a + b + d. Then moved to the centroid and turned into I = tr(C) Id - C.
  double C[3][3] = {};
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Point3 a = m.corner(t, 0) - o, b = m.corner(t, 1) - o, d = m.corner(t, 2) - o;
    const double w = dot(a, cross(b, d)) / 120;
    const Point3 s = a + b + d;
    const double v[4][3] = {{s.x, s.y, s.z}, {a.x, a.y, a.z}, {b.x, b.y, b.z}, {d.x, d.y, d.z}};
    for (const auto& q : v)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) C[i][j] += w * q[i] * q[j];
  }
  const Point3 g = p.centroid - o;
  const double gv[3] = {g.x, g.y, g.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[i][j] -= p.volume * gv[i] * gv[j];
  const double tr = C[0][0] + C[1][1] + C[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.inertia[3 * i + j] = (i == j ? tr : 0) - C[i][j];
  p.interior_area = area;
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  p.neighbors = std::move(nb);
}

// Marks the triangles of sub-piece `sp` that lie on a cut face of its parent (in the
// plane of one of the parent's cut triangles) as cut, tagged with the parent's tag
// (a top-level neighbour id t becomes -1000 - t, to be mapped once all ids are known).
void mark_parent_cut_faces(const Piece& parent, Piece& sp) {
  const TriangleMesh& m = sp.geometry.mesh;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (sp.geometry.cut[t]) continue;
    // A sub-piece triangle on the parent's cut face lies in the plane of one of
    // the parent's cut triangles.
    const TriangleMesh& pm = parent.geometry.mesh;
    for (std::size_t u = 0; u < pm.triangles.size(); ++u) {
      if (!parent.geometry.cut[u]) continue;
      Point3 n = pm.area_normal(u);
      const double len = norm(n);
      if (len == 0) continue;
      n = (1.0 / len) * n;
      bool on = true;
      for (int k = 0; k < 3 && on; ++k)
        on = std::abs(dot(n, m.corner(t, k) - pm.corner(u, 0))) <= 1e-9 * std::sqrt(len);
      if (on) {
        sp.geometry.cut[t] = 1;
        sp.geometry.cut_tag[t] =
            parent.geometry.cut_tag[u] >= 0 ? -1000 - parent.geometry.cut_tag[u] : parent.geometry.cut_tag[u];
        break;
      }
    }
  }
}

// The input as a solid (repaired first with o.repair), its report and repair steps in r.
TriangleMesh solid_input(const TriangleMesh& mesh, const FractureOptions& o, FractureResult& r) {
  if (o.repair) {
    RepairResult rr = repair_mesh(mesh);
    r.report = rr.before;
    r.repairs = rr.steps;
    if (!rr.solid()) throw std::invalid_argument("cannot be repaired into a solid: " + rr.after.why_not_solid());
    return std::move(rr.mesh);
  }
  if (r.report = analyze_mesh(mesh); !r.report.solid())
    throw std::invalid_argument("not a solid: " + r.report.why_not_solid() + " (--repair tries to fix it)");
  return mesh;
}

// Recursion: each chosen piece (a closed mesh itself) is fractured again, its
// sub-pieces appended to r.pieces in place of it. Sub-pieces keep their parent's cut
// faces; their neighbours are their siblings plus the parent's neighbours they share a
// cut face with (tags of the parent's cut faces). ids: top piece -> its final ids.
std::vector<std::vector<std::uint32_t>> fracture_chosen(Level& top, const FractureOptions& o, FractureResult& r) {
  std::vector<char> chosen(top.pieces.size(), 0);
  for (auto i : o.recurse) {
    if (i >= top.pieces.size())
      throw std::invalid_argument("--recurse: no piece " + std::to_string(i) + " (there are " +
                                  std::to_string(top.pieces.size()) + ")");
    chosen[i] = 1;
  }
  std::vector<std::vector<std::uint32_t>> ids(top.pieces.size());
  for (std::size_t i = 0; i < top.pieces.size(); ++i) {
    if (!chosen[i]) {
      ids[i].push_back(static_cast<std::uint32_t>(r.pieces.size()));
      r.pieces.push_back(std::move(top.pieces[i]));
      continue;
    }
    const Piece& parent = top.pieces[i];
    // A piece's vertices were rounded to doubles: check it is still a solid.
    const MeshReport pr = analyze_mesh(parent.geometry.mesh);
    if (!pr.solid())
      throw std::runtime_error("--recurse: piece " + std::to_string(i) + " is not a solid after rounding: " +
                               pr.why_not_solid());
    MeshClipper sub_clipper(parent.geometry.mesh, MeshClipper::MeshCheck::solid);
    sub_clipper.set_time_budget(o.boolean_seconds);
    sub_clipper.set_exact_tally(r.exact_tiling_checked);
    Level sub = fracture_once(sub_clipper, o, SiteOptions{}, o.seed * 1000003 + i, o.recurse_pieces, r);
    r.booleans += sub.booleans;
    r.skipped += sub.skipped;
    const std::uint32_t first = static_cast<std::uint32_t>(r.pieces.size());
    for (auto& sp : sub.pieces) {
      for (auto& tag : sp.geometry.cut_tag)
        if (tag >= 0) tag += static_cast<std::int32_t>(first);
      mark_parent_cut_faces(parent, sp);
      sp.parent = static_cast<int>(i);
      ids[i].push_back(static_cast<std::uint32_t>(r.pieces.size()));
      r.pieces.push_back(std::move(sp));
    }
  }
  return ids;
}

// Every piece measured and its neighbours resolved: tags >= 0 are final ids (siblings,
// unchanged top level), tags <= -1000 a top-level piece mapped through ids (all its
// final pieces, conservatively); links made symmetric, self links dropped.
void resolve_neighbours(const std::vector<std::vector<std::uint32_t>>& ids, FractureResult& r) {
  for (auto& p : r.pieces) {
    if (p.parent < 0) {
      for (auto& tag : p.geometry.cut_tag)
        if (tag >= 0) tag = ids[tag].size() == 1 ? static_cast<std::int32_t>(ids[tag][0]) : -1000 - tag;
    }
  }
  for (auto& p : r.pieces) {
    measure_piece(p);
    std::vector<std::uint32_t> nb;
    for (std::size_t t = 0; t < p.geometry.cut_tag.size(); ++t) {
      const auto tag = p.geometry.cut_tag[t];
      if (!p.geometry.cut[t]) continue;
      if (tag <= -1000) {
        for (auto j : ids[-1000 - tag]) nb.push_back(j);
        p.geometry.cut_tag[t] = -1;
      }
    }
    nb.insert(nb.end(), p.neighbors.begin(), p.neighbors.end());
    p.neighbors = std::move(nb);
  }
  std::vector<std::vector<std::uint32_t>> sym(r.pieces.size());
  for (std::uint32_t i = 0; i < r.pieces.size(); ++i)
    for (auto j : r.pieces[i].neighbors)
      if (j != i && j < r.pieces.size()) sym[i].push_back(j), sym[j].push_back(i);
  for (std::uint32_t i = 0; i < r.pieces.size(); ++i) {
    std::sort(sym[i].begin(), sym[i].end());
    sym[i].erase(std::unique(sym[i].begin(), sym[i].end()), sym[i].end());
    r.pieces[i].neighbors = std::move(sym[i]);
  }
}

FractureResult fracture_mesh(const TriangleMesh& mesh, const FractureOptions& o) {
  if (o.pieces == 0) throw std::invalid_argument("--pieces must be at least 1");
  // A gap as wide as the mesh leaves no piece (the CLI and Python both refuse it here).
  if (const Box3 box = bounding_box(mesh); o.margin > 0 && !(o.margin < norm(box.hi - box.lo))) {
    char why[160];
    std::snprintf(why, sizeof why, "%.*s %g is not smaller than the mesh (bounding box diagonal %g)",
                  static_cast<int>(o.margin_name.size()), o.margin_name.data(), o.margin, norm(box.hi - box.lo));
    throw std::invalid_argument(why);
  }
  FractureResult r;
  MeshClipper clipper(solid_input(mesh, o, r), MeshClipper::MeshCheck::solid);  // analyzed by solid_input
  clipper.set_time_budget(o.boolean_seconds);
  r.exact_tiling_checked = r.exact_tiling = o.exact_tiling && o.margin == 0;
  clipper.set_exact_tally(r.exact_tiling_checked);
  clipper.set_progress(o.progress);
  r.input = clipper.mesh();
  r.mesh_volume = clipper.volume();
  Level top = fracture_once(clipper, o, o.sites, o.seed, o.pieces, r);
  r.booleans += top.booleans;
  r.skipped += top.skipped;
  resolve_neighbours(fracture_chosen(top, o, r), r);
  return r;
}

}  // namespace dtlab
