#include "voronoi_check/voronoi_check.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <stdexcept>

#include "kernel/parallel_for.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/convex_cell.hpp"
#include "voronoi_check/cell_geometry.hpp"
#include "voronoi_check/voronoi_neighbors.hpp"

namespace dtlab {

using namespace vor;

const char* voronoi_defect_name(VoronoiDefect d) {
  static const char* names[kVoronoiDefects] = {
      "missing-cell",    "extra-cell",   "missing-face", "spurious-face", "small-missing-face", "small-spurious-face",
      "degenerate-face", "bad-neighbor", "vertex-off",   "not-convex",    "volume-mismatch"};
  return names[static_cast<int>(d)];
}

const char* topology_name(Topology t) {
  return t == Topology::exact ? "exact-topology" : t == Topology::rounded ? "rounded-topology" : "wrong-topology";
}

const char* voronoi_verdict_name(VoronoiVerdict v) {
  static const char* names[] = {"exact-topology", "rounded-topology", "bad-geometry", "volume-mismatch",
                                "wrong-topology", "crashed",          "hung",         "refused",
                                "not-installed",  "out-of-memory"};
  return names[static_cast<int>(v)];
}

std::string voronoi_counts_text(const VoronoiCheckReport& r) {
  std::string s;
  for (int k = 0; k < kVoronoiDefects; ++k)
    if (r.counts[k]) {
      if (!s.empty()) s += ", ";
      s += voronoi_defect_name(static_cast<VoronoiDefect>(k));
      s += ' ';
      s += std::to_string(r.counts[k]);
    }
  return s;
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double sites_extent(std::span<const Point3> sites, const Box& box) {
  Box b{sites[0], sites[0]};
  for (const auto& p : sites) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  const Point3 e = b.hi - b.lo;
  const double ext = std::max({e.x, e.y, e.z});
  return ext > 0 ? ext : box.diagonal();
}

// A face's area and diameter (the largest distance of two of its vertices).
struct FaceSize {
  double area = 0, diameter = 0;
};

// The largest distance between two corners of a polygon (corner ids into `vertices`).
double polygon_diameter(std::span<const Point3> vertices, std::span<const std::uint32_t> corners) {
  double d = 0;
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = i + 1; j < corners.size(); ++j)
      d = std::max(d, norm(vertices[corners[i]] - vertices[corners[j]]));
  return d;
}

// One directed face of a tool's cell, merged by neighbour (a tool may split a face).
// Its area is needed only for a face that is not expected: computed then (area < 0:
// not yet; a split face's parts are summed at once).
struct ToolFace {
  std::uint32_t neighbor;  // representative site
  std::int64_t id;         // the id the tool wrote
  std::uint32_t face;      // the tool's face (the first one of a split face)
  double area;
};

// What one chunk of sites or cells found: merged in chunk order, so the report does
// not depend on the thread count (the chunks are fixed, the threads only run them).
struct Partial {
  std::array<std::uint64_t, kVoronoiDefects> counts{};
  std::vector<VoronoiWitness> witnesses;
  double largest_wrong_face = 0, largest_small_face = 0, max_vertex_ulps = 0, max_vertex_error = 0;
  double max_vertex_distance = 0;  // the chunk's largest vertex distance solved (absolute)
  double volume_sum = 0;
  double volume_bound = 0, surface = 0;  // the volume floor's sums over cells (computed only when needed)
  std::uint64_t faces = 0, vertices = 0, voronoi_edges = 0, degenerate_edges = 0;
  std::uint64_t not_closed = 0;  // cells the volume bound does not hold for
  bool convex_widened = false;   // a face's convexity tolerance was the ulp floor's
  bool small_by_ulps = false;    // a face small only by the ulp floor
};

// One thread's scratch (no allocation per site or cell once warm).
struct Scratch {
  std::vector<std::uint32_t> pos, deg, all;
  std::vector<ToolFace> tf;
  std::vector<VertexError> errors;
  CellIncidence incidence;  // of the cell being judged
  std::vector<Point3> centres;
  NeighborScratch ring;
  ConvexCell clipped;
  std::uint32_t clipped_site = 0xFFFFFFFFu;
};

constexpr std::size_t kChunk = 256;  // sites or cells per chunk

std::shared_ptr<const VoronoiNeighbors> relation(std::span<const Point3> sites, const VoronoiCheckOptions& o) {
  if (!o.relation) return voronoi_relation(sites, o);
  if (o.relation->site_count() != sites.size()) throw std::invalid_argument("the relation is not of these sites");
  return o.relation;
}

// The state of one check: the exact relation, the tool's cells by site, the report.
class Judge {
 public:
  Judge(std::span<const Point3> sites, const Box& box, const ToolCells& cells, const VoronoiCheckOptions& o,
        VoronoiCheckReport& r)
      : sites_(sites), box_(box), cells_(cells), o_(o), r_(r) {
    extent2_ = sites_extent(sites, box);
    scale_ = cell_scale(box, sites);
    extent2_ *= extent2_;
    // The tolerances: the relative bound, or K ulps of the box's largest coordinate.
    auto& t = r_.tolerances;
    ulp_ = t.ulp = box_ulp(box);
    // Relative to the cells' scale (cell_scale, voronoi/voronoi.hpp: the box diagonal, or
    // the sites' default box's where that is shorter), as our own cells' tolerances: of
    // the diagonal of a box far larger than the sites, 1e-9 let vertices be off by far
    // more than the cells' size (35 in a box of +-1e10 around the unit cube).
    const double ulp_floor = o.ulps * ulp_;
    vertex_tol_ = std::max(o.vertex_tolerance * scale_, ulp_floor);
    t.vertex = {vertex_tol_ / scale_, ulp_floor > o.vertex_tolerance * scale_};
    // Convexity: per face, the relative tolerance or what vertices within the floor
    // allow for that face's computed plane (voronoi/cell_check.hpp).
    convex_tol_ = o.convex_tolerance * scale_;
    vertex_error_ = t.floor_distance = std::sqrt(3.0) * ulp_floor;  // the floor as a Euclidean distance
    t.convex = {o.convex_tolerance, false};
    t.small_face = {o.small_face, false};
    small_face_ = o.small_face;
  }

