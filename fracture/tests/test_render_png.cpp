#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>

#include "fracture/render_png.hpp"

using namespace dtlab;

namespace {
std::uint32_t be32(const std::vector<std::uint8_t>& v, std::size_t i) {
  return (std::uint32_t{v[i]} << 24) | (std::uint32_t{v[i + 1]} << 16) | (std::uint32_t{v[i + 2]} << 8) | v[i + 3];
}

// The RGB pixels of a PNG written with stored deflate blocks (rows without their filter byte).
std::vector<std::uint8_t> decode_stored_png(const std::string& path, int w, int h) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> f((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(f.size() > 8 + 25 + 12);
  REQUIRE(be32(f, 16) == static_cast<std::uint32_t>(w));
  REQUIRE(be32(f, 20) == static_cast<std::uint32_t>(h));
  std::size_t i = 8 + 25 + 8 + 2;
  std::vector<std::uint8_t> raw;
  for (bool last = false; !last;) {
    last = f[i] & 1;
    const std::size_t n = f[i + 1] | (f[i + 2] << 8);
    raw.insert(raw.end(), f.begin() + i + 5, f.begin() + i + 5 + n);
    i += 5 + n;
  }
  REQUIRE(raw.size() == static_cast<std::size_t>(h) * (3 * w + 1));
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < h; ++y)
    rgb.insert(rgb.end(), raw.begin() + y * (3 * w + 1) + 1, raw.begin() + (y + 1) * (3 * w + 1));
  return rgb;
}
}  // namespace

TEST_CASE("png: the exploded view shows outer and cut faces, filling the frame") {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({(k & 1) ? 1.0 : 0.0, (k & 2) ? 1.0 : 0.0, (k & 4) ? 1.0 : 0.0});
  const std::uint32_t q[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (auto& f : q) m.triangles.push_back({f[0], f[1], f[2]}), m.triangles.push_back({f[0], f[2], f[3]});
  FractureOptions o;
  o.pieces = 8;
  o.seed = 1;
  const FractureResult r = fracture_mesh(m, o);
  const std::string path = "render_png_test.png";
  const int w = 120, h = 90;
  write_exploded_png(path, r, 0.6, w, h);
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> f((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(f.size() > 8 + 25 + 12);
  CHECK(f[0] == 137);
  CHECK(f[1] == 'P');
  REQUIRE(std::string(f.begin() + 8 + 25 + 4, f.begin() + 8 + 25 + 8) == "IDAT");
  const std::vector<std::uint8_t> rgb = decode_stored_png(path, w, h);
  std::remove(path.c_str());
  std::size_t cut = 0, outer = 0;
  int top = h, bottom = -1, left = w, rightmost = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = &rgb[3 * (static_cast<std::size_t>(y) * w + x)];
      if (p[0] == 255 && p[1] == 255 && p[2] == 255) continue;
      top = std::min(top, y), bottom = std::max(bottom, y), left = std::min(left, x), rightmost = std::max(rightmost, x);
      if (p[0] > p[1] + 30 && p[1] > p[2]) ++cut;    // orange
      else if (p[2] >= p[1] && p[1] >= p[0]) ++outer;  // grey-blue
    }
  CHECK(cut > 50);
  CHECK(outer > 50);
  CHECK((bottom - top > 0.85 * h || rightmost - left > 0.85 * w));  // fills the frame
}

TEST_CASE("png: Voronoi cells, shrunk, each in its own colour, filling the frame") {
  std::vector<Point3> sites;
  for (int i = 0; i < 27; ++i) sites.push_back({(i % 3) + 0.1 * (i % 2), ((i / 3) % 3) + 0.05 * (i % 5), (i / 9) + 0.07 * (i % 3)});
  VoronoiOptions o;
  const VoronoiDiagram vd = compute_voronoi(sites, o);
  const std::string path = "render_cells_test.png";
  const int w = 160, h = 120;
  write_cells_png(path, vd, 0.8, w, h);
  const std::vector<std::uint8_t> rgb = decode_stored_png(path, w, h);
  std::remove(path.c_str());
  std::set<std::array<int, 3>> hues;  // colours by their channel order and rough ratios
  int top = h, bottom = -1, left = w, rightmost = -1;
  std::size_t background = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = &rgb[3 * (static_cast<std::size_t>(y) * w + x)];
      if (p[0] == 255 && p[1] == 255 && p[2] == 255) {
        ++background;
        continue;
      }
      top = std::min(top, y), bottom = std::max(bottom, y), left = std::min(left, x), rightmost = std::max(rightmost, x);
      const int m = std::max({int(p[0]), int(p[1]), int(p[2]), 1});
      hues.insert({4 * p[0] / m, 4 * p[1] / m, 4 * p[2] / m});
    }
  CHECK(hues.size() >= 6);          // cells in several colours
  CHECK(background > std::size_t(w) * h / 10);  // gaps around the shrunk cells and the margins
  CHECK((bottom - top > 0.85 * h || rightmost - left > 0.85 * w));
}
