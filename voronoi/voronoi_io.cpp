#include "voronoi/voronoi_io.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "kernel/output_file.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/voronoi_range.hpp"

namespace dtlab {

namespace {
struct File {
  OutputFile file;  // checked writes: close() throws on a failed write
  std::FILE* f;
  explicit File(const std::string& path) : file(path), f(file.get()) {}
};
nlohmann::json point_json(const Point3& p) { return {p.x, p.y, p.z}; }
}  // namespace

void write_cells_obj(const std::string& path, const VoronoiDiagram& vd) {
  File out(path);
  std::fprintf(out.f, "# dtlab voronoi: %zu cells\n", vd.cells.size());
  std::size_t base = 1;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    const VoronoiCell& c = vd.cells[i];
    if (c.vertices.empty()) continue;
    std::fprintf(out.f, "g cell_%zu\n", i);
    for (const auto& p : c.vertices) std::fprintf(out.f, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      std::fputc('f', out.f);
      for (auto k = c.face_offsets[f]; k < c.face_offsets[f + 1]; ++k)
        std::fprintf(out.f, " %zu", base + c.face_vertices[k]);
      std::fputc('\n', out.f);
    }
    base += c.vertices.size();
  }
  out.file.close();
}

void write_cells_vtu(const std::string& path, const VoronoiDiagram& vd, VtuFormat format) {
  VtuGrid g;
  std::vector<std::int64_t> site, walls;
  std::vector<double> volume;
  std::vector<std::uint8_t> defect;
  const double tol = 1e-9 * vd.scale;
  const double vertex_error = cells_rounding_floor(vd, false).vertex_error;  // --check's rule
  // Cells by vertex count (stable): meshio reads polyhedra into one block per vertex
  // count, in order of first appearance, but splits the cell data in ascending count;
  // the two agree only in this order. VTK and ParaView take any order.
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < vd.cells.size(); ++i)
    if (!vd.cells[i].vertices.empty()) order.push_back(i);  // a repeated site's empty cell is left out
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return vd.cells[a].vertices.size() < vd.cells[b].vertices.size();
  });
  for (const std::size_t i : order) {
    const VoronoiCell& c = vd.cells[i];
    g.add_polyhedron(c.vertices, c.face_offsets, c.face_vertices);
    site.push_back(static_cast<std::int64_t>(i));
    volume.push_back(c.volume);
    walls.push_back(std::count_if(c.face_neighbor.begin(), c.face_neighbor.end(), [](std::int32_t n) { return n < 0; }));
    defect.push_back(check_cell(c, tol, vertex_error).empty() ? 0 : 1);
  }
  g.cell_data.push_back({"site", std::move(site)});
  g.cell_data.push_back({"volume", std::move(volume)});
  g.cell_data.push_back({"walls", std::move(walls)});
  g.cell_data.push_back({"defect", std::move(defect)});
  write_vtu_grid(path, g, format);
}

void write_cells_tets_vtu(const std::string& path, const VoronoiDiagram& vd, VtuFormat format) {
  VtuGrid g;
  std::vector<std::int64_t> site;
  std::vector<double> cell_volume;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    const VoronoiCell& c = vd.cells[i];
    if (c.vertices.empty()) continue;
    const auto base = static_cast<std::int64_t>(g.points.size());
    g.points.insert(g.points.end(), c.vertices.begin(), c.vertices.end());
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      const auto first = c.face_vertices.begin() + c.face_offsets[f];
      const auto last = c.face_vertices.begin() + c.face_offsets[f + 1];
      if (std::find(first, last, 0u) != last) continue;  // a face through the apex: no volume
      // The face is counter-clockwise seen from outside, so clockwise seen from the apex
      // (vertex 0, inside its plane's half-space); VTK wants (0, 1, 2) counter-clockwise
      // seen from 3: each fan triangle (a, b, c) becomes (a, c, b, apex).
      for (auto k = first + 1; k + 1 < last; ++k) {
        for (const std::uint32_t v : {*first, *(k + 1), *k, 0u}) g.connectivity.push_back(base + v);
        g.offsets.push_back(static_cast<std::int64_t>(g.connectivity.size()));
        g.types.push_back(kVtkTetra);
        site.push_back(static_cast<std::int64_t>(i));
        cell_volume.push_back(c.volume);
      }
    }
  }
  g.cell_data.push_back({"site", std::move(site)});
  g.cell_data.push_back({"cell_volume", std::move(cell_volume)});
  write_vtu_grid(path, g, format);
}

nlohmann::json cells_manifest(const VoronoiDiagram& vd) {
  nlohmann::json cells = nlohmann::json::array();
  double total = 0;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    const VoronoiCell& c = vd.cells[i];
    nlohmann::json j;
    j["id"] = i;
    j["site"] = point_json(vd.sites[i]);
    j["volume"] = c.volume;
    j["centroid"] = point_json(c.centroid);
    j["faces"] = c.face_count();
    j["vertices"] = c.vertices.size();
    j["neighbors"] = c.neighbors();
    std::vector<int> walls;
    for (auto t : c.face_neighbor)
      if (t < 0) walls.push_back(t);
    j["walls"] = walls;
    if (c.duplicate_of >= 0) j["duplicate_of"] = c.duplicate_of;
    total += c.volume;
    cells.push_back(std::move(j));
  }
  nlohmann::json m;
  m["box"] = {{"lo", point_json(vd.box.lo)}, {"hi", point_json(vd.box.hi)}};
  m["box_volume"] = vd.box.volume();
  m["cell_volume_sum"] = total;
  m["tets"] = vd.tets;
  m["cells"] = std::move(cells);
  return m;
}

}  // namespace dtlab