  void run() {
    const unsigned threads = thread_count(o_.threads);
    scratch_.resize(threads);
    std::vector<Partial> geometry;
    if (o_.relation || o_.dt || threads < 2) {
      shared_ = relation(sites_, o_);
      geometry = judge_geometry_stage(threads);
    } else
      geometry = build_relation_beside_geometry(threads);
    nb_ = shared_.get();
    Partial cells;
    assign_cells(cells);
    merge(cells);
    auto t = Clock::now();
    relation_stage(threads);
    r_.seconds_relation = since(t);
    merge_all(std::move(geometry));
    t = Clock::now();
    judge_volume(threads);
    r_.seconds_geometry += since(t);
    if (!o_.relation) r_.seconds_dt = nb_->seconds_dt, r_.seconds_tables = nb_->seconds_tables;
    // One representative per set of equal sites (the relation's, no second sort).
    for (std::size_t i = 0; i < sites_.size(); ++i) r_.distinct_sites += nb_->rep(static_cast<std::uint32_t>(i)) == i;
  }

 private:
  // The geometry stage reads neither the DT nor its tables: with two or more threads
  // and a DT to build, it runs on half of them beside the build rather than after it
  // (the build gains little from a second thread at 10^5 sites, the cells nearly 2x),
  // and sorts the sites' representatives for the relation when done; the tables then
  // take every thread. Returns the geometry's findings, merged by run() after the
  // relation's, so the report does not depend on the thread count. The build's refusal
  // of the sites is rethrown first, whatever the other task threw.
  std::vector<Partial> build_relation_beside_geometry(unsigned threads) {
    const unsigned beside = threads / 2;
    std::vector<Partial> geometry;
    std::shared_ptr<const Tetrahedralization> dt;
    std::exception_ptr refused;
    double seconds_dt = 0;
    std::vector<std::uint32_t> reps;
    parallel_chunks(2, 2, 1, [&](std::size_t task, std::size_t, unsigned) {
      if (task == 1) {
        geometry = judge_geometry_stage(beside);
        if (std::all_of(sites_.begin(), sites_.end(), is_finite)) reps = site_representatives(sites_);
        return;
      }
      const auto t = Clock::now();
      try {
        dt = exact_delaunay(sites_, threads - beside);
      } catch (...) {
        refused = std::current_exception();
      }
      seconds_dt = since(t);
    });
    if (refused) std::rethrow_exception(refused);
    shared_ = std::make_shared<VoronoiNeighbors>(sites_, std::move(dt), threads, seconds_dt, std::move(reps));
    return geometry;
  }

