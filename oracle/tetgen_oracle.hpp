#pragma once
// TetGen as an oracle: the `tetgen` binary run as a separate process on a
// temporary .node file, in plain Delaunay mode (`-QzJNF`: quiet, 0-based, keep
// every input point's number, write only the .ele; no -p/-q, so no points are
// added). A crash, an abort or a timeout is "no answer", never our defect.
#include <span>
#include <string>

#include "oracle/oracle_run.hpp"

namespace dtlab {

struct TetgenOptions {
  std::string binary = "tetgen";
  double timeout_s = 600;
};

// Inputs TetGen left out of every tet are reported as its duplicates (the checker
// verifies that each has the coordinates of a vertex). `seconds` is the whole
// process, file writing and reading excluded.
OracleRun tetgen_delaunay(std::span<const Point3> points, const TetgenOptions& options = {});

}  // namespace dtlab
