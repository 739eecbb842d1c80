#include "voronoi_check/voronoi_neighbors.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "kernel/build.hpp"
#include "kernel/ids.hpp"
#include "kernel/parallel_for.hpp"
#include "oracle/check/facet_table.hpp"
#include "oracle/check/filtered_exact.hpp"
#include "voronoi/circumcenter.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/exact_centre.hpp"
#include "voronoi_check/tet_spheres.hpp"

namespace dtlab {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

std::vector<std::uint32_t> site_representatives(std::span<const Point3> p) {
  // Sorted as (point, index) records, not indices into the points (each comparison two
  // scattered reads): equal points then come in index order, the first the representative.
  struct Keyed {
    Point3 p;
    std::uint32_t i;
  };
  std::vector<Keyed> keyed(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) keyed[k] = {p[k], static_cast<std::uint32_t>(k)};
  std::sort(keyed.begin(), keyed.end(),
            [](const Keyed& a, const Keyed& b) { return lex_less(a.p, b.p) || (!lex_less(b.p, a.p) && a.i < b.i); });
  std::vector<std::uint32_t> rep(p.size());
  for (std::size_t k = 0; k < keyed.size(); ++k)
    rep[keyed[k].i] = k > 0 && keyed[k].p == keyed[k - 1].p ? rep[keyed[k - 1].i] : keyed[k].i;
  return rep;
}

std::shared_ptr<const Tetrahedralization> exact_delaunay(std::span<const Point3> sites, unsigned threads,
                                                         std::size_t* duplicates) {
  for (const auto& p : sites)
    if (!is_finite(p)) throw std::invalid_argument("a site is not finite");
  BuildOptions bo;
  bo.threads = threads;
  bo.count_stages = false;
  bo.keep_adjacency = true;  // the tables then pair no facets
  BuildResult r = build_delaunay(sites, PredicateSpec{"adaptive", 0, false, true}, bo);
  if (r.failure) {
    if (r.failure->kind == FailureKind::lower_dimensional)
      throw std::invalid_argument("fewer than 4 distinct sites, or all coplanar: no Delaunay tetrahedralization");
    throw std::runtime_error(std::string("Delaunay build failed: ") + failure_name(r.failure->kind));
  }
  if (duplicates) *duplicates = r.duplicates.size();
  return std::make_shared<const Tetrahedralization>(std::move(r.mesh));
}

VoronoiNeighbors::VoronoiNeighbors(std::span<const Point3> sites, unsigned threads) {
  const auto t0 = Clock::now();
  std::size_t duplicates = 0;
  dt_ = exact_delaunay(sites, threads, &duplicates);
  seconds_dt = since(t0);
  // The build found every site equal to an earlier one (exact comparisons): with none,
  // each site is its own representative and the sort is not needed.
  if (duplicates == 0) {
    rep_.resize(sites.size());
    std::iota(rep_.begin(), rep_.end(), 0u);
  } else
    rep_ = site_representatives(sites);
  const auto t1 = Clock::now();
  build_tables(threads);
  seconds_tables = since(t1);
}

VoronoiNeighbors::VoronoiNeighbors(std::span<const Point3> sites, std::shared_ptr<const Tetrahedralization> dt,
                                   unsigned threads, double dt_seconds, std::vector<std::uint32_t> reps)
    : seconds_dt(dt_seconds), rep_(reps.empty() ? site_representatives(sites) : std::move(reps)), dt_(std::move(dt)) {
  if (rep_.size() != sites.size()) throw std::invalid_argument("the representatives are not of these sites");
  if (dt_->points.size() != sites.size()) throw std::invalid_argument("the DT is not of these sites");
  const auto t1 = Clock::now();
  build_tables(threads);
  seconds_tables = since(t1);
}

// Flat tets (exact orient3d 0; a tet whose certified centre exists is not flat).
void VoronoiNeighbors::classify_tets(unsigned threads, std::span<const TetSphere> spheres) {
  const FilteredExact pred;
  const auto& p = dt_->points;
  const std::size_t nt = dt_->tets.size();
  flat_.assign(nt, 0);
  parallel_for(nt, threads, 4096, [&](std::size_t t, unsigned) {
    if (std::isfinite(spheres[t].error)) return;
    const Tet& q = dt_->tets[t];
    flat_[t] = pred.orient3d(p[q[0]], p[q[1]], p[q[2]], p[q[3]]) == 0;
  });
  degenerate_ = flat_;
}

// The facets of the tets paired by sorting (oracle/check/facet_table.hpp); each pair
// that `cospherical` flags marks both tets degenerate. Returns the boundary facets.
std::vector<std::uint32_t> VoronoiNeighbors::pair_by_table(const FacetPairClassifier& cospherical, unsigned threads) {
  const auto mark = [&](const FacetPair& f, int) { degenerate_[f.r1 / 4] = degenerate_[f.r2 / 4] = 1; };
  return build_facet_table(dt_->tets, first_appearance(dt_->tets, dt_->points.size()), cospherical, mark, threads)
      .boundary_refs;
}

// The same from the build's own adjacency (Tetrahedralization::adjacency): each
// interior facet once, from its lower tet, classified in parallel; the flagged tets
// marked afterwards (per-chunk lists, no shared writes). No sort of all facets.
std::vector<std::uint32_t> VoronoiNeighbors::pair_by_adjacency(const FacetPairClassifier& cospherical,
                                                               std::span<const TetSphere> spheres, unsigned threads) {
  const auto& tets = dt_->tets;
  const auto& adj = dt_->adjacency;
  constexpr std::size_t kChunk = 4096;
  std::vector<std::vector<std::uint32_t>> flagged((tets.size() + kChunk - 1) / kChunk);
  constexpr std::size_t kAhead = 8;  // tets ahead whose neighbours' spheres are fetched
  parallel_chunks(tets.size(), threads, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
    auto& out = flagged[b / kChunk];
    for (std::size_t t = b; t < e; ++t) {
      if (t + kAhead < e)
        for (int f = 0; f < 4; ++f)
          if (const std::uint32_t m = adj[4 * (t + kAhead) + f]; m != kNone) __builtin_prefetch(&spheres[m / 4]);
      for (int f = 0; f < 4; ++f) {
        const std::uint32_t m = adj[4 * t + f];
        if (m == kNone || m / 4 < t) continue;
        // Centres apart: not cospherical (as `cospherical` says first), decided before
        // the far tet's record is read (a cache miss at nearly every facet).
        if (surely_apart(spheres[t], spheres[m / 4])) continue;
        const auto v = facet_vertices(tets[t], f);
        const FacetPair pair{
            static_cast<std::uint32_t>(4 * t + f), m, {v[0], v[1], v[2]}, tets[t][f], tets[m / 4][m % 4], false};
        if (cospherical(pair)) out.push_back(static_cast<std::uint32_t>(t)), out.push_back(m / 4);
      }
    }
  });
  for (const auto& chunk : flagged)
    for (const std::uint32_t t : chunk) degenerate_[t] = 1;
  std::vector<std::uint32_t> boundary;
  for (std::size_t r = 0; r < adj.size(); ++r)
    if (adj[r] == kNone) boundary.push_back(static_cast<std::uint32_t>(r));
  return boundary;
}

