#pragma once
// The boundary surface of a tetrahedralization: the facets that belong to one tet
// only, oriented outward, with their edge neighbours; and its 2-manifold defects.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/ids.hpp"
#include "oracle/check/facet_table.hpp"

namespace dtlab {

struct BoundarySurface {
  std::vector<std::array<std::uint32_t, 3>> facets;  // outward (counter-clockwise from outside)
  std::vector<std::uint32_t> tet_of;                 // the tet each facet belongs to
  // across[i][e]: the facet across edge (facets[i][e], facets[i][(e+1)%3]), or kNone.
  std::vector<std::array<std::uint32_t, 3>> across;
  // Edges not shared by exactly two facets traversing them in opposite directions.
  std::vector<std::array<std::uint32_t, 2>> bad_edges;
  // Vertices whose link (the cycle of their boundary neighbours) is not one cycle.
  std::vector<std::uint32_t> bad_vertices;
  std::vector<std::uint32_t> component;  // per facet, over edge adjacency
  std::uint32_t components = 0;
  std::uint64_t vertices = 0, edges = 0;
};

BoundarySurface build_boundary(std::span<const Tet> tets, const FacetTable& table, std::size_t point_count);

}  // namespace dtlab
