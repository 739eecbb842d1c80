#include "oracle/check/report_json.hpp"

#include <cstdio>

namespace dtlab {
namespace {

std::string list(const std::vector<std::uint32_t>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(v[i]);
  }
  return s + "]";
}

// A mesh with no tets is right exactly when the input spans less than a volume.
bool proven_flat(const CheckStats& s) {
  return s.tets == 0 && s.input_span != AffineSpan::not_decided && s.input_span != AffineSpan::volume;
}

const char* span_text(AffineSpan s) {
  switch (s) {
    case AffineSpan::no_points: return "there are no points";
    case AffineSpan::point: return "the points coincide";
    case AffineSpan::line: return "the points are collinear";
    case AffineSpan::plane: return "the points are coplanar";
    case AffineSpan::not_decided:
    case AffineSpan::volume: break;
  }
  return "the points span a volume";
}

}  // namespace

std::string check_headline(const CheckReport& r) {
  if (!r.ok()) return "DEFECTS FOUND";
  if (proven_flat(r.stats))
    return std::string("valid: no tetrahedra; ") + span_text(r.stats.input_span) +
           " (decided exactly), so the empty mesh is the Delaunay tetrahedralization";
  return "valid Delaunay tetrahedralization";
}

std::string format_defect(const Defect& d) {
  std::string s = std::string(defect_name(d.kind)) + ": " + d.detail;
  if (!d.tets.empty()) s += "; tets " + list(d.tets);
  if (!d.vertices.empty()) s += "; vertices " + list(d.vertices);
  if (d.sign != 0) s += "; sign " + std::to_string(d.sign);
  return s;
}

std::string format_stats(const CheckStats& s) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%llu points, %llu vertices, %llu duplicates, %llu tets, %llu boundary facets, "
                "%llu cospherical facets, Euler %lld, ",
                (unsigned long long)s.points, (unsigned long long)s.vertices, (unsigned long long)s.duplicates,
                (unsigned long long)s.tets, (unsigned long long)s.boundary_facets,
                (unsigned long long)s.cospherical_facets, (long long)s.euler);
  std::string out = buf;
  // A volume is only a property of the hull once the tets are proven to tile it once.
  if (s.cover_proven)
    std::snprintf(buf, sizeof buf, "volume %.17g; ", s.volume_hull);
  else if (proven_flat(s))
    std::snprintf(buf, sizeof buf, "input spans %s: volume 0; ", span_name(s.input_span));
  else
    std::snprintf(buf, sizeof buf, "cover not proven, no volume; ");
  out += buf;
  std::snprintf(buf, sizeof buf, "checked in %.3f s", s.seconds);
  return out + buf;
}

nlohmann::json to_json(const Defect& d) {
  return {{"kind", defect_name(d.kind)},
          {"detail", d.detail},
          {"tets", d.tets},
          {"vertices", d.vertices},
          {"sign", d.sign}};
}

nlohmann::json to_json(const CheckReport& r) {
  const CheckStats& s = r.stats;
  nlohmann::json counts = nlohmann::json::object();
  for (int k = 0; k < kDefectKinds; ++k)
    if (r.counts[k]) counts[defect_name(static_cast<DefectKind>(k))] = r.counts[k];
  nlohmann::json defects = nlohmann::json::array();
  for (const Defect& d : r.defects) defects.push_back(to_json(d));
  return {{"valid", r.ok()},
          {"defect_counts", counts},
          {"defects", defects},
          {"points", s.points},
          {"vertices", s.vertices},
          {"duplicates", s.duplicates},
          {"tets", s.tets},
          {"edges", s.edges},
          {"interior_facets", s.interior_facets},
          {"boundary_facets", s.boundary_facets},
          {"boundary_vertices", s.boundary_vertices},
          {"boundary_components", s.boundary_components},
          {"euler", s.euler},
          {"boundary_euler", s.boundary_euler},
          {"cospherical_facets", s.cospherical_facets},
          {"covering_checked", s.degree_checked},
          {"cover_proven", s.cover_proven},
          {"volume_checked", s.volume_checked},
          {"volume_equal", s.volume_equal},
          {"input_span", span_name(s.input_span)},
          {"volume", s.cover_proven || proven_flat(s) ? nlohmann::json(s.volume_hull) : nlohmann::json(nullptr)},
          {"seconds", s.seconds}};
}

nlohmann::json to_json(const Comparison& c) {
  return {{"agree", c.agree()},
          {"general_position", c.general_position},
          {"tets_equal", c.tets_equal},
          {"complexes_equal", c.complexes_equal},
          {"cells", {c.cells_a, c.cells_b}},
          {"only_first_count", c.only_a_count},
          {"only_second_count", c.only_b_count},
          {"only_first", c.only_a},
          {"only_second", c.only_b}};
}

}  // namespace dtlab
