#pragma once
// The Voronoi checker's report as JSON: one shape for the CLI (`dtlab voronoi
// --against`) and the Python module (`dtlab.check_voronoi`).
#include <nlohmann/json.hpp>

#include "voronoi_check/voronoi_check.hpp"

namespace dtlab {

nlohmann::json to_json(const VoronoiCheckReport& r);

}  // namespace dtlab
