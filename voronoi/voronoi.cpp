#include "voronoi/voronoi.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "kernel/ids.hpp"
#include "kernel/parallel_for.hpp"
#include "voronoi/cell_buffer.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/circumcenter.hpp"
#include "voronoi/dual_cell.hpp"
#include "voronoi/exact_cell.hpp"
#include "voronoi/rounding_bound.hpp"

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
      const Point3 d = dt.points[*it] - dt.points[v];
      row.push_back({dot(d, d), *it});
    }
    std::sort(row.begin(), row.end());
    for (auto& r : row) a.adj.push_back(r.second);
    off[v + 1] = static_cast<std::uint32_t>(a.adj.size());
  }
  a.off = std::move(off);
  return a;
}

void vertex_stars(std::size_t n, std::span<const Tet> tets, std::vector<std::uint32_t>& off,
                  std::vector<std::uint32_t>& star) {
  off.assign(n + 1, 0);
  for (const auto& t : tets)
    for (auto v : t) ++off[v + 1];
  for (std::size_t i = 0; i < n; ++i) off[i + 1] += off[i];
  star.resize(off[n]);
  std::vector<std::uint32_t> fill(off.begin(), off.end() - 1);
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    for (auto v : tets[t]) star[fill[v]++] = t;
}

Box default_box(std::span<const Point3> sites, double margin) {
  Box b{sites[0], sites[0]};
  for (const auto& p : sites) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  // A flat input (all sites on a plane or line) still gets a box with volume.
  const Point3 e = b.hi - b.lo;
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

double cell_scale(const Box& box, std::span<const Point3> sites) {
  const double diagonal = box.diagonal();
  if (sites.empty()) return diagonal;
  return std::min(diagonal, default_box(sites, 0.1).diagonal());
}

namespace {

// Faces of at most this fraction of the scale squared may differ between an
// ambiguous cell's band and exact forms (or be dropped by drop_tiny_faces).
constexpr double kSmallFace = 1e-10;

// The area of face f of `c` (its rounded corners, fanned from the first).
double face_area(const ConvexCell& c, std::size_t f) {
  const auto fv = c.face(f);
  const Point3 o = c.vertices()[fv[0]];
  Point3 n{0, 0, 0};
  for (std::size_t k = 1; k + 1 < fv.size(); ++k) n = n + cross(c.vertices()[fv[k]] - o, c.vertices()[fv[k + 1]] - o);
  return 0.5 * norm(n);
}

// The largest face of `a` whose tag `b` lacks (0 if none).
double largest_face_missing(const ConvexCell& a, const ConvexCell& b) {
  double largest = 0;
  const auto tb = b.face_tags();
  for (std::size_t f = 0; f < a.face_count(); ++f)
    if (std::find(tb.begin(), tb.end(), a.face_tag(f)) == tb.end()) largest = std::max(largest, face_area(a, f));
  return largest;
}

// `c` rounded to doubles as the checkers judge it, each part of the cell check run
// once: `clean` when it passes `dtlab voronoi --check`'s cell check at `tol` (no edge
// shorter, no face smaller than tol^2, planar, convex); `representable` when it is
// still a cell to the Voronoi checker: no edge collapsed (an exact edge of 1e-17 at a
// box corner rounds to zero length), closed, planar faces and convex within `tol`
// (faces below tol^2, whose plane rounding does not define, left out), or within what
// vertices `vertex_error` off allow a face's plane where that is more (the ulp floor,
// voronoi/cell_check.hpp: a face reaching a wall at 1e30 is planar only to its ulps).
struct Rounded {
  bool clean, representable;
};
Rounded judge_rounded(const ConvexCell& c, double tol, double vertex_error) {
  if (c.empty()) return {true, true};
  const VoronoiCell view = cell_view(c);
  if (!check_cell_closed(view).empty()) return {false, false};
  ConvexFindings found;
  const bool convex = check_cell_convex(view, {tol, true, vertex_error}, &found).empty();
  const bool tiny_face = found.skipped;
  const bool short_edge = has_edge_within(view, tol);  // implied by a collapsed one
  const bool representable = convex && !(short_edge && has_edge_within(view, 0));
  return {representable && !short_edge && !tiny_face, representable};
}

// Whether every vertex of `a` lies within `tol` of a vertex of `b`.
bool vertices_near(const ConvexCell& a, const ConvexCell& b, double tol) {
  for (const Point3& p : a.vertices()) {
    const auto& bv = b.vertices();
    if (std::none_of(bv.begin(), bv.end(), [&](const Point3& q) { return norm(p - q) <= tol; })) return false;
  }
  return true;
}

enum class CellChoice { exact, band, refused };

// Which of the exact cell and the band's cell an ambiguous cell keeps, in order (`scale`:
// cell_scale):
// - the exact one when it passes the cell check at half `--check`'s tolerance (1e-9 of
//   the scale): no short edge, no tiny face, planar, convex;
// - the band's when the two differ only by faces below kSmallFace of the scale
//   squared, the band's is closed, planar and convex and its vertices lie where
//   exact ones are (a grazing cut can move a band vertex by more than the Voronoi
//   checker's 1e-9);
// - the exact one when it survives rounding (its short edges are real);
// - the band's when the two differ only by faces below kSmallFace and it is closed;
// - neither. `off` is set to the largest face on which the two differ.
CellChoice choose_cell(const ConvexCell& band, const ConvexCell& exact, double scale, double vertex_error,
                       double& off) {
  const double tol = 0.5e-9 * scale;
  off = std::max(largest_face_missing(exact, band), largest_face_missing(band, exact));
  const bool small = off <= kSmallFace * scale * scale;
  const Rounded e = judge_rounded(exact, tol, vertex_error);
  if (e.clean) return CellChoice::exact;
  if (small && vertices_near(band, exact, tol) && judge_rounded(band, tol, vertex_error).representable)
    return CellChoice::band;
  if (e.representable) return CellChoice::exact;
  return small && check_cell_closed(cell_view(band)).empty() ? CellChoice::band : CellChoice::refused;
}

// `exact` (sites[i]'s exact cell, translated) redone without the bisectors whose
// faces are tiny, if that makes a cell doubles can hold. Near-degenerate sites give a
// cell that is exactly closed and convex but has a cluster of faces of 1e-14..1e-36
// of the scale squared whose corners round together (collapsed edges, open faces).
// The faces below each threshold in turn (1e-16 .. kSmallFace of `scale` squared,
// walls never) are dropped and the cell clipped again exactly by the other
// neighbours; the first result that survives rounding and grew by at most 1e-15 of
// `scale` cubed (a dropped face's plane only gives the cell a sliver back) is kept.
// The dropped faces are what the Voronoi checker calls small missing faces; every
// vertex is still exactly on its three planes before rounding.
bool drop_tiny_faces(ConvexCell& exact, std::span<const Point3> sites, std::uint32_t i,
                     std::span<const std::uint32_t> neighbors, const Box& box, double scale) {
  const double volume = exact.volume(), area_unit = scale * scale;
  std::vector<std::uint32_t> kept(neighbors.begin(), neighbors.end());
  std::vector<std::int32_t> tiny;
  for (const double fraction : {1e-16, 1e-14, 1e-12, kSmallFace}) {
    tiny.clear();
    for (std::size_t f = 0; f < exact.face_count(); ++f)
      if (exact.face_tag(f) >= 0 && face_area(exact, f) <= fraction * area_unit) tiny.push_back(exact.face_tag(f));
    if (tiny.empty()) continue;
    std::erase_if(kept, [&](std::uint32_t j) {
      return std::find(tiny.begin(), tiny.end(), static_cast<std::int32_t>(j)) != tiny.end();
    });
    exact_clip_cell(exact, sites, i, kept, box);
    exact.translate(sites[i]);
    if (exact.volume() - volume <= 1e-15 * area_unit * scale &&
        judge_rounded(exact, 0.5e-9 * scale, rounding_floor_distance(box)).representable)
      return true;
  }
  return false;
}

}  // namespace

bool compute_cell(ConvexCell& cell, std::span<const Point3> sites, std::uint32_t i,
                  std::span<const std::uint32_t> neighbors, const Box& box, double tol, double scale, double shrink) {
  const Point3 s = sites[i];
  cell.reset({box.lo - s, box.hi - s});
  const double band = tol * scale;
  for (auto j : neighbors) {
    // Bisector of s and sites[j], relative to s: n.x <= |n|^2 / 2 with n = p_j - s.
    const Point3 n = sites[j] - s;
    cell.clip(n, 0.5 * dot(n, n) - shrink * norm(n), static_cast<std::int32_t>(j), band);
    if (cell.empty()) break;
  }
  const bool exact = cell.ambiguous() && shrink == 0;
  cell.translate(s);
  if (!exact) return false;
  // A side decided inside the band (or the rounding) may be wrong and lose a whole
  // face of two close sites: redo the cell with exact signs and keep what
  // choose_cell says.
  thread_local ConvexCell exact_cell;
  exact_clip_cell(exact_cell, sites, i, neighbors, box);
  exact_cell.translate(s);
  double off = 0;
  switch (choose_cell(cell, exact_cell, scale, rounding_floor_distance(box), off)) {
    case CellChoice::exact: cell = exact_cell; return true;
    case CellChoice::band: return true;
    case CellChoice::refused: break;
  }
  // At the sites' scale in a far larger box, a cell whose exact form does not survive
  // rounding (cospherical sites: corners 1e-17 apart at the centre) and whose band is
  // below its far vertices' rounding (the band's clip then does not close) is redone
  // in the box's band, as before cell_scale: that band merges the corners.
  if (scale < box.diagonal()) return compute_cell(cell, sites, i, neighbors, box, tol, box.diagonal(), shrink);
  // Last: the exact cell without its faces far below rounding, if that is a cell.
  if (drop_tiny_faces(exact_cell, sites, i, neighbors, box, scale)) {
    cell = exact_cell;
    return true;
  }
  char fraction[32];
  std::snprintf(fraction, sizeof fraction, "%.3g", off / (scale * scale));
  throw UnrepresentableCell("the Voronoi cell of site " + std::to_string(i) +
                            " has faces that double precision cannot represent (a face of " + fraction +
                            " of the cells' scale squared is lost in rounding; voronoi.hpp's cell_scale)");
}

VoronoiCell cell_view(std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
                      std::span<const std::uint32_t> face_vertices, std::span<const std::int32_t> face_neighbor) {
  VoronoiCell c;
  c.vertices = vertices;
  c.face_offsets = face_offsets;
  c.face_vertices = face_vertices;
  c.face_neighbor = face_neighbor;
  return c;
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

void sort_by_distance(std::span<const Point3> p, std::uint32_t v, std::vector<std::uint32_t>& row) {
  std::sort(row.begin(), row.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Point3 da = p[a] - p[v], db = p[b] - p[v];
    const double la = dot(da, da), lb = dot(db, db);
    return la < lb || (la == lb && a < b);
  });
}

// The arrays of a finished cell, copied into the worker's arena.
void store(CellArena& arena, std::span<const Point3> v, std::span<const std::uint32_t> fo,
           std::span<const std::uint32_t> fv, std::span<const std::int32_t> fn, VoronoiCell& out) {
  out.vertices = arena.copy(v);
  out.face_offsets = arena.copy(fo);
  out.face_vertices = arena.copy(fv);
  out.face_neighbor = arena.copy(fn);
}

void store(CellArena& arena, const ConvexCell& c, VoronoiCell& out) {
  store(arena, c.vertices(), c.face_offsets(), c.face_vertices(), c.face_tags(), out);
  out.volume = c.volume();
  out.centroid = c.centroid();
}

}  // namespace