  // Stage 2 over every site with a cell, in the cells' order (a tool's cells are read as
  // stored, and a tool's order, voro++'s blocks, is not the sites'), then over the sites
  // without one.
  void relation_stage(unsigned threads) {
    const std::size_t nc = cells_.size();
    merge_all(stage(nc + sites_.size(), threads, [&](std::size_t i, Partial& p, Scratch& s) {
      if (i < nc) {
        if (primary_[i]) judge_site(nb_->rep(static_cast<std::uint32_t>(cells_.site(i))), i, p, s);
        return;
      }
      const auto a = static_cast<std::uint32_t>(i - nc);
      if (nb_->rep(a) == a && cell_of_[a] < 0) judge_cellless(a, p, s);
    }));
  }

  // Stage 3 over every cell on `threads` threads (scratch 0..threads-1), unmerged.
  std::vector<Partial> judge_geometry_stage(unsigned threads) {
    const auto t = Clock::now();
    auto parts = stage(cells_.size(), threads, [&](std::size_t c, Partial& p, Scratch& s) { judge_geometry(c, p, s); });
    r_.seconds_geometry = since(t);
    return parts;
  }

  // f(i, partial, scratch) for i in [0, n), in fixed chunks on `threads` threads; the
  // chunks' findings, in order, for merge_all.
  template <class F>
  std::vector<Partial> stage(std::size_t n, unsigned threads, F&& f) {
    std::vector<Partial> parts((n + kChunk - 1) / kChunk);
    parallel_chunks(n, threads, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      Partial& p = parts[b / kChunk];
      for (std::size_t i = b; i < e; ++i) f(i, p, scratch_[w]);
    });
    return parts;
  }

  void merge_all(std::vector<Partial>&& parts) {
    for (auto& p : parts) merge(p);
  }

  void merge(Partial& p) {
    for (auto& w : p.witnesses)
      if (std::count_if(r_.witnesses.begin(), r_.witnesses.end(), [&](const VoronoiWitness& x) {
            return x.kind == w.kind;
          }) < static_cast<std::ptrdiff_t>(o_.witnesses_per_kind))
        r_.witnesses.push_back(std::move(w));
    for (int k = 0; k < kVoronoiDefects; ++k) r_.counts[k] += p.counts[k];
    r_.largest_wrong_face = std::max(r_.largest_wrong_face, p.largest_wrong_face);
    r_.largest_small_face = std::max(r_.largest_small_face, p.largest_small_face);
    r_.max_vertex_ulps = std::max(r_.max_vertex_ulps, p.max_vertex_ulps);
    r_.max_vertex_error = std::max(r_.max_vertex_error, p.max_vertex_error);
    r_.volume_sum += p.volume_sum;
    volume_bound_ += p.volume_bound, surface_ += p.surface;
    not_closed_ += p.not_closed;
    r_.tolerances.convex.ulps |= p.convex_widened;
    r_.tolerances.small_face.ulps |= p.small_by_ulps;
    r_.faces += p.faces, r_.vertices += p.vertices;
    r_.voronoi_edges += p.voronoi_edges, r_.degenerate_edges += p.degenerate_edges;
  }

  void add(Partial& p, VoronoiDefect k, std::int64_t site, std::int64_t neighbor, double size,
           std::string detail = {}) const {
    if (p.counts[static_cast<int>(k)]++ < o_.witnesses_per_kind)
      p.witnesses.push_back({k, site, neighbor, size, std::move(detail)});
  }

