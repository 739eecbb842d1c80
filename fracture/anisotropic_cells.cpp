#include "fracture/anisotropic_cells.hpp"

#include <stdexcept>

namespace dtlab {

namespace {
Point3 times(const Point3& p, const Point3& s) { return {p.x * s.x, p.y * s.y, p.z * s.z}; }
Point3 divided(const Point3& p, const Point3& s) { return {p.x / s.x, p.y / s.y, p.z / s.z}; }
}  // namespace

ScaledCells anisotropic_voronoi(const std::vector<Point3>& sites, VoronoiOptions o, const Point3& s) {
  if (!(s.x > 0 && s.y > 0 && s.z > 0)) throw std::invalid_argument("--cell-scale: every factor must be positive");
  if (!o.box) throw std::invalid_argument("anisotropic_voronoi needs a box");
  std::vector<Point3> scaled;
  for (const auto& p : sites) scaled.push_back(divided(p, s));
  o.box = vor::Box{divided(o.box->lo, s), divided(o.box->hi, s)};
  ScaledCells out;
  out.diagram = compute_voronoi(scaled, o);
  out.diagram.sites = sites;
  out.diagram.box = vor::Box{times(out.diagram.box.lo, s), times(out.diagram.box.hi, s)};
  const double jacobian = s.x * s.y * s.z;
  out.vertices.resize(out.diagram.cells.size());
  for (std::size_t i = 0; i < out.diagram.cells.size(); ++i) {
    VoronoiCell& c = out.diagram.cells[i];
    for (const auto& v : c.vertices) out.vertices[i].push_back(times(v, s));
    c.vertices = out.vertices[i];
    c.volume *= jacobian;
    c.centroid = times(c.centroid, s);
  }
  return out;
}

}  // namespace dtlab
