#include "fracture/piece_io.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "sampling/mesh_report_json.hpp"
#include "kernel/output_file.hpp"

namespace dtlab {

namespace {
nlohmann::json point_json(const Point3& p) { return {p.x, p.y, p.z}; }
Point3 volume_centroid(const FractureResult& r) {
  Point3 c{0, 0, 0};
  double v = 0;
  for (const auto& p : r.pieces) c += p.volume * p.centroid, v += p.volume;
  return v > 0 ? (1.0 / v) * c : c;
}

// One piece as object piece_i with groups piece_i_outer / piece_i_cut; returns the
// next vertex number.
std::size_t write_piece(std::FILE* f, std::size_t i, const Piece& p, const Point3& shift, std::size_t base) {
  std::fprintf(f, "o piece_%zu\n", i);
  for (const auto& v : p.geometry.mesh.vertices) {
    const Point3 q = v + shift;
    std::fprintf(f, "v %.17g %.17g %.17g\n", q.x, q.y, q.z);
  }
  for (int cut = 0; cut < 2; ++cut) {
    std::fprintf(f, "g piece_%zu_%s\nusemtl %s\n", i, cut ? "cut" : "outer", cut ? "cut" : "outer");
    for (std::size_t t = 0; t < p.geometry.mesh.triangles.size(); ++t) {
      if (p.geometry.cut[t] != cut) continue;
      const auto& tr = p.geometry.mesh.triangles[t];
      std::fprintf(f, "f %zu %zu %zu\n", base + tr[0], base + tr[1], base + tr[2]);
    }
  }
  return base + p.geometry.mesh.vertices.size();
}
}  // namespace

std::string piece_file_name(std::size_t i) {
  char name[32];
  std::snprintf(name, sizeof name, "piece_%04zu.obj", i);
  return name;
}

std::vector<std::string> piece_files_in(const std::string& dir) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    constexpr std::string_view head = "piece_", tail = ".obj";
    if (name.size() <= head.size() + tail.size() || !name.starts_with(head) || !name.ends_with(tail)) continue;
    const std::string_view digits = std::string_view(name).substr(head.size(), name.size() - head.size() - tail.size());
    // Only names piece_file_name gives (piece_12.obj or piece_00012.obj are someone else's).
    if (digits.size() > 18 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    if (name == piece_file_name(std::stoull(std::string(digits))) && e.is_regular_file(ec))
      paths.push_back(e.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

std::vector<std::string> write_piece_files(const std::string& dir, const FractureResult& r,
                                           const std::function<void(const std::string& path)>& placed) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const std::string name = piece_file_name(i);
    const std::string path = dir + "/" + name;
    OutputFile file(path);
    std::fprintf(file.get(), "# dtlab fracture: piece %zu of %zu\nmtllib ../pieces.mtl\n", i, r.pieces.size());
    write_piece(file.get(), i, r.pieces[i], Point3{0, 0, 0}, 1);
    file.close();
    if (placed) placed(path);
    names.push_back(name);
  }
  return names;
}

void write_pieces_obj(const std::string& path, const FractureResult& r, double explode) {
  OutputFile file(path);
  std::FILE* f = file.get();
  std::fprintf(f, "# dtlab fracture: %zu pieces\nmtllib pieces.mtl\n", r.pieces.size());
  const Point3 centre = volume_centroid(r);
  std::size_t base = 1;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const Piece& p = r.pieces[i];
    base = write_piece(f, i, p, explode * (p.centroid - centre), base);
  }
  file.close();
}

void write_pieces_mtl(const std::string& path) {
  write_text_file(path, "newmtl outer\nKd 0.70 0.72 0.78\n\nnewmtl cut\nKd 0.85 0.35 0.20\n");
}

