#include "voronoi_check/tool_cells.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dtlab {

using namespace vor;

void ToolCells::add_cell(std::int64_t site, std::span<const Point3> vertices,
                         std::span<const std::uint32_t> face_offsets, std::span<const std::uint32_t> face_vertices,
                         std::span<const std::int32_t> face_neighbor) {
  const std::size_t nf = face_neighbor.size();
  const auto fail = [site](const std::string& why) {
    throw std::invalid_argument("cell of site " + std::to_string(site) + ": " + why);
  };
  if (!face_offsets.empty() && face_offsets.size() != nf + 1)
    fail(std::to_string(nf) + " face neighbours for " + std::to_string(face_offsets.size() - 1) +
         " faces (one per face)");
  if (face_offsets.size() != nf + 1 || face_offsets[0] != 0 || face_offsets[nf] != face_vertices.size())
    fail("face offsets do not match its faces");
  for (std::size_t f = 0; f < nf; ++f) {
    if (face_offsets[f + 1] < face_offsets[f]) fail("face offsets do not rise");
    const std::uint32_t corners = face_offsets[f + 1] - face_offsets[f];
    if (corners < 3)
      fail("face " + std::to_string(f) + " has " + std::to_string(corners) + " corners (a face needs at least 3)");
  }
  for (auto id : face_neighbor)
    if (id < -6) fail("neighbour id " + std::to_string(id) + " is neither a site (>= 0) nor a wall (-1..-6)");
  for (auto v : face_vertices)
    if (v >= vertices.size()) fail("a corner out of range");
  for (const auto& p : vertices)
    if (!is_finite(p)) fail("a vertex is not finite");
  site_.push_back(site);
  v_.insert(v_.end(), vertices.begin(), vertices.end());
  fo_.insert(fo_.end(), face_offsets.begin(), face_offsets.end());
  fv_.insert(fv_.end(), face_vertices.begin(), face_vertices.end());
  fn_.insert(fn_.end(), face_neighbor.begin(), face_neighbor.end());
  v_off_.push_back(v_.size());
  fo_off_.push_back(fo_.size());
  fv_off_.push_back(fv_.size());
  fn_off_.push_back(fn_.size());
}

VoronoiCell ToolCells::cell(std::size_t c) const {
  VoronoiCell out = view(c);
  out.volume = cell_volume(out);
  return out;
}

VoronoiCell ToolCells::view(std::size_t c) const {
  VoronoiCell out;
  out.vertices = {v_.data() + v_off_[c], v_off_[c + 1] - v_off_[c]};
  out.face_offsets = {fo_.data() + fo_off_[c], fo_off_[c + 1] - fo_off_[c]};
  out.face_vertices = {fv_.data() + fv_off_[c], fv_off_[c + 1] - fv_off_[c]};
  out.face_neighbor = {fn_.data() + fn_off_[c], fn_off_[c + 1] - fn_off_[c]};
  return out;
}

void ToolCells::erase(std::size_t c) {
  ToolCells rest;
  for (std::size_t k = 0; k < size(); ++k) {
    if (k == c) continue;
    const VoronoiCell v = cell(k);
    rest.add_cell(site_[k], v.vertices, v.face_offsets, v.face_vertices, v.face_neighbor);
  }
  *this = std::move(rest);
}

ToolCells tool_cells_of(const VoronoiDiagram& diagram) {
  ToolCells t;
  for (std::size_t i = 0; i < diagram.cells.size(); ++i) {
    const VoronoiCell& c = diagram.cells[i];
    if (c.face_count() == 0) continue;
    t.add_cell(static_cast<std::int64_t>(i), c.vertices, c.face_offsets, c.face_vertices, c.face_neighbor);
  }
  return t;
}

double cell_volume(const VoronoiCell& c) {
  if (c.vertices.empty()) return 0;
  const Point3 o = c.vertices[0];
  double vol = 0;
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    const Point3 a = c.vertices[c.face_vertices[b]] - o;
    for (auto k = b + 1; k + 1 < e; ++k)
      vol += det3(a, c.vertices[c.face_vertices[k]] - o, c.vertices[c.face_vertices[k + 1]] - o);
  }
  return vol / 6;
}

}  // namespace dtlab
