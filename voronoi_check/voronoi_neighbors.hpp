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
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

class VoronoiNeighbors {
 public:
  // Throws std::invalid_argument on a non-finite site, or on fewer than 4 distinct or
  // coplanar sites (no tetrahedralization to read the relation from).
  explicit VoronoiNeighbors(std::span<const Point3> sites);
  ~VoronoiNeighbors();

  // rep(i): the first site with the coordinates of site i (itself when unique).
  std::uint32_t rep(std::uint32_t i) const { return rep_[i]; }
  std::size_t site_count() const { return rep_.size(); }
  const Tetrahedralization& dt() const { return dt_; }
  std::span<const std::uint32_t> star(std::uint32_t v) const {
    return {star_.data() + star_off_[v], star_off_[v + 1] - star_off_[v]};
  }

  // The DT neighbours of representative site a, sorted, split by the area of the dual
  // face: `positive` (Voronoi neighbours) and `degenerate` (zero-area faces).
  // Not thread-safe (exact centres are cached).
  void neighbors(std::uint32_t a, std::vector<std::uint32_t>& positive, std::vector<std::uint32_t>& degenerate);

  // Circumcentres (in doubles) of the tets around edge (a, b) that are not flat.
  void ring_centres(std::uint32_t a, std::uint32_t b, std::vector<Point3>& out) const;

  std::uint64_t degenerate_tets() const;
  double seconds_dt = 0, seconds_tables = 0;

 private:
  bool edge_positive(std::uint32_t a, std::uint32_t b);
  bool ring_collinear(std::uint32_t a, std::uint32_t b);
  void build_tables();

  struct Exact;
  std::vector<std::uint32_t> rep_;
  Tetrahedralization dt_;
  std::vector<std::uint32_t> star_off_, star_;
  std::vector<char> flat_, degenerate_, hull_vertex_, mark_;
  std::vector<std::uint64_t> hull_edges_, flat_hull_edges_;  // sorted keys (min << 32 | max)
  std::unique_ptr<Exact> exact_;                              // cached exact centres
};

}  // namespace dtlab
