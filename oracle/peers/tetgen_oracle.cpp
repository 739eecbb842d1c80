#include "oracle/peers/tetgen_oracle.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "kernel/input_error.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"

namespace dtlab {

namespace fs = std::filesystem;

TetgenOutput run_tetgen(std::span<const Point3> points, const std::string& binary, const std::string& flags,
                        const TempDir& dir, const ChildLimits& limits) {
  TetgenOutput out;
  const std::string node = dir.file("in.node");
  write_node(node, std::vector<Point3>(points.begin(), points.end()));
  // Its own process group, killed as a whole on time-out (run_child).
  out.child = run_child({binary, flags, node}, limits);
  if (out.child.status != ChildStatus::exited || out.child.exit_code != 0) return out;
  const std::string ele = dir.file("in.1.ele");
  out.wrote_ele = fs::exists(ele);
  if (!out.wrote_ele) return out;
  try {
    out.tets = read_ele(ele, 0, points.size());
  } catch (const InputError& e) {
    out.read_error = e.what();
  }
  return out;
}

OracleRun tetgen_delaunay(std::span<const Point3> points, const TetgenOptions& options) {
  if (!(options.timeout_s > 0 && std::isfinite(options.timeout_s)))
    throw std::invalid_argument("tetgen: the time-out must be finite and positive");
  OracleRun run;
  run.name = "tetgen";
  TempDir dir("dtlab-tetgen");
  TetgenOutput out =
      run_tetgen(points, options.binary, "-QzJNF", dir, ChildLimits::of(options.timeout_s, dir.file("tetgen.log")));
  const ChildResult& c = out.child;
  run.seconds = c.seconds;
  switch (c.status) {
    case ChildStatus::not_started: run.note = c.message; return run;
    case ChildStatus::timed_out:
      run.note = "tetgen timed out after " + std::to_string(options.timeout_s) + " s";
      return run;
    case ChildStatus::output_limit: run.note = "tetgen " + c.message; return run;
    case ChildStatus::signaled: run.note = "tetgen killed by signal " + std::to_string(c.signal); return run;
    case ChildStatus::exited:
      if (c.exit_code != 0) {
        run.note = "tetgen exited with status " + std::to_string(c.exit_code);
        return run;
      }
  }
  Tetrahedralization t;
  t.points.assign(points.begin(), points.end());
  if (!out.wrote_ele) {
    // TetGen writes no .ele when the input spans no volume.
    run.note = "tetgen wrote no .ele";
    run.mesh = std::move(t);
    return run;
  }
  if (!out.read_error.empty()) {
    run.note = "unreadable tetgen output: " + out.read_error;
    return run;
  }
  t.tets = std::move(out.tets);
  std::vector<char> used(points.size(), 0);
  for (const Tet& k : t.tets)
    for (auto v : k) used[v] = 1;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!used[i]) run.duplicates.push_back(static_cast<std::uint32_t>(i));
  run.mesh = std::move(t);
  return run;
}

}  // namespace dtlab
