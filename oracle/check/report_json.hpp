#pragma once
// Text and JSON renderings of checker reports and comparisons, shared by
// `dtlab check` and `dtlab oracle`.
#include <nlohmann/json.hpp>
#include <string>

#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"

namespace dtlab {

std::string format_defect(const Defect& d);     // one line
std::string format_stats(const CheckStats& s);  // one line
// "valid Delaunay tetrahedralization", "DEFECTS FOUND", or for a valid mesh with no
// tets what makes it right: "valid: no tetrahedra; the points are coplanar (decided
// exactly), so the empty mesh is the Delaunay tetrahedralization".
std::string check_headline(const CheckReport& r);
nlohmann::json to_json(const Defect& d);
nlohmann::json to_json(const CheckReport& r);
nlohmann::json to_json(const Comparison& c);

}  // namespace dtlab