  // Stage 1: one non-empty cell per set of copies of a site.
  void assign_cells(Partial& p) {
    cell_of_.assign(sites_.size(), -1);
    primary_.assign(cells_.size(), 0);
    for (std::size_t c = 0; c < cells_.size(); ++c) {
      const std::int64_t s = cells_.site(c);
      if (cells_.face_count(c) == 0) continue;
      ++r_.cells;
      if (s < 0 || static_cast<std::size_t>(s) >= sites_.size()) {
        add(p, VoronoiDefect::extra_cell, s, -1, 0, "a cell of no site");
        continue;
      }
      auto& slot = cell_of_[nb_->rep(static_cast<std::uint32_t>(s))];
      if (slot >= 0)
        add(p, VoronoiDefect::extra_cell, s, cells_.site(slot), 0, "a second cell for this site or a copy of it");
      else {
        slot = static_cast<std::int64_t>(c);
        primary_[c] = 1;
      }
    }
  }

  void tool_faces(const VoronoiCell& c, std::uint32_t a, std::vector<ToolFace>& out, Partial& p) const {
    out.clear();
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      const std::int32_t id = c.face_neighbor[f];
      if (id < 0) continue;
      if (static_cast<std::size_t>(id) >= sites_.size()) {
        add(p, VoronoiDefect::bad_neighbor, a, id, 0, "neighbour id is no site");
        continue;
      }
      out.push_back({nb_->rep(static_cast<std::uint32_t>(id)), id, static_cast<std::uint32_t>(f), -1.0});
    }
    std::sort(out.begin(), out.end(), [](const ToolFace& x, const ToolFace& y) { return x.neighbor < y.neighbor; });
    std::size_t k = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (k > 0 && out[k - 1].neighbor == out[i].neighbor) {
        if (out[k - 1].area < 0) out[k - 1].area = face_area(c, out[k - 1].face);
        out[k - 1].area += face_area(c, out[i].face);
      } else
        out[k++] = out[i];
    }
    out.resize(k);
  }

  // A bounded exact face (an interior DT edge) whose every vertex (the ring's
  // centres, in doubles) lies beyond one wall by more than 1e-9 of the diagonal, or
  // the ulp floor where that is larger, cannot meet the box: the clip below is not needed.
  bool beyond_a_wall(const std::vector<Point3>& centres) const {
    const double m = std::max(1e-9 * box_.diagonal(), o_.ulps * ulp_);
    const double lo[3] = {box_.lo.x, box_.lo.y, box_.lo.z}, hi[3] = {box_.hi.x, box_.hi.y, box_.hi.z};
    for (int axis = 0; axis < 3; ++axis) {
      const auto coord = [axis](const Point3& c) { return axis == 0 ? c.x : axis == 1 ? c.y : c.z; };
      if (std::all_of(centres.begin(), centres.end(), [&](const Point3& c) { return coord(c) < lo[axis] - m; }) ||
          std::all_of(centres.begin(), centres.end(), [&](const Point3& c) { return coord(c) > hi[axis] + m; }))
        return true;
    }
    return false;
  }

  // The exact face of (a, b) clipped to the box, in doubles: its area and diameter, or
  // nullopt when it does not meet the box interior. The clip's band is our cells' (1e-12 of
  // cell_scale): it moves an area by far less than small_face, and above the vertices'
  // rounding bounds, so only a truly ambiguous cell is redone with exact signs (a band
  // below them, as 1e-15 was, sent every clipped cell to GMP).
  std::optional<FaceSize> true_area(std::uint32_t a, std::uint32_t b, Scratch& s) const {
    nb_->ring_centres(a, b, s.centres);
    const bool bounded = !nb_->hull_edge(a, b) && !s.centres.empty();
    if (bounded && beyond_a_wall(s.centres)) return std::nullopt;
    if (s.clipped_site != a) {
      s.all.assign(s.pos.begin(), s.pos.end());
      s.all.insert(s.all.end(), s.deg.begin(), s.deg.end());
      compute_cell(s.clipped, sites_, a, s.all, box_, VoronoiOptions{}.tolerance, scale_);
      s.clipped_site = a;
    }
    FaceSize size;
    const ConvexCell& cc = s.clipped;
    for (std::size_t f = 0; f < cc.face_count(); ++f)
      if (cc.face_tag(f) == static_cast<std::int32_t>(b)) {
        const auto fv = cc.face(f);
        const Point3 o = cc.vertices()[fv[0]];
        Point3 n{0, 0, 0};
        for (std::size_t k = 1; k + 1 < fv.size(); ++k)
          n = n + cross(cc.vertices()[fv[k]] - o, cc.vertices()[fv[k + 1]] - o);
        size.area += 0.5 * std::hypot(n.x, n.y, n.z);  // no overflow of |n|^2 in a box at 1e100
        size.diameter = std::max(size.diameter, polygon_diameter(cc.vertices(), fv));
      }
    if (size.area > 0) return size;
    // Rounded away by the clip: required when a vertex of the exact face is inside the box.
    for (const auto& c : s.centres)
      if (c.x > box_.lo.x && c.x < box_.hi.x && c.y > box_.lo.y && c.y < box_.hi.y && c.z > box_.lo.z &&
          c.z < box_.hi.z)
        return FaceSize{};
    return std::nullopt;
  }

  // Small: at most small_face of the extent squared, or (the ulp floor) no wider than
  // 2 e, e the floor's Euclidean vertex bound: a face that vertices within e of their
  // exact places can flatten (area <= 2 e diameter holds for every face of width at most
  // 2 e, and implies a width of at most 4 e for a convex one).
  // The diameter is asked for only when the relative bound does not decide.
  template <class Diameter>
  bool is_small_face(double area, Diameter&& diameter, Partial& p) const {
    if (area / extent2_ <= small_face_) return true;
    if (!(vertex_error_ > 0 && area <= 2 * vertex_error_ * diameter())) return false;
    p.small_by_ulps = true;
    return true;
  }

  void face_defect(Partial& p, bool missing, std::uint32_t a, std::int64_t b, const FaceSize& size) const {
    const double rel = size.area / extent2_;
    if (is_small_face(size.area, [&] { return size.diameter; }, p)) {
      add(p, missing ? VoronoiDefect::small_missing_face : VoronoiDefect::small_spurious_face, a, b, rel);
      p.largest_small_face = std::max(p.largest_small_face, rel);
    } else {
      add(p, missing ? VoronoiDefect::missing_face : VoronoiDefect::spurious_face, a, b, rel);
      p.largest_wrong_face = std::max(p.largest_wrong_face, rel);
    }
  }

  // Site a's exact neighbours into s.pos (positive faces) and s.deg (zero-area), counted.
  void exact_neighbors(std::uint32_t a, Partial& p, Scratch& s) const {
    nb_->neighbors(a, s.pos, s.deg, s.ring);
    p.voronoi_edges += s.pos.size();
    p.degenerate_edges += s.deg.size();
  }

  // A site without a cell: missing when inside the box, or when its exact cell meets it.
  void judge_cellless(std::uint32_t a, Partial& p, Scratch& s) const {
    exact_neighbors(a, p, s);
    if (box_.contains(sites_[a])) {
      add(p, VoronoiDefect::missing_cell, a, -1, 0);
      return;
    }
    for (auto b : s.pos)
      if (true_area(a, b, s)) {
        add(p, VoronoiDefect::missing_cell, a, -1, 0, "site outside the box, its cell meets it");
        return;
      }
  }

  // Stage 2: the neighbour set of representative site a against its cell c's.
  void judge_site(std::uint32_t a, std::size_t c, Partial& p, Scratch& s) const {
    exact_neighbors(a, p, s);
    const VoronoiCell cell = cells_.view(c);
    tool_faces(cell, a, s.tf, p);
    std::size_t i = 0;
    for (auto b : s.pos) {
      while (i < s.tf.size() && s.tf[i].neighbor < b) unexpected(a, cell, s.tf[i++], p, s);
      if (i < s.tf.size() && s.tf[i].neighbor == b) {
        ++i;
        continue;
      }
      if (const auto size = true_area(a, b, s)) face_defect(p, true, a, b, *size);
    }
    while (i < s.tf.size()) unexpected(a, cell, s.tf[i++], p, s);
  }

  // A tool face towards a site that is no Voronoi neighbour of a (its diameter over
  // every part of a split face).
  void unexpected(std::uint32_t a, const VoronoiCell& c, const ToolFace& f, Partial& p, const Scratch& s) const {
    FaceSize size{f.area < 0 ? face_area(c, f.face) : f.area, -1};
    const auto diameter = [&] {
      if (size.diameter >= 0) return size.diameter;
      size.diameter = 0;
      for (std::size_t g = 0; g < c.face_count(); ++g) {
        const std::int32_t id = c.face_neighbor[g];
        if (id < 0 || static_cast<std::size_t>(id) >= sites_.size() ||
            nb_->rep(static_cast<std::uint32_t>(id)) != f.neighbor)
          continue;
        const auto b = c.face_offsets[g], e = c.face_offsets[g + 1];
        size.diameter = std::max(size.diameter, polygon_diameter(c.vertices, c.face_vertices.subspan(b, e - b)));
      }
      return size.diameter;
    };
    const bool dt_edge = std::binary_search(s.deg.begin(), s.deg.end(), f.neighbor);
    if (dt_edge && is_small_face(size.area, diameter, p)) {
      add(p, VoronoiDefect::degenerate_face, a, f.id, size.area / extent2_, "exact face has zero area");
      return;
    }
    face_defect(p, false, a, f.id, FaceSize{size.area, diameter()});
  }

  // A vertex far from its site (a hull cell's corner on the wall of a box much larger
  // than the sites) is fixed by planes whose rounding moves it in proportion to that
  // distance: its relative tolerance is of the distance (max-norm) where that exceeds
  // the cells' scale.
  double far_vertex_tolerance(const Point3& v, const Point3& site) const {
    const Point3 d = v - site;
    return o_.vertex_tolerance * std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  }

  // Stage 3: one cell's shape, vertices and volume.
  void judge_geometry(std::size_t k, Partial& p, Scratch& s) const {
    const VoronoiCell c = cells_.view(k);
    if (c.face_count() == 0) return;
    const std::int64_t site = cells_.site(k);
    prefetch_face_sites(c, sites_);
    p.faces += c.face_count();
    p.vertices += c.vertices.size();
    cell_incidence(c, s.incidence);
    ConvexFindings found;  // its volume from the face normals, when the test ran through
    std::string why = check_cell_closed(c, s.incidence);
    if (!why.empty())
      ++p.not_closed;
    else
      why = check_cell_convex(c, {convex_tol_, true, vertex_error_}, &found);
    p.convex_widened = p.convex_widened || found.widened;
    p.volume_sum += std::isnan(found.volume) ? cell_volume(c) : found.volume;
    if (!why.empty()) add(p, VoronoiDefect::not_convex, site, -1, 0, why);
    if (site < 0 || static_cast<std::size_t>(site) >= sites_.size()) return;
    s.errors.resize(c.vertices.size());
    // A vertex certified no farther than a distance already solved (in any chunk: all
    // are merged) and within the tolerance changes no number of the report: its solve is
    // skipped. Which vertices are solved depends on the schedule, the report does not.
    const double tol = vertex_tol_;
    const double solved = std::max(p.max_vertex_distance, largest_distance_.load(std::memory_order_relaxed));
    vertex_errors(c, s.incidence, sites_, static_cast<std::uint32_t>(site), box_, s.errors, std::min(solved, tol));
    const Point3 o = sites_[static_cast<std::size_t>(site)];
    for (std::size_t j = 0; j < s.errors.size(); ++j) {
      const VertexError& e = s.errors[j];
      if (!e.decided || e.below) continue;
      p.max_vertex_distance = std::max(p.max_vertex_distance, e.distance);
      p.max_vertex_ulps = std::max(p.max_vertex_ulps, e.distance / ulp_);
      p.max_vertex_error = std::max(p.max_vertex_error, e.distance / scale_);
      if (e.distance > tol && e.distance > far_vertex_tolerance(c.vertices[j], o))
        add(p, VoronoiDefect::vertex_off, site, -1, e.distance / scale_);
    }
    for (double seen = largest_distance_.load(std::memory_order_relaxed);
         p.max_vertex_distance > seen &&
         !largest_distance_.compare_exchange_weak(seen, p.max_vertex_distance, std::memory_order_relaxed);)
      ;
  }

  // The volumes' sum against the box volume: within the relative tolerance, or else
  // within the ulp floor (every vertex within K ulps moves the volumes by at most the
  // sum of volume_rounding_bound; computed only here, so a check whose volumes meet the
  // relative bound does no more work), when the bound holds: every cell closed and no
  // vertex off.
  void judge_volume(unsigned threads) {
    auto& t = r_.tolerances;
    r_.volume_error = std::abs(r_.volume_sum - r_.box_volume) / r_.box_volume;
    t.volume = {o_.volume_tolerance, false};
    if (r_.volume_error <= o_.volume_tolerance || !(o_.ulps > 0) || not_closed_ > 0 ||
        r_.count(VoronoiDefect::vertex_off) > 0)
      return;
    const double d = vertex_error_;
    auto parts = stage(cells_.size(), threads, [&](std::size_t k, Partial& p, Scratch&) {
      const VoronoiCell c = cells_.view(k);
      if (c.face_count() == 0) return;
      const VolumeRoundingBound b = volume_rounding_bound(c, d);
      p.volume_bound += b.volume, p.surface += b.surface;
    });
    merge_all(std::move(parts));
    t.surface = surface_;
    const double ulp_floor = volume_bound_ / r_.box_volume;
    if (ulp_floor > o_.volume_tolerance) t.volume = {ulp_floor, true};
  }

  std::span<const Point3> sites_;
  const Box& box_;
  const ToolCells& cells_;
  const VoronoiCheckOptions& o_;
  VoronoiCheckReport& r_;
  std::shared_ptr<const VoronoiNeighbors> shared_;
  const VoronoiNeighbors* nb_ = nullptr;  // shared_, once built
  double extent2_ = 1, scale_ = 0, ulp_ = 0, vertex_tol_ = 0, convex_tol_ = 0, vertex_error_ = 0, small_face_ = 0;
  double volume_bound_ = 0, surface_ = 0;
  std::uint64_t not_closed_ = 0;
  mutable std::atomic<double> largest_distance_{0};  // the largest vertex distance solved so far, any chunk
  std::vector<std::int64_t> cell_of_;                // per representative site, its cell (-1: none)
  std::vector<char> primary_;                        // per cell, it is cell_of_ of its site's representative
  std::vector<Scratch> scratch_;
};

