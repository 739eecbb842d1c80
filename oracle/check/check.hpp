#pragma once
// The exact invariant checker: proves (or refutes, with a witness) that a compact
// tetrahedralization is the Delaunay tetrahedralization of its input points.
// See oracle/README.md for the argument behind each check.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

enum class DefectKind {
  broken_adjacency,  // bad tet, facet in > 2 tets, boundary not a closed 2-manifold
  inverted,          // orient3d < 0
  flat,              // orient3d == 0
  non_delaunay,      // an interior facet's opposite vertex strictly inside the circumsphere
  hull_not_convex,   // a reflex boundary edge, or a point outside a boundary facet's plane
  overlap,           // tets on the same side of a shared facet, or the hull covered twice
  gap,               // a hole: more than one boundary component, or no tets for a 3D input
  missing_point,     // an input point (not an exact duplicate of a vertex) that is no vertex
  duplicate_vertex,  // two vertices with identical coordinates
  euler,             // Euler characteristics inconsistent with a ball
  unproven,          // a stage could not decide: the mesh is not proven valid
};
inline constexpr int kDefectKinds = 11;
const char* defect_name(DefectKind k);

// The affine hull of the input points, decided exactly. The checker decides it for a
// mesh with no tets, which is the Delaunay tetrahedralization only of an input that
// spans less than a volume.
enum class AffineSpan { not_decided, no_points, point, line, plane, volume };
const char* span_name(AffineSpan s);  // "no-points", "point", "line", "plane", ...

struct Defect {
  DefectKind kind;
  std::vector<std::uint32_t> tets;      // tet ids (index into Tetrahedralization::tets)
  std::vector<std::uint32_t> vertices;  // point ids (input indices)
  int sign = 0;                         // exact sign of the deciding predicate, if any
  std::string detail;                   // which predicate / what was expected
};

struct CheckOptions {
  // Input indices the producer reported as duplicates of an earlier point. They
  // need not be vertices; each is verified to have the coordinates of a vertex.
  std::span<const std::uint32_t> duplicates = {};
  bool delaunay = true;                 // run the insphere test on every interior facet
  std::size_t witnesses_per_kind = 16;  // defects listed per kind (all are counted)
  // Also compare the exact sum of tet volumes with the exact volume inside the
  // boundary. Implied by stage 3 (interior facets cancel), so no extra proof: a
  // cross-check of the checker's bookkeeping, a GMP sum over every tet (slow).
  bool volume_identity = false;
  // Threads for the orientation pass, the facet table with its insphere tests and the
  // edge count (0: all hardware threads). The report is the same for every count.
  unsigned threads = 1;
};

struct CheckStats {
  std::uint64_t points = 0, vertices = 0, tets = 0;
  std::uint64_t interior_facets = 0, boundary_facets = 0, edges = 0;
  std::uint64_t boundary_vertices = 0, boundary_edges = 0, boundary_components = 0;
  std::int64_t euler = 0;                           // V - E + F - T (1 for a ball)
  std::int64_t boundary_euler = 0;                  // V - E + F of the boundary (2 for a sphere)
  std::uint64_t duplicates = 0;                     // input points equal to a vertex but not one
  std::uint64_t cospherical_facets = 0;             // interior facets with insphere == 0
  bool degree_checked = false;                      // the covering degree of the boundary was decided
  bool cover_proven = false;                        // ... and it is 1: the tets tile the convex hull once
  bool volume_checked = false;                      // the volume identity was computed (volume_identity)
  bool volume_equal = false;                        // exact sum of tet volumes == exact hull volume
  double volume_tets = 0, volume_hull = 0;          // the exact values, rounded (meaningful only
                                                    // as the hull's volume when cover_proven)
  AffineSpan input_span = AffineSpan::not_decided;  // decided when there are no tets
  double seconds = 0;
};

struct CheckReport {
  std::vector<Defect> defects;                       // witnesses, at most witnesses_per_kind each
  std::array<std::uint64_t, kDefectKinds> counts{};  // all defects, per kind
  CheckStats stats;
  // Interior facets whose five points are cospherical (exact insphere == 0), as the
  // pair of tets sharing them: the input of the canonical comparison.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cospherical_pairs;
  bool ok() const {
    for (auto c : counts)
      if (c) return false;
    return true;
  }
  std::uint64_t defect_count() const {
    std::uint64_t n = 0;
    for (auto c : counts) n += c;
    return n;
  }
};

// Exact: every sign comes from FilteredExact (oracle/check/filtered_exact.hpp).
CheckReport check_tetrahedralization(const Tetrahedralization& t, const CheckOptions& options = {});
// The same check on a tetrahedralization the caller gives up: its vertices are
// renumbered in place by first appearance in the tets, which makes the checker's
// memory accesses local (about a quarter less time at 5*10^6 points, oracle/README.md),
// and the report is in the caller's numbering. Counts and stats are those of the
// overload above; only the order of the witnesses may differ (boundary
// broken-adjacency ones follow vertex ids), so with `witnesses_per_kind` reached,
// other ones of that kind may be listed.
CheckReport check_tetrahedralization(Tetrahedralization&& t, const CheckOptions& options = {});

}  // namespace dtlab