namespace {

// Volume and centroid of a polytope, cones from `o` (near the cell: keeps the
// magnitudes local).
void measure(const CellBuffer& c, const Point3& o, VoronoiCell& out) {
  double vol = 0;
  Point3 m{0, 0, 0};
  for (std::size_t f = 0; f + 1 < c.face_offsets.size(); ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    const Point3 a = c.vertices[c.face_vertices[b]] - o;
    for (auto k = b + 1; k + 1 < e; ++k) {
      const Point3 p = c.vertices[c.face_vertices[k]] - o, q = c.vertices[c.face_vertices[k + 1]] - o;
      const double w = det3(a, p, q);
      vol += w;
      m = m + w * (a + p + q);
    }
  }
  out.volume = vol / 6;
  out.centroid = vol != 0 ? o + 1.0 / (4 * vol) * m : o;
}

// The tets with vertices renamed by rank, in a stable counting sort by their lowest
// rank (the first cell that reaches them).
std::vector<Tet> sort_by_first_cell(std::span<const Tet> tets, std::span<const std::uint32_t> rank) {
  std::vector<std::uint32_t> key(tets.size()), off(rank.size() + 1, 0);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& q = tets[t];
    key[t] = std::min(std::min(rank[q[0]], rank[q[1]]), std::min(rank[q[2]], rank[q[3]]));
    ++off[key[t] + 1];
  }
  for (std::size_t k = 0; k + 1 < off.size(); ++k) off[k + 1] += off[k];
  std::vector<Tet> out(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& q = tets[t];
    out[off[key[t]]++] = {rank[q[0]], rank[q[1]], rank[q[2]], rank[q[3]]};
  }
  return out;
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A circumcentre whose relative error amplification exceeds this is not trusted for a
// dual cell (error ~ condition * 1e-16 of the tet size).
constexpr double kMaxCondition = 1e4;

bool finite(const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Stage 1: refuses sites, a margin or a box that no cell could be computed from.
void check_voronoi_input(std::span<const Point3> sites, const VoronoiOptions& o) {
  if (sites.empty()) throw std::invalid_argument("no sites");
  for (std::size_t i = 0; i < sites.size(); ++i)
    if (!finite(sites[i]))
      throw std::invalid_argument("voronoi: site " + std::to_string(i) + " has a non-finite coordinate");
  if (!(std::isfinite(o.margin) && o.margin >= 0)) throw std::invalid_argument("voronoi: margin must be finite and >= 0");
  if (o.box && !(finite(o.box->lo) && finite(o.box->hi)))
    throw std::invalid_argument("voronoi: the box has a non-finite coordinate");
}

// Stage 2 when the DT has no volume (fewer than four distinct or coplanar sites):
// every other site is a candidate neighbour of each cell.
void all_pairs_cells(std::span<const Point3> sites, const std::vector<std::int64_t>& dup, const VoronoiOptions& o,
                     VoronoiDiagram& vd) {
  if (sites.size() > 4096) throw std::runtime_error("coplanar input too large for all-pairs cells");
  ConvexCell cell;
  std::vector<std::uint32_t> row;
  auto storage = std::make_shared<std::vector<CellArena>>(1);
  for (std::uint32_t v = 0; v < sites.size(); ++v) {
    if (dup[v] >= 0) {
      vd.cells[v].duplicate_of = dup[v];
      continue;
    }
    row.clear();
    for (std::uint32_t w = 0; w < sites.size(); ++w)
      if (w != v && dup[w] < 0) row.push_back(w);
    sort_by_distance(sites, v, row);
    vd.exact_clipped += compute_cell(cell, sites, v, row, vd.box, o.tolerance, vd.scale, o.shrink);
    store(storage->front(), cell, vd.cells[v]);
  }
  vd.storage = std::move(storage);
  vd.clipped = sites.size();
}

// The DT renumbered for locality: cells in the order of their first tet (the tets come
// out of the DT in spatial, insertion order, so neighbouring cells are near each other;
// sites in no tet, the duplicates, go last), sites by that rank, and tets in the order
// the cells first reach them, so that the stars, tets and centres of consecutive cells
// lie in nearby memory instead of all over the mesh.
struct RankedDelaunay {
  std::vector<std::uint32_t> order;  // site of each rank
  std::vector<Tet> tets;             // over ranks
  std::vector<Point3> sites;         // by rank
  std::vector<char> duplicate;       // by rank
};

// Stage 3: ranks the sites and sorts the tets (consumes `tets`).
RankedDelaunay rank_by_first_cell(std::vector<Tet>& tets, std::span<const Point3> sites,
                                  const std::vector<std::int64_t>& dup) {
  const std::size_t n = sites.size();
  RankedDelaunay r;
  r.order.reserve(n);
  std::vector<std::uint32_t> rank(n, kNone);
  for (const auto& q : tets)
    for (auto v : q)
      if (rank[v] == kNone) rank[v] = static_cast<std::uint32_t>(r.order.size()), r.order.push_back(v);
  for (std::uint32_t v = 0; v < n; ++v)
    if (rank[v] == kNone) r.order.push_back(v);
  r.tets = sort_by_first_cell(tets, rank);
  std::vector<std::uint32_t>().swap(rank);
  tets = {};
  r.sites.resize(n);
  r.duplicate.resize(n);
  for (std::size_t k = 0; k < n; ++k) r.sites[k] = sites[r.order[k]], r.duplicate[k] = dup[r.order[k]] >= 0;
  return r;
}

// Every vertex's star and every tet's circumcentre (with whether it is too
// ill-conditioned to trust).
struct StarsAndCentres {
  std::vector<std::uint32_t> star_off, star;
  std::vector<Point3> centre;
  std::vector<char> bad;
};

// Stage 4: the stars (one task) while other workers compute the circumcentres (chunks
// of 4096 tets); with one thread, one after the other.
StarsAndCentres stars_and_centres(const RankedDelaunay& dt, unsigned threads) {
  const std::vector<Tet>& tets = dt.tets;
  StarsAndCentres sc;
  sc.centre.resize(tets.size());
  sc.bad.resize(tets.size());
  constexpr std::size_t kChunk = 4096;
  parallel_chunks(1 + (tets.size() + kChunk - 1) / kChunk, threads, 1, [&](std::size_t job, std::size_t, unsigned) {
    if (job == 0) return vertex_stars(dt.sites.size(), tets, sc.star_off, sc.star);
    for (std::size_t t = (job - 1) * kChunk, e = std::min(tets.size(), job * kChunk); t < e; ++t) {
      const Tet& q = tets[t];
      double cond = 0;
      sc.centre[t] = circumcenter(dt.sites[q[0]], dt.sites[q[1]], dt.sites[q[2]], dt.sites[q[3]], &cond);
      sc.bad[t] = !(cond <= kMaxCondition);
    }
  });
  return sc;
}

// A worker's reusable state for stage 5.
struct CellScratch {
  explicit CellScratch(std::size_t n) : builder(n) {}
  DualCellBuilder builder;
  ConvexCell cell;
  std::vector<std::uint32_t> row;
  CellBuffer buffer;
  CellArena arena;
};

// The box walls a dual cell crosses or comes within the band of (where the clip
// decides whether it crosses): bit 2k the low wall of axis k, bit 2k+1 the high one.
int crossed_walls(const CellBuffer& buf, const Box& box, double band) {
  int walls = 0;
  for (const auto& p : buf.vertices) {
    walls |= (p.x < box.lo.x + band) << 0 | (p.x > box.hi.x - band) << 1;
    walls |= (p.y < box.lo.y + band) << 2 | (p.y > box.hi.y - band) << 3;
    walls |= (p.z < box.lo.z + band) << 4 | (p.z > box.hi.z - band) << 5;
  }
  return walls;
}

// The dual cell in `sc.buffer` (site s) clipped by the walls it crosses, into `out`;
// false (nothing stored) when a wall decision was ambiguous: the caller clips the
// cell from its neighbours instead, with its exact fallback.
bool clip_dual_to_walls(CellScratch& sc, const Point3& s, int walls, const Box& box, double band, VoronoiCell& out) {
  ConvexCell& cell = sc.cell;
  const CellBuffer& buf = sc.buffer;
  cell.assign(buf.vertices, buf.face_offsets, buf.face_vertices, buf.face_neighbor, s);
  const Point3 lo = box.lo - s, hi = box.hi - s;
  const Point3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double los[3] = {lo.x, lo.y, lo.z}, his[3] = {hi.x, hi.y, hi.z};
  for (int k = 0; k < 3 && !cell.empty(); ++k) {
    if (walls >> (2 * k) & 1) cell.clip(-1 * axis[k], -los[k], -1 - 2 * k, band);
    if (walls >> (2 * k + 1) & 1) cell.clip(axis[k], his[k], -2 - 2 * k, band);
  }
  if (cell.ambiguous()) return false;
  cell.translate(s);
  store(sc.arena, cell, out);
  return true;
}

// What stage 5 did with one cell.
enum class CellPath { duplicate, dual, dual_box_clipped, clipped, clipped_exact };

// Stage 5, one cell (rank rk): the dual of its star when it can be trusted (clipped by
// the box walls it crosses), else clipped from the bisectors of its DT neighbours.
CellPath one_cell(std::size_t rk, std::span<const Point3> sites, const std::vector<std::int64_t>& dup,
                  const RankedDelaunay& dt, const StarsAndCentres& sc, const VoronoiOptions& o, double band,
                  CellScratch& scratch, VoronoiDiagram& vd) {
  const std::uint32_t i = dt.order[rk];
  VoronoiCell& out = vd.cells[i];
  const auto r = static_cast<std::uint32_t>(rk);
  const std::span<const std::uint32_t> st(sc.star.data() + sc.star_off[r], sc.star_off[r + 1] - sc.star_off[r]);
  if (dt.duplicate[r]) {
    out.duplicate_of = dup[i];
    return CellPath::duplicate;
  }
  const Point3 s = dt.sites[r];
  const bool dual_ok = o.shrink == 0;
  CellBuffer& buf = scratch.buffer;
  if (dual_ok && scratch.builder.build(r, st, dt.tets, sc.centre, sc.bad, band, 1e4 * band, buf)) {
    for (auto& f : buf.face_neighbor) f = static_cast<std::int32_t>(dt.order[f]);
    const int walls = crossed_walls(buf, vd.box, band);
    if (!walls) {
      measure(buf, s, out);
      store(scratch.arena, buf.vertices, buf.face_offsets, buf.face_vertices, buf.face_neighbor, out);
      return CellPath::dual;
    }
    if (clip_dual_to_walls(scratch, s, walls, vd.box, band, out)) return CellPath::dual_box_clipped;
  } else if (!dual_ok) {
    scratch.builder.gather(r, st, dt.tets, sc.bad);
  }
  scratch.row.clear();
  for (auto w : scratch.builder.neighbors()) scratch.row.push_back(dt.order[w]);
  sort_by_distance(sites, i, scratch.row);
  const bool exact = compute_cell(scratch.cell, sites, i, scratch.row, vd.box, o.tolerance, vd.scale, o.shrink);
  store(scratch.arena, scratch.cell, out);
  return exact ? CellPath::clipped_exact : CellPath::clipped;
}

// Stage 5: every cell, in rank order, in chunks over the threads; the cells' storage
// (one arena per worker) then goes to the diagram.
void dual_cells(std::span<const Point3> sites, const std::vector<std::int64_t>& dup, const RankedDelaunay& dt,
                const StarsAndCentres& sc, const VoronoiOptions& o, unsigned threads, VoronoiDiagram& vd) {
  const double band = o.tolerance * vd.scale;
  std::atomic<std::size_t> clipped{0}, box_clipped{0}, exact{0};
  std::vector<std::unique_ptr<CellScratch>> scratch(threads);
  parallel_chunks(sites.size(), threads, 256, [&](std::size_t b, std::size_t e, unsigned w) {
    if (!scratch[w]) scratch[w] = std::make_unique<CellScratch>(sites.size());
    std::size_t n_clip = 0, n_box = 0, n_exact = 0;
    for (std::size_t k = b; k < e; ++k) {
      // The cells are stored by site id, in no spatial order: fetch the next one early.
      if (k + 1 < e) __builtin_prefetch(&vd.cells[dt.order[k + 1]], 1);
      const CellPath path = one_cell(k, sites, dup, dt, sc, o, band, *scratch[w], vd);
      n_clip += path == CellPath::clipped || path == CellPath::clipped_exact;
      n_exact += path == CellPath::clipped_exact;
      n_box += path == CellPath::dual_box_clipped;
    }
    clipped += n_clip;
    box_clipped += n_box;
    exact += n_exact;
  });
  auto storage = std::make_shared<std::vector<CellArena>>();
  for (auto& s : scratch)
    if (s) storage->push_back(std::move(s->arena));
  vd.storage = std::move(storage);
  vd.clipped = clipped;
  vd.box_clipped = box_clipped;
  vd.exact_clipped = exact;
}

}  // namespace

VoronoiDiagram compute_voronoi(std::span<const Point3> sites, const VoronoiOptions& o) {
  check_voronoi_input(sites, o);
  VoronoiDiagram vd;
  vd.sites.assign(sites.begin(), sites.end());
  vd.box = o.box ? *o.box : default_box(sites, o.margin);
  if (!(finite(vd.box.lo) && finite(vd.box.hi)))
    throw std::invalid_argument("voronoi: the box overflows (coordinates or margin too large)");
  vd.scale = cell_scale(vd.box, sites);
  vd.cells.resize(sites.size());
  const auto dup = find_duplicates(sites);
  const unsigned threads = thread_count(o.threads);

  auto t0 = Clock::now();
  // The DT is kept only from exact predicates with perturbation (the checker's relation).
  const bool keep_dt =
      o.keep_dt && o.predicates.perturb && (o.predicates.backend == "adaptive" || o.predicates.backend == "exact");
  BuildOptions build = o.build;
  build.keep_adjacency = keep_dt;  // the checker's tables then pair no facets
  BuildResult r = build_delaunay(sites, o.predicates, build);
  vd.tets = r.mesh.tets.size();
  if (r.failure && r.failure->kind != FailureKind::lower_dimensional)
    throw std::runtime_error("Delaunay build failed: " + r.failure->detail);
  vd.seconds_dt = since(t0);
  t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  if (r.failure) {
    all_pairs_cells(sites, dup, o, vd);
  } else {
    // Points and tets copied (ranking consumes the tets); the adjacency, unused here, moved.
    if (keep_dt)
      vd.dt = std::make_shared<const Tetrahedralization>(
          Tetrahedralization{r.mesh.points, r.mesh.tets, std::move(r.mesh.adjacency)});
    const RankedDelaunay dt = rank_by_first_cell(r.mesh.tets, sites, dup);
    const StarsAndCentres sc = stars_and_centres(dt, threads);
    dual_cells(sites, dup, dt, sc, o, threads, vd);
  }
  vd.seconds_cells = since(t0);
  vd.cpu_seconds_cells = double(std::clock() - c0) / CLOCKS_PER_SEC;
  return vd;
}

}  // namespace dtlab
