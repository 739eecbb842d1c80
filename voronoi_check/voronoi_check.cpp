#include "voronoi_check/voronoi_check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "voronoi/cell_check.hpp"
#include "voronoi/convex_cell.hpp"
#include "voronoi_check/cell_geometry.hpp"
#include "voronoi_check/voronoi_neighbors.hpp"

namespace dtlab {

using namespace vor;

const char* voronoi_defect_name(VoronoiDefect d) {
  static const char* names[kVoronoiDefects] = {
      "missing-cell",       "extra-cell",      "missing-face", "spurious-face", "small-missing-face",
      "small-spurious-face", "degenerate-face", "bad-neighbor", "vertex-off",    "not-convex",
      "volume-mismatch"};
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

// One directed face of a tool's cell, merged by neighbour (a tool may split a face).
struct ToolFace {
  std::uint32_t neighbor;  // representative site
  std::int64_t id;         // the id the tool wrote
  double area;
};

// The state of one check: the exact relation, the tool's cells by site, the report.
class Judge {
 public:
  Judge(std::span<const Point3> sites, const Box& box, const ToolCells& cells, const VoronoiCheckOptions& o,
        VoronoiCheckReport& r)
      : sites_(sites), box_(box), cells_(cells), o_(o), r_(r), nb_(sites) {
    extent2_ = sites_extent(sites, box);
    extent2_ *= extent2_;
  }

  void run() {
    assign_cells();
    for (std::uint32_t a = 0; a < sites_.size(); ++a)
      if (nb_.rep(a) == a) judge_site(a);
    for (std::size_t c = 0; c < cells_.size(); ++c) judge_geometry(c);
    r_.seconds_dt = nb_.seconds_dt;
  }

 private:
  void add(VoronoiDefect k, std::int64_t site, std::int64_t neighbor, double size, std::string detail = {}) {
    if (r_.counts[static_cast<int>(k)]++ < o_.witnesses_per_kind)
      r_.witnesses.push_back({k, site, neighbor, size, std::move(detail)});
  }

  // Stage 1: one non-empty cell per set of copies of a site.
  void assign_cells() {
    cell_of_.assign(sites_.size(), -1);
    for (std::size_t c = 0; c < cells_.size(); ++c) {
      const std::int64_t s = cells_.site(c);
      if (cells_.cell(c).face_count() == 0) continue;
      ++r_.cells;
      if (s < 0 || static_cast<std::size_t>(s) >= sites_.size()) {
        add(VoronoiDefect::extra_cell, s, -1, 0, "a cell of no site");
        continue;
      }
      auto& slot = cell_of_[nb_.rep(static_cast<std::uint32_t>(s))];
      if (slot >= 0)
        add(VoronoiDefect::extra_cell, s, cells_.site(slot), 0, "a second cell for this site or a copy of it");
      else
        slot = static_cast<std::int64_t>(c);
    }
  }

  void tool_faces(const VoronoiCell& c, std::uint32_t a, std::vector<ToolFace>& out) {
    out.clear();
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      const std::int32_t id = c.face_neighbor[f];
      if (id < 0) continue;
      if (static_cast<std::size_t>(id) >= sites_.size()) {
        add(VoronoiDefect::bad_neighbor, a, id, 0, "neighbour id is no site");
        continue;
      }
      out.push_back({nb_.rep(static_cast<std::uint32_t>(id)), id, face_area(c, f)});
    }
    std::sort(out.begin(), out.end(), [](const ToolFace& x, const ToolFace& y) { return x.neighbor < y.neighbor; });
    std::size_t k = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (k > 0 && out[k - 1].neighbor == out[i].neighbor)
        out[k - 1].area += out[i].area;
      else
        out[k++] = out[i];
    }
    out.resize(k);
  }

  // The exact face of (a, b) clipped to the box, in doubles: its area, or nullopt when
  // it does not meet the box interior.
  std::optional<double> true_area(std::uint32_t a, std::uint32_t b) {
    if (clipped_site_ != a) {
      std::vector<std::uint32_t> all(pos_);
      all.insert(all.end(), deg_.begin(), deg_.end());
      compute_cell(clipped_, sites_, a, all, box_, 1e-15);
      clipped_site_ = a;
    }
    double area = 0;
    for (std::size_t f = 0; f < clipped_.face_count(); ++f)
      if (clipped_.face_tag(f) == static_cast<std::int32_t>(b)) {
        const auto fv = clipped_.face(f);
        const Point3 o = clipped_.vertices()[fv[0]];
        Point3 n{0, 0, 0};
        for (std::size_t k = 1; k + 1 < fv.size(); ++k)
          n = n + cross(clipped_.vertices()[fv[k]] - o, clipped_.vertices()[fv[k + 1]] - o);
        area += 0.5 * norm(n);
      }
    if (area > 0) return area;
    // Rounded away by the clip: required when a vertex of the exact face is inside the box.
    nb_.ring_centres(a, b, centres_);
    for (const auto& c : centres_)
      if (c.x > box_.lo.x && c.x < box_.hi.x && c.y > box_.lo.y && c.y < box_.hi.y && c.z > box_.lo.z &&
          c.z < box_.hi.z)
        return 0.0;
    return std::nullopt;
  }

