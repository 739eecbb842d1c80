#pragma once
// How a fuzz case is compared with an external oracle (CGAL, TetGen). The campaign
// only knows this signature; oracle/ provides the implementations and the CLI
// passes them in, so fuzz/ stays free of CGAL and TetGen.
#include <functional>
#include <span>
#include <string>

#include "kernel/build.hpp"

namespace dtlab::fuzz {

struct OracleHook {
  std::string name;  // "cgal", "tetgen"
  // "" when the oracle agrees with `ours`, else a short name of the difference.
  std::function<std::string(std::span<const Point3> points, const BuildResult& ours)> compare;
};

}  // namespace dtlab::fuzz