// Stars, flat tets, then tets with a cospherical facet (exact insphere 0 of a facet and
// its two apexes, asked only when the tets' certified centres are not apart; a flat tet
// is degenerate too), hull edges and the degenerate ones.
void VoronoiNeighbors::build_tables(unsigned threads) {
  const FilteredExact pred;
  const auto& p = dt_->points;
  vertex_stars(p.size(), dt_->tets, star_off_, star_);
  const std::vector<TetSphere> spheres = tet_spheres(p, dt_->tets, threads);
  classify_tets(threads, spheres);
  const auto cospherical = [&](const FacetPair& f) {
    const std::uint32_t t1 = f.r1 / 4, t2 = f.r2 / 4;
    if ((flat_[t1] && flat_[t2]) || surely_apart(spheres[t1], spheres[t2])) return 0;
    return pred.insphere(p[f.v[0]], p[f.v[1]], p[f.v[2]], p[f.apex1], p[f.apex2]) == 0 ? 1 : 0;
  };
  const std::vector<std::uint32_t> boundary_refs = dt_->adjacency.size() == 4 * dt_->tets.size()
                                                       ? pair_by_adjacency(cospherical, spheres, threads)
                                                       : pair_by_table(cospherical, threads);
  // Per vertex: some tet of its star is degenerate (one byte read per site by neighbors()).
  degenerate_star_.assign(p.size(), 0);
  for (std::size_t t = 0; t < degenerate_.size(); ++t)
    if (degenerate_[t])
      for (const std::uint32_t v : dt_->tets[t]) degenerate_star_[v] = 1;
  // Hull facets by edge: the third vertex and the tet's fourth of both facets at an edge.
  struct Side {
    std::uint64_t key;
    std::uint32_t third, apex;
  };
  std::vector<Side> sides;
  hull_vertex_.assign(p.size(), 0);
  for (auto ref : boundary_refs) {
    const Tet& q = dt_->tets[ref / 4];
    const auto v = facet_vertices(q, static_cast<int>(ref % 4));
    for (int k = 0; k < 3; ++k) {
      hull_vertex_[v[k]] = 1;
      sides.push_back({edge_key(v[k], v[(k + 1) % 3]), v[(k + 2) % 3], q[ref % 4]});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.key < b.key; });
  for (std::size_t k = 0; k + 1 < sides.size(); k += 2) {
    const Side &s1 = sides[k], &s2 = sides[k + 1];
    hull_edges_.push_back(s1.key);
    const Point3 &a = p[s1.key >> 32], &b = p[s1.key & 0xFFFFFFFFu];
    // Coplanar hull facets whose four points are cocircular: the face is a ray.
    if (pred.orient3d(a, b, p[s1.third], p[s2.third]) == 0 &&
        pred.insphere(a, b, p[s1.third], p[s2.third], p[s1.apex]) == 0)
      flat_hull_edges_.push_back(s1.key);
  }
}