void decide(VoronoiCheckReport& r) {
  using D = VoronoiDefect;
  if (!(r.volume_error <= r.tolerances.volume.value)) ++r.counts[static_cast<int>(D::volume_mismatch)];
  const bool wrong = r.count(D::missing_cell) || r.count(D::extra_cell) || r.count(D::missing_face) ||
                     r.count(D::spurious_face) || r.count(D::bad_neighbor);
  const bool rounded = r.count(D::small_missing_face) || r.count(D::small_spurious_face);
  r.topology = wrong ? Topology::wrong : rounded ? Topology::rounded : Topology::exact;
  if (wrong)
    r.verdict = VoronoiVerdict::wrong_topology;
  else if (r.count(D::volume_mismatch))
    r.verdict = VoronoiVerdict::volume_mismatch;
  else if (r.count(D::vertex_off) || r.count(D::not_convex))
    r.verdict = VoronoiVerdict::bad_geometry;
  else
    r.verdict = rounded ? VoronoiVerdict::rounded_topology : VoronoiVerdict::exact_topology;
}

}  // namespace

std::shared_ptr<const VoronoiNeighbors> voronoi_relation(std::span<const Point3> sites, const VoronoiCheckOptions& o) {
  return o.dt ? std::make_shared<const VoronoiNeighbors>(sites, o.dt, o.threads)
              : std::make_shared<const VoronoiNeighbors>(sites, o.threads);
}

VoronoiCheckReport check_voronoi(std::span<const Point3> sites, const Box& box, const ToolCells& cells,
                                 const VoronoiCheckOptions& options) {
  const auto t0 = Clock::now();
  for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
    if (!std::isfinite(v)) throw std::invalid_argument("the box is not finite");
  if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
    throw std::invalid_argument("the box is empty");
  if (sites.empty())  // as the DT build refuses it, before any stage reads a site
    throw std::invalid_argument("fewer than 4 distinct sites, or all coplanar: no Delaunay tetrahedralization");
  VoronoiCheckReport r;
  r.sites = sites.size();
  r.box_volume = box.volume();
  Judge judge(sites, box, cells, options, r);
  judge.run();
  decide(r);
  r.seconds = since(t0);
  return r;
}

}  // namespace dtlab
