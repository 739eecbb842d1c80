#pragma once
// Canonical comparison of two Delaunay tetrahedralizations of the same points.
//
// In general position (no five cospherical points on a Delaunay sphere, checked
// exactly: every interior facet has insphere != 0) the DT is unique and the tet
// sets must be equal. Otherwise the unique object is the Delaunay complex: tets
// merged across facets whose five points are cospherical (exact insphere == 0)
// form its cells, each the convex hull of the points on one empty sphere; the
// cells, as sorted vertex sets, must be equal. Both need the checker's reports
// (their cospherical_pairs) and are meaningful only for valid meshes. Vertices are
// compared through the smallest input index with their coordinates, so producers
// that keep different copies of a duplicated point still compare equal.
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/tetrahedralization.hpp"
#include "oracle/check/check.hpp"

namespace dtlab {

struct Cells {
  std::vector<std::uint32_t> vertices;  // concatenated sorted vertex sets
  std::vector<std::uint64_t> offsets;   // cell i is vertices[offsets[i] .. offsets[i+1])
  std::size_t size() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::vector<std::uint32_t> cell(std::size_t i) const {
    return {vertices.begin() + static_cast<std::ptrdiff_t>(offsets[i]),
            vertices.begin() + static_cast<std::ptrdiff_t>(offsets[i + 1])};
  }
};

// The Delaunay complex, cells sorted lexicographically.
Cells delaunay_complex(const Tetrahedralization& t, const CheckReport& report);

struct Comparison {
  bool general_position = false;  // neither mesh has a cospherical interior facet
  bool tets_equal = false;        // same sorted vertex quadruples
  bool complexes_equal = false;   // same Delaunay cells
  bool agree() const { return complexes_equal && (!general_position || tets_equal); }
  std::size_t cells_a = 0, cells_b = 0;
  std::size_t only_a_count = 0, only_b_count = 0;          // cells in one complex only
  std::vector<std::vector<std::uint32_t>> only_a, only_b;  // a few of them, as witnesses
};

Comparison compare_canonical(const Tetrahedralization& a, const CheckReport& ra, const Tetrahedralization& b,
                             const CheckReport& rb, std::size_t witnesses = 8);

}  // namespace dtlab
