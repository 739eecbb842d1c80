#include "voronoi/voronoi_io.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "kernel/output_file.hpp"

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

void write_cells_vtu(const std::string& path, const VoronoiDiagram& vd) {
  File out(path);
  std::size_t npts = 0, ncells = 0;
  for (const auto& c : vd.cells)
    if (!c.vertices.empty()) npts += c.vertices.size(), ++ncells;
  std::fprintf(out.f,
               "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
               "<UnstructuredGrid><Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n"
               "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
               npts, ncells);
  for (const auto& c : vd.cells)
    for (const auto& p : c.vertices) std::fprintf(out.f, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
  std::fprintf(out.f, "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  std::size_t base = 0;
  for (const auto& c : vd.cells) {
    for (std::size_t k = 0; k < c.vertices.size(); ++k) std::fprintf(out.f, "%zu ", base + k);
    if (!c.vertices.empty()) std::fputc('\n', out.f);
    base += c.vertices.size();
  }
  std::fprintf(out.f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  base = 0;
  for (const auto& c : vd.cells)
    if (!c.vertices.empty()) std::fprintf(out.f, "%zu\n", base += c.vertices.size());
  std::fprintf(out.f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (std::size_t i = 0; i < ncells; ++i) std::fprintf(out.f, "42\n");
  // Polyhedra: per cell [nfaces, (nverts, ids...)...] in point ids of the whole file.
  std::fprintf(out.f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">\n");
  std::vector<std::size_t> faceoffsets;
  std::size_t written = 0;
  base = 0;
  for (const auto& c : vd.cells) {
    if (c.vertices.empty()) continue;
    std::fprintf(out.f, "%zu", c.face_count());
    ++written;
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      std::fprintf(out.f, " %u", c.face_offsets[f + 1] - c.face_offsets[f]);
      ++written;
      for (auto k = c.face_offsets[f]; k < c.face_offsets[f + 1]; ++k, ++written)
        std::fprintf(out.f, " %zu", base + c.face_vertices[k]);
    }
    std::fputc('\n', out.f);
    faceoffsets.push_back(written);
    base += c.vertices.size();
  }
  std::fprintf(out.f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">\n");
  for (auto w : faceoffsets) std::fprintf(out.f, "%zu\n", w);
  std::fprintf(out.f, "</DataArray>\n</Cells>\n<CellData Scalars=\"site\">\n"
                      "<DataArray type=\"Int64\" Name=\"site\" format=\"ascii\">\n");
  for (std::size_t i = 0; i < vd.cells.size(); ++i)
    if (!vd.cells[i].vertices.empty()) std::fprintf(out.f, "%zu\n", i);
  std::fprintf(out.f, "</DataArray>\n</CellData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n");
  out.file.close();
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