void write_pieces_vtu(const std::string& path, const FractureResult& r, VtuFormat format) {
  VtuGrid g;
  std::vector<std::int64_t> piece, site, island, parent, cut;
  std::vector<double> volume, interior;
  std::vector<std::uint8_t> skipped;
  std::vector<std::uint32_t> offsets, corners;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const Piece& p = r.pieces[i];
    const TriangleMesh& m = p.geometry.mesh;
    offsets.assign(1, 0);
    corners.clear();
    for (const auto& t : m.triangles) {
      corners.insert(corners.end(), t.begin(), t.end());
      offsets.push_back(static_cast<std::uint32_t>(corners.size()));
    }
    g.add_polyhedron(m.vertices, offsets, corners);
    piece.push_back(static_cast<std::int64_t>(i));
    site.push_back(p.site_index);
    island.push_back(p.island);
    parent.push_back(p.parent);
    volume.push_back(p.volume);
    interior.push_back(p.interior_area);
    cut.push_back(std::count(p.geometry.cut.begin(), p.geometry.cut.end(), 1));
    skipped.push_back(p.geometry.boolean_skipped ? 1 : 0);
  }
  g.cell_data.push_back({"piece", std::move(piece)});
  g.cell_data.push_back({"site", std::move(site)});
  g.cell_data.push_back({"island", std::move(island)});
  g.cell_data.push_back({"parent", std::move(parent)});
  g.cell_data.push_back({"volume", std::move(volume)});
  g.cell_data.push_back({"interior_area", std::move(interior)});
  g.cell_data.push_back({"cut_triangles", std::move(cut)});
  g.cell_data.push_back({"boolean_skipped", std::move(skipped)});
  write_vtu_grid(path, g, format);
}

void write_piece_surfaces_vtu(const std::string& path, const FractureResult& r, VtuFormat format) {
  constexpr std::uint8_t kVtkTriangle = 5;
  VtuGrid g;
  std::vector<std::int64_t> piece, site, island;
  std::vector<std::uint8_t> cut;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const Piece& p = r.pieces[i];
    const auto base = static_cast<std::int64_t>(g.points.size());
    g.points.insert(g.points.end(), p.geometry.mesh.vertices.begin(), p.geometry.mesh.vertices.end());
    for (std::size_t t = 0; t < p.geometry.mesh.triangles.size(); ++t) {
      for (auto v : p.geometry.mesh.triangles[t]) g.connectivity.push_back(base + v);
      g.offsets.push_back(static_cast<std::int64_t>(g.connectivity.size()));
      g.types.push_back(kVtkTriangle);
      piece.push_back(static_cast<std::int64_t>(i));
      site.push_back(p.site_index);
      island.push_back(p.island);
      cut.push_back(p.geometry.cut[t] ? 1 : 0);
    }
  }
  g.cell_data.push_back({"piece", std::move(piece)});
  g.cell_data.push_back({"site", std::move(site)});
  g.cell_data.push_back({"island", std::move(island)});
  g.cell_data.push_back({"cut", std::move(cut)});
  write_vtu_grid(path, g, format);
}

void write_piece_tets_vtu(const std::string& path, const FractureResult& r, const std::vector<PieceTets>& tets,
                          VtuFormat format) {
  VtuGrid g;
  std::vector<std::int64_t> piece, site, island;
  for (std::size_t i = 0; i < r.pieces.size() && i < tets.size(); ++i) {
    const auto base = static_cast<std::int64_t>(g.points.size());
    g.points.insert(g.points.end(), tets[i].points.begin(), tets[i].points.end());
    for (const Tet& t : tets[i].tets) {
      // VTK's order: (0, 1, 2) counter-clockwise seen from 3, dtlab's with 0 and 1 swapped.
      for (auto v : {t[1], t[0], t[2], t[3]}) g.connectivity.push_back(base + v);
      g.offsets.push_back(static_cast<std::int64_t>(g.connectivity.size()));
      g.types.push_back(kVtkTetra);
      piece.push_back(static_cast<std::int64_t>(i));
      site.push_back(r.pieces[i].site_index);
      island.push_back(r.pieces[i].island);
    }
  }
  g.cell_data.push_back({"piece", std::move(piece)});
  g.cell_data.push_back({"site", std::move(site)});
  g.cell_data.push_back({"island", std::move(island)});
  write_vtu_grid(path, g, format);
}

