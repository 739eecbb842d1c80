#pragma once
// The exact Voronoi neighbour relation of a point set, read off its Delaunay
// tetrahedralization (adaptive predicates with symbolic perturbation, every sign
// exact). The perturbed DT refines the Delaunay complex: each DT edge (a, b) is dual
// to the face of the bisector of a and b spanned by the circumcentres of the tets
// around the edge. That face has positive area exactly when (a, b) is an edge of the
// Delaunay complex; otherwise (the edge lies inside a cospherical cell or a
// cocircular polygon: lattices) it is a point or a segment, a `degenerate` face that
// only the perturbation creates. Decided as follows, all exactly:
//   - a ring of tets with no flat tet and no cospherical facet (exact insphere != 0):
//     consecutive centres are distinct and no three are collinear: positive;
//   - otherwise (a closed ring): the exact rational centres of its non-flat tets
//     (a flat tet's limit centre lies between its neighbours') are all collinear or
//     not (GMP);
//   - a hull edge: its face is unbounded, positive unless its two hull facets are
//     coplanar and their four points cocircular (then the face is a ray on the
//     circle's axis).
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "voronoi_check/exact_centre.hpp"
#include "voronoi_check/tet_spheres.hpp"

#include "kernel/tetrahedralization.hpp"
#include "oracle/check/facet_table.hpp"

namespace dtlab {

// One thread's scratch for neighbors(): the exact centres of the rings it has
// decided for the current site (kept for that site's other edges).
struct NeighborScratch {
  std::vector<std::pair<std::uint32_t, ExactPoint>> centres;  // (tet, exact centre)
  std::vector<const ExactPoint*> ring;
  std::vector<std::uint32_t> corners;  // the vertices of the site's star, 4 per tet
  std::vector<char> mark;  // per site, all 0 between calls
};

// The sites' DT by exact predicates with symbolic perturbation, with the build's
// adjacency (the tables' facet pairs): what VoronoiNeighbors reads. Throws as its
// first constructor. `duplicates` (if given): how many sites equal an earlier one (the
// build inserts none of them).
std::shared_ptr<const Tetrahedralization> exact_delaunay(std::span<const Point3> sites, unsigned threads = 1,
                                                         std::size_t* duplicates = nullptr);

// Per site, the first site with its coordinates (itself when unique): VoronoiNeighbors::rep.
std::vector<std::uint32_t> site_representatives(std::span<const Point3> sites);

class VoronoiNeighbors {
 public:
  // Throws std::invalid_argument on a non-finite site, or on fewer than 4 distinct or
  // coplanar sites (no tetrahedralization to read the relation from). `threads`: of
  // the DT build (symbolic perturbation: the same tets for any count) and the tables.
  explicit VoronoiNeighbors(std::span<const Point3> sites, unsigned threads = 1);
  // The same from the sites' DT already built with exact predicates and symbolic
  // perturbation (its points are the sites); only the tables are built.
  // dt_seconds: the build's time when it was built for this relation (0: read); reps:
  // site_representatives(sites) when already computed (empty: computed here).
  VoronoiNeighbors(std::span<const Point3> sites, std::shared_ptr<const Tetrahedralization> dt, unsigned threads = 1,
                   double dt_seconds = 0, std::vector<std::uint32_t> reps = {});

  // rep(i): the first site with the coordinates of site i (itself when unique).
  std::uint32_t rep(std::uint32_t i) const { return rep_[i]; }
  std::size_t site_count() const { return rep_.size(); }
  const Tetrahedralization& dt() const { return *dt_; }
  std::span<const std::uint32_t> star(std::uint32_t v) const {
    return {star_.data() + star_off_[v], star_off_[v + 1] - star_off_[v]};
  }

  // The DT neighbours of representative site a, sorted, split by the area of the dual
  // face: `positive` (Voronoi neighbours) and `degenerate` (zero-area faces).
  // Thread-safe with one scratch per thread.
  void neighbors(std::uint32_t a, std::vector<std::uint32_t>& positive, std::vector<std::uint32_t>& degenerate,
                 NeighborScratch& scratch) const;

  // Circumcentres (in doubles) of the tets around edge (a, b) that are not flat.
  void ring_centres(std::uint32_t a, std::uint32_t b, std::vector<Point3>& out) const;
  // (a, b) is an edge of the convex hull: its dual face is unbounded.
  bool hull_edge(std::uint32_t a, std::uint32_t b) const;

  std::uint64_t degenerate_tets() const;
  double seconds_dt = 0, seconds_tables = 0;

 private:
  // degenerate_star: some tet around a is degenerate (else only hull edges need a look).
  bool edge_positive(std::uint32_t a, std::uint32_t b, bool degenerate_star, NeighborScratch& s) const;
  bool ring_collinear(std::uint32_t a, std::uint32_t b, NeighborScratch& s) const;
  void build_tables(unsigned threads);
  std::vector<std::uint32_t> pair_by_table(const FacetPairClassifier& cospherical, unsigned threads);
  // `spheres`: what `cospherical` reads of each tet, fetched ahead of the walk.
  std::vector<std::uint32_t> pair_by_adjacency(const FacetPairClassifier& cospherical,
                                               std::span<const TetSphere> spheres, unsigned threads);
  void classify_tets(unsigned threads, std::span<const TetSphere> spheres);

  std::vector<std::uint32_t> rep_;
  std::shared_ptr<const Tetrahedralization> dt_;
  std::vector<std::uint32_t> star_off_, star_;
  std::vector<char> flat_, degenerate_, hull_vertex_, degenerate_star_;  // per tet, per tet, per vertex, per vertex
  std::vector<std::uint64_t> hull_edges_, flat_hull_edges_;  // sorted keys (min << 32 | max)
};

}  // namespace dtlab
