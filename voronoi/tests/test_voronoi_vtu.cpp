#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>

#include "kernel/tests/vtu_reader.hpp"
#include "tests/support/random_points.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi/voronoi_io.hpp"

using namespace dtlab;

TEST_CASE("voronoi VTU: binary decodes to the ASCII values; cell data per cell") {
  std::vector<Point3> sites = test::uniform(30, 5);
  sites.push_back(sites[3]);  // a repeated site: its empty cell is left out
  VoronoiOptions o;
  o.predicates = PredicateSpec{"exact", 0, false, true};
  const VoronoiDiagram vd = compute_voronoi(sites, o);
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string a = dir + "/dtlab_voronoi_vtu_ascii.vtu", b = dir + "/dtlab_voronoi_vtu_binary.vtu";
  write_cells_vtu(a, vd, VtuFormat::ascii);
  write_cells_vtu(b, vd);
  const test::VtuFile fa = test::read_vtu(a), fb = test::read_vtu(b);
  REQUIRE(fa.arrays.size() == fb.arrays.size());
  for (const auto& [name, arr] : fa.arrays) {
    INFO(name);
    CHECK(arr.format == "ascii");
    CHECK(fb.arrays.at(name).format == "binary");
    CHECK(fb.arrays.at(name).type == arr.type);
    CHECK(fb.arrays.at(name).values == arr.values);
  }
  CHECK(fb.first_lines.find("header_type=\"UInt64\"") != std::string::npos);
  REQUIRE(fb.cells == 30);
  const auto& site = fb.arrays.at("site").values;
  const auto& volume = fb.arrays.at("volume").values;
  double total = 0;
  std::size_t points = 0;
  for (std::size_t c = 0; c < 30; ++c) {
    const auto i = static_cast<std::size_t>(site[c]);
    CHECK(volume[c] == vd.cells[i].volume);
    total += volume[c];
    points += vd.cells[i].vertices.size();
  }
  CHECK(total == Approx(vd.box.volume()).epsilon(1e-12));
  CHECK(fb.points == points);
  CHECK(fb.arrays.at("defect").values == std::vector<double>(30, 0.0));
  CHECK(fb.arrays.at("types").values == std::vector<double>(30, 42.0));
  const auto& walls = fb.arrays.at("walls").values;
  CHECK(std::count_if(walls.begin(), walls.end(), [](double w) { return w > 0; }) > 0);
  // Face stream: the last cell's stream ends at the end of the faces array.
  CHECK(fb.arrays.at("faceoffsets").values.back() == static_cast<double>(fb.arrays.at("faces").values.size()));
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST_CASE("voronoi tets VTU: positive VTK tetrahedra that fill each cell to its volume") {
  std::vector<Point3> sites = test::uniform(40, 9);
  sites.push_back(sites[7]);  // a repeated site: no tets
  VoronoiOptions o;
  o.predicates = PredicateSpec{"exact", 0, false, true};
  const VoronoiDiagram vd = compute_voronoi(sites, o);
  const std::string path = std::filesystem::temp_directory_path().string() + "/dtlab_voronoi_tets.vtu";
  write_cells_tets_vtu(path, vd);
  const test::VtuFile f = test::read_vtu(path);
  std::remove(path.c_str());
  const auto& xyz = f.arrays.at("Points").values;
  const auto& conn = f.arrays.at("connectivity").values;
  const auto& site = f.arrays.at("site").values;
  const auto& cell_volume = f.arrays.at("cell_volume").values;
  REQUIRE(conn.size() == 4 * f.cells);
  REQUIRE(site.size() == f.cells);
  CHECK(f.arrays.at("types").values == std::vector<double>(f.cells, 10.0));
  const auto point = [&](double id) {
    const auto k = 3 * static_cast<std::size_t>(id);
    return Point3{xyz[k], xyz[k + 1], xyz[k + 2]};
  };
  std::vector<double> sum(sites.size(), 0.0);
  std::size_t not_positive = 0;
  for (std::size_t t = 0; t < f.cells; ++t) {
    // VTK's order: (0, 1, 2) counter-clockwise seen from 3, so this determinant is positive.
    const Point3 a = point(conn[4 * t]), b = point(conn[4 * t + 1]), c = point(conn[4 * t + 2]),
                 d = point(conn[4 * t + 3]);
    const Point3 u = b - a, v = c - a, w = d - a;
    const double det = u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
    if (!(det > 0)) ++not_positive;
    const auto i = static_cast<std::size_t>(site[t]);
    sum[i] += det / 6;
    CHECK(cell_volume[t] == vd.cells[i].volume);
  }
  CHECK(not_positive == 0);
  for (std::size_t i = 0; i < 40; ++i) {
    INFO("cell " << i);
    CHECK(sum[i] == Approx(vd.cells[i].volume).epsilon(1e-12));
  }
  CHECK(sum[40] == 0.0);  // the repeated site's empty cell
}