nlohmann::json volume_identity_json(const VolumeIdentity& id, double mesh_volume) {
  return {{"float_difference", id.float_difference},
          {"float_relative", id.relative(id.float_difference, mesh_volume)},
          {"exact_difference", id.exact_difference},
          {"exact_relative", id.relative(id.exact_difference, mesh_volume)},
          {"exact", id.exact}};
}

void add_tets_to_manifest(nlohmann::json& m, const std::vector<PieceTets>& tets) {
  std::size_t count = 0, steiner = 0, exact = 0;
  for (std::size_t i = 0; i < tets.size() && i < m["pieces"].size(); ++i) {
    auto& j = m["pieces"][i];
    j["tets"] = tets[i].tets.size();
    j["steiner_points"] = tets[i].steiner;
    j["tet_volume"] = tets[i].volume;
    j["tet_volume_exact"] = tets[i].exact_match;
    count += tets[i].tets.size();
    steiner += tets[i].steiner;
    exact += tets[i].exact_match ? 1 : 0;
  }
  m["tets"] = {{"tets", count}, {"steiner_points", steiner}, {"pieces_exact", exact}, {"pieces", tets.size()}};
}

nlohmann::json fracture_manifest(const FractureResult& r, double density) {
  nlohmann::json pieces = nlohmann::json::array();
  double sum = 0;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const Piece& p = r.pieces[i];
    std::size_t cut = 0;
    for (char c : p.geometry.cut) cut += c;
    nlohmann::json j;
    j["id"] = i;
    j["volume"] = p.volume;
    j["centroid"] = point_json(p.centroid);
    const auto& I = p.inertia;
    j["inertia"] = {{I[0], I[1], I[2]}, {I[3], I[4], I[5]}, {I[6], I[7], I[8]}};
    j["site"] = point_json(p.site);
    j["site_index"] = p.site_index;
    j["island"] = p.island;
    j["site_islands"] = p.site_islands;
    j["mass"] = density * p.volume;
    j["mass_inertia"] = {{density * I[0], density * I[1], density * I[2]},
                         {density * I[3], density * I[4], density * I[5]},
                         {density * I[6], density * I[7], density * I[8]}};
    j["interior_area"] = p.interior_area;
    j["neighbors"] = p.neighbors;
    j["triangles"] = p.geometry.mesh.triangles.size();
    j["cut_triangles"] = cut;
    j["boolean_skipped"] = p.geometry.boolean_skipped;
    if (p.parent >= 0) j["parent"] = p.parent;
    sum += p.volume;
    pieces.push_back(std::move(j));
  }
  nlohmann::json m;
  m["mesh"] = mesh_report_json(r.report);
  nlohmann::json repairs = nlohmann::json::array();
  for (const auto& s : r.repairs) repairs.push_back({{"step", s.what}, {"count", s.count}, {"detail", s.detail}});
  m["repairs"] = std::move(repairs);
  m["mesh_volume"] = r.mesh_volume;
  m["piece_volume_sum"] = sum;
  m["relative_volume_error"] = r.mesh_volume != 0 ? std::abs(sum - r.mesh_volume) / r.mesh_volume : 0.0;
  m["volume_identity"] = volume_identity_json(volume_identity(r), r.mesh_volume);
  if (r.exact_tiling_checked)
    m["volume_identity"]["exact_tiling"] = {{"holds", r.exact_tiling}, {"difference", r.exact_tiling_difference}};
  m["density"] = density;
  m["sites"] = {{"count", r.sites}, {"duplicates", r.duplicate_sites}, {"without_piece", r.sites_without_piece}};
  m["booleans"] = r.booleans;
  m["skipped_booleans"] = r.skipped;
  m["seconds"] = {{"sampling", r.seconds_sampling}, {"voronoi", r.seconds_voronoi}, {"boolean", r.seconds_boolean}};
  m["pieces"] = std::move(pieces);
  return m;
}

}  // namespace dtlab
