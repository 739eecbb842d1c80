#pragma once
// What an oracle returns: a tetrahedralization over the input points (input
// indices, dtlab orientation), or no answer (crash, timeout, missing tool).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct OracleRun {
  std::string name;                        // "cgal", "tetgen", "dtlab"
  std::optional<Tetrahedralization> mesh;  // empty: no answer
  std::vector<std::uint32_t> duplicates;   // inputs the oracle collapsed onto another point
  double seconds = 0;                      // the triangulation only (TetGen: the whole process)
  std::string note;                        // why there is no answer, or other remarks
};

}  // namespace dtlab