std::uint64_t VoronoiNeighbors::degenerate_tets() const {
  return static_cast<std::uint64_t>(std::count(degenerate_.begin(), degenerate_.end(), 1));
}

void VoronoiNeighbors::ring_centres(std::uint32_t a, std::uint32_t b, std::vector<Point3>& out) const {
  out.clear();
  const auto& p = dt_->points;
  for (auto t : star(a)) {
    const Tet& q = dt_->tets[t];
    if (flat_[t] || (q[0] != b && q[1] != b && q[2] != b && q[3] != b)) continue;
    out.push_back(vor::circumcenter(p[q[0]], p[q[1]], p[q[2]], p[q[3]]));
  }
}

bool VoronoiNeighbors::hull_edge(std::uint32_t a, std::uint32_t b) const {
  return hull_vertex_[a] && hull_vertex_[b] &&
         std::binary_search(hull_edges_.begin(), hull_edges_.end(), edge_key(a, b));
}

// The exact centres of the ring's non-flat tets, from the scratch when this site has
// met them before.
bool VoronoiNeighbors::ring_collinear(std::uint32_t a, std::uint32_t b, NeighborScratch& s) const {
  const auto& p = dt_->points;
  std::vector<std::size_t> at;
  for (auto t : star(a)) {
    const Tet& q = dt_->tets[t];
    if (flat_[t] || (q[0] != b && q[1] != b && q[2] != b && q[3] != b)) continue;
    std::size_t k = 0;
    while (k < s.centres.size() && s.centres[k].first != t) ++k;
    if (k == s.centres.size()) s.centres.emplace_back(t, exact_circumcentre(p[q[0]], p[q[1]], p[q[2]], p[q[3]]));
    at.push_back(k);
  }
  s.ring.clear();
  for (auto k : at) s.ring.push_back(&s.centres[k].second);
  return all_collinear(s.ring);
}

bool VoronoiNeighbors::edge_positive(std::uint32_t a, std::uint32_t b, bool degenerate_star, NeighborScratch& s) const {
  const std::uint64_t key = edge_key(a, b);
  if (hull_edge(a, b)) return !std::binary_search(flat_hull_edges_.begin(), flat_hull_edges_.end(), key);
  if (!degenerate_star) return true;
  for (auto t : star(a)) {
    const Tet& q = dt_->tets[t];
    if (degenerate_[t] && (q[0] == b || q[1] == b || q[2] == b || q[3] == b)) return !ring_collinear(a, b, s);
  }
  return true;
}

void VoronoiNeighbors::neighbors(std::uint32_t a, std::vector<std::uint32_t>& positive,
                                 std::vector<std::uint32_t>& degenerate, NeighborScratch& scratch) const {
  positive.clear();
  degenerate.clear();
  scratch.centres.clear();
  std::vector<std::uint32_t>& all = degenerate;  // collected here first, then split
  auto& mark = scratch.mark;
  mark.resize(rep_.size(), 0);
  // The star's tets are scattered in memory: their vertices are copied first, with no
  // branch between the loads, then made distinct branch-free (a branch per vertex
  // mispredicts and cancels the loads in flight: the walk then waits on each tet).
  const auto st = star(a);
  auto& corners = scratch.corners;
  corners.resize(4 * st.size());
  for (std::size_t k = 0; k < st.size(); ++k) {
    const Tet& q = dt_->tets[st[k]];
    for (int j = 0; j < 4; ++j) corners[4 * k + j] = q[j];
  }
  const bool degenerate_star = degenerate_star_[a];  // else every interior edge of a is positive
  all.resize(corners.size());
  std::size_t distinct = 0;
  mark[a] = 1;  // a is no neighbour of its own
  for (auto v : corners) {
    all[distinct] = v;
    distinct += mark[v] == 0;
    mark[v] = 1;
  }
  all.resize(distinct);
  mark[a] = 0;
  for (auto v : all) mark[v] = 0;
  std::sort(all.begin(), all.end());
  if (!degenerate_star && !hull_vertex_[a]) {  // no hull edge, no degenerate tet: all positive
    positive.swap(all);
    degenerate.clear();
    return;
  }
  std::size_t kept = 0;
  for (auto v : all) {
    if (edge_positive(a, v, degenerate_star, scratch))
      positive.push_back(v);
    else
      all[kept++] = v;
  }
  all.resize(kept);
}

}  // namespace dtlab
