#pragma once
// How a fuzz case is compared with an external oracle: any peer of oracle/peers/peers.hpp
// (CGAL, TetGen, qhull, scipy, gmsh, ...), run in its own process. The campaign only
// knows this signature; the CLI builds the hooks from oracle/ and passes them in, so
// fuzz/ stays free of the peers.
#include <functional>
#include <span>
#include <string>

#include "kernel/build.hpp"

namespace dtlab::fuzz {

struct OracleHook {
  std::string name;  // a peer name: "cgal", "tetgen", "qhull", ...
  // "" when the oracle agrees with `ours`, else a short name of the difference.
  std::function<std::string(std::span<const Point3> points, const BuildResult& ours)> compare;
};

}  // namespace dtlab::fuzz
