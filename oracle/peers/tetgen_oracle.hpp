#pragma once
// TetGen as an oracle: the `tetgen` binary run as a separate process on a
// temporary .node file, in plain Delaunay mode (`-QzJNF`: quiet, 0-based, keep
// every input point's number, write only the .ele; no -p/-q, so no points are
// added). A crash, an abort or a timeout is "no answer", never our defect.
#include <span>
#include <string>
#include <vector>

#include "oracle/peers/child_process.hpp"
#include "oracle/peers/oracle_run.hpp"
#include "oracle/peers/temp_dir.hpp"

namespace dtlab {

struct TetgenOptions {
  std::string binary = "tetgen";
  double timeout_s = 600;
};

// Inputs TetGen left out of every tet are reported as its duplicates (the checker
// verifies that each has the coordinates of a vertex). `seconds` is the whole
// process, file writing and reading excluded.
OracleRun tetgen_delaunay(std::span<const Point3> points, const TetgenOptions& options = {});

// What one run of the tetgen binary left.
struct TetgenOutput {
  ChildResult child;
  bool wrote_ele = false;  // in.1.ele exists (read only when the child exited 0)
  std::vector<Tet> tets;   // its tets: input indices, dtlab orientation
  std::string read_error;  // the .ele was there but unreadable
};

// The one launch of TetGen (tetgen_delaunay and the tetgen peers): writes `dir`/in.node,
// runs `binary FLAGS in.node` under `limits` (run_child) and, when it exited 0, reads
// the in.1.ele it wrote.
TetgenOutput run_tetgen(std::span<const Point3> points, const std::string& binary, const std::string& flags,
                        const TempDir& dir, const ChildLimits& limits);

}  // namespace dtlab