  void face_defect(bool missing, std::uint32_t a, std::int64_t b, double area) {
    const double rel = area / extent2_;
    if (rel <= o_.small_face) {
      add(missing ? VoronoiDefect::small_missing_face : VoronoiDefect::small_spurious_face, a, b, rel);
      r_.largest_small_face = std::max(r_.largest_small_face, rel);
    } else {
      add(missing ? VoronoiDefect::missing_face : VoronoiDefect::spurious_face, a, b, rel);
      r_.largest_wrong_face = std::max(r_.largest_wrong_face, rel);
    }
  }

  // Stage 2: the neighbour set of one site against the exact one.
  void judge_site(std::uint32_t a) {
    nb_.neighbors(a, pos_, deg_);
    r_.voronoi_edges += pos_.size();
    r_.degenerate_edges += deg_.size();
    const std::int64_t c = cell_of_[a];
    if (c < 0) {
      if (box_.contains(sites_[a])) add(VoronoiDefect::missing_cell, a, -1, 0);
      else if (!pos_.empty()) {
        for (auto b : pos_)
          if (true_area(a, b)) {
            add(VoronoiDefect::missing_cell, a, -1, 0, "site outside the box, its cell meets it");
            break;
          }
      }
      return;
    }
    tool_faces(cells_.cell(static_cast<std::size_t>(c)), a, tf_);
    std::size_t i = 0;
    for (auto b : pos_) {
      while (i < tf_.size() && tf_[i].neighbor < b) unexpected(a, tf_[i++]);
      if (i < tf_.size() && tf_[i].neighbor == b) {
        ++i;
        continue;
      }
      if (const auto area = true_area(a, b)) face_defect(true, a, b, *area);
    }
    while (i < tf_.size()) unexpected(a, tf_[i++]);
  }

  // A tool face towards a site that is no Voronoi neighbour of a.
  void unexpected(std::uint32_t a, const ToolFace& f) {
    const bool dt_edge = std::binary_search(deg_.begin(), deg_.end(), f.neighbor);
    if (dt_edge && f.area / extent2_ <= o_.small_face) {
      add(VoronoiDefect::degenerate_face, a, f.id, f.area / extent2_, "exact face has zero area");
      return;
    }
    face_defect(false, a, f.id, f.area);
  }

  // Stage 3: one cell's shape, vertices and volume.
  void judge_geometry(std::size_t k) {
    const VoronoiCell c = cells_.cell(k);
    if (c.face_count() == 0) return;
    const std::int64_t s = cells_.site(k);
    r_.faces += c.face_count();
    r_.vertices += c.vertices.size();
    r_.volume_sum += c.volume;
    const double diag = box_.diagonal();
    std::string why = check_cell_closed(c);
    if (why.empty()) why = check_cell_convex(c, o_.convex_tolerance * diag, true);
    if (!why.empty()) add(VoronoiDefect::not_convex, s, -1, 0, why);
    if (s < 0 || static_cast<std::size_t>(s) >= sites_.size()) return;
    errors_.resize(c.vertices.size());
    vertex_errors(c, sites_, static_cast<std::uint32_t>(s), box_, errors_);
    const double ulp = std::nextafter(coord_max_, INFINITY) - coord_max_;
    for (const auto& e : errors_) {
      if (!e.decided) continue;
      r_.max_vertex_ulps = std::max(r_.max_vertex_ulps, e.distance / ulp);
      r_.max_vertex_error = std::max(r_.max_vertex_error, e.distance / diag);
      if (e.distance > o_.vertex_tolerance * diag) add(VoronoiDefect::vertex_off, s, -1, e.distance / diag);
    }
  }

 public:
  double coord_max_ = 0;

 private:
  std::span<const Point3> sites_;
  const Box& box_;
  const ToolCells& cells_;
  const VoronoiCheckOptions& o_;
  VoronoiCheckReport& r_;
  VoronoiNeighbors nb_;
  double extent2_ = 1;
  std::vector<std::int64_t> cell_of_;
  std::vector<std::uint32_t> pos_, deg_;
  std::vector<ToolFace> tf_;
  std::vector<VertexError> errors_;
  std::vector<Point3> centres_;
  ConvexCell clipped_;
  std::uint32_t clipped_site_ = 0xFFFFFFFFu;
};

void decide(VoronoiCheckReport& r, const VoronoiCheckOptions& o) {
  using D = VoronoiDefect;
  r.volume_error = std::abs(r.volume_sum - r.box_volume) / r.box_volume;
  if (!(r.volume_error <= o.volume_tolerance)) ++r.counts[static_cast<int>(D::volume_mismatch)];
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

VoronoiCheckReport check_voronoi(std::span<const Point3> sites, const Box& box, const ToolCells& cells,
                                 const VoronoiCheckOptions& options) {
  const auto t0 = Clock::now();
  for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
    if (!std::isfinite(v)) throw std::invalid_argument("the box is not finite");
  if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
    throw std::invalid_argument("the box is empty");
  VoronoiCheckReport r;
  r.sites = sites.size();
  r.box_volume = box.volume();
  Judge judge(sites, box, cells, options, r);
  for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
    judge.coord_max_ = std::max(judge.coord_max_, std::abs(v));
  judge.run();
  std::vector<Point3> distinct(sites.begin(), sites.end());
  std::sort(distinct.begin(), distinct.end(), lex_less);
  r.distinct_sites = static_cast<std::uint64_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
  decide(r, options);
  r.seconds = since(t0);
  return r;
}

}  // namespace dtlab
