#include "fracture/render_png.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "kernel/output_file.hpp"

namespace dtlab {

namespace {
std::uint32_t crc32(const std::uint8_t* data, std::size_t n, std::uint32_t crc = 0) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

void put32(std::vector<std::uint8_t>& v, std::uint32_t x) {
  for (int s = 24; s >= 0; s -= 8) v.push_back(static_cast<std::uint8_t>(x >> s));
}

void chunk(std::FILE* f, const char* type, const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> c;
  put32(c, static_cast<std::uint32_t>(data.size()));
  c.insert(c.end(), type, type + 4);
  c.insert(c.end(), data.begin(), data.end());
  put32(c, crc32(c.data() + 4, c.size() - 4));
  std::fwrite(c.data(), 1, c.size(), f);
}

// RGB rows -> PNG (filter 0 on every row, zlib stream of stored blocks).
void write_png(const std::string& path, int w, int h, const std::vector<std::uint8_t>& rgb) {
  std::vector<std::uint8_t> raw;
  raw.reserve(static_cast<std::size_t>(h) * (3 * w + 1));
  for (int y = 0; y < h; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), rgb.begin() + static_cast<std::ptrdiff_t>(y) * 3 * w,
               rgb.begin() + static_cast<std::ptrdiff_t>(y + 1) * 3 * w);
  }
  std::vector<std::uint8_t> z = {0x78, 0x01};
  std::uint32_t a = 1, b = 0;
  for (std::uint8_t x : raw) a = (a + x) % 65521, b = (b + a) % 65521;
  for (std::size_t i = 0; i < raw.size() || i == 0; i += 65535) {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - i);
    z.push_back(i + n >= raw.size() ? 1 : 0);
    z.push_back(static_cast<std::uint8_t>(n & 0xFF));
    z.push_back(static_cast<std::uint8_t>(n >> 8));
    z.push_back(static_cast<std::uint8_t>(~n & 0xFF));
    z.push_back(static_cast<std::uint8_t>((~n >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + static_cast<std::ptrdiff_t>(i), raw.begin() + static_cast<std::ptrdiff_t>(i + n));
    if (n == 0) break;
  }
  put32(z, (b << 16) | a);
  OutputFile file(path, "wb");  // checked and atomic: a full disk is a named failure
  std::FILE* f = file.get();
  static const std::uint8_t sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  std::fwrite(sig, 1, 8, f);
  std::vector<std::uint8_t> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(w));
  put32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
  chunk(f, "IHDR", ihdr);
  chunk(f, "IDAT", z);
  chunk(f, "IEND", {});
  file.close();
}
}  // namespace

void write_view_png(const std::string& path, const std::vector<ViewTriangle>& triangles, int w, int h) {
  const double az = 35 * M_PI / 180, el = 25 * M_PI / 180;
  const Point3 d{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};  // towards the eye
  const Point3 right{-std::sin(az), std::cos(az), 0};
  const Point3 up = cross(d, right);
  const Point3 light = (1.0 / norm(d + Point3{0.3, -0.4, 0.5})) * (d + Point3{0.3, -0.4, 0.5});
  // Projected triangles with their shaded colour.
  struct Tri {
    double x[3], y[3], z[3];
    std::array<double, 3> rgb;
  };
  std::vector<Tri> tris;
  double lo_x = std::numeric_limits<double>::max(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
  for (const ViewTriangle& v : triangles) {
    Point3 n = cross(v.corners[1] - v.corners[0], v.corners[2] - v.corners[0]);
    const double len = norm(n);
    if (len == 0 || dot(n, d) <= 0) continue;  // back face of a closed surface
    n = (1.0 / len) * n;
    const double shade = 0.3 + 0.7 * std::max(0.0, dot(n, light));
    Tri tr{};
    for (int c = 0; c < 3; ++c) tr.rgb[c] = v.colour[c] * shade;
    for (int k = 0; k < 3; ++k) {
      const Point3& q = v.corners[k];
      tr.x[k] = dot(q, right), tr.y[k] = dot(q, up), tr.z[k] = dot(q, d);
      lo_x = std::min(lo_x, tr.x[k]), hi_x = std::max(hi_x, tr.x[k]);
      lo_y = std::min(lo_y, tr.y[k]), hi_y = std::max(hi_y, tr.y[k]);
    }
    tris.push_back(tr);
  }
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(3) * w * h, 255);
  std::vector<double> depth(static_cast<std::size_t>(w) * h, -std::numeric_limits<double>::max());
  const double span = std::max(hi_x - lo_x, hi_y - lo_y);
  const double scale = span > 0 ? 0.92 * std::min(w, h) / span : 1;
  const double ox = 0.5 * w - scale * 0.5 * (lo_x + hi_x), oy = 0.5 * h + scale * 0.5 * (lo_y + hi_y);
  for (const Tri& t : tris) {
    double px[3], py[3];
    for (int k = 0; k < 3; ++k) px[k] = ox + scale * t.x[k], py[k] = oy - scale * t.y[k];
    const double area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
    if (area == 0) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({px[0], px[1], px[2]}))));
    const int x1 = std::min(w - 1, static_cast<int>(std::ceil(std::max({px[0], px[1], px[2]}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({py[0], py[1], py[2]}))));
    const int y1 = std::min(h - 1, static_cast<int>(std::ceil(std::max({py[0], py[1], py[2]}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double sx = x + 0.5, sy = y + 0.5;
        const double b0 = ((px[1] - sx) * (py[2] - sy) - (px[2] - sx) * (py[1] - sy)) / area;
        const double b1 = ((px[2] - sx) * (py[0] - sy) - (px[0] - sx) * (py[2] - sy)) / area;
        const double b2 = 1 - b0 - b1;
        if (b0 < 0 || b1 < 0 || b2 < 0) continue;
        const double z = b0 * t.z[0] + b1 * t.z[1] + b2 * t.z[2];
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        if (z <= depth[i]) continue;
        depth[i] = z;
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(255 * std::min(1.0, t.rgb[c])));
      }
  }
  write_png(path, w, h, rgb);
}

void write_exploded_png(const std::string& path, const FractureResult& r, double explode, int w, int h) {
  Point3 centre{0, 0, 0};
  double vsum = 0;
  for (const auto& p : r.pieces) centre += p.volume * p.centroid, vsum += p.volume;
  if (vsum > 0) centre = (1.0 / vsum) * centre;
  std::vector<ViewTriangle> tris;
  for (const auto& p : r.pieces) {
    const Point3 shift = explode * (p.centroid - centre);
    const TriangleMesh& m = p.geometry.mesh;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      ViewTriangle v;
      for (int k = 0; k < 3; ++k) v.corners[k] = m.corner(t, k) + shift;
      v.colour = p.geometry.cut[t] ? kCutColour : kOuterColour;
      tris.push_back(v);
    }
  }
  write_view_png(path, tris, w, h);
}

void write_cells_png(const std::string& path, const VoronoiDiagram& vd, double shrink, int w, int h) {
  std::vector<ViewTriangle> tris;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    const VoronoiCell& c = vd.cells[i];
    if (c.vertices.empty()) continue;
    // A colour per cell: hues a golden angle apart, fairly light.
    const double hue = std::fmod(0.618033988749895 * static_cast<double>(i), 1.0) * 6;
    const double f = hue - std::floor(hue);
    const double q = 1 - f;
    std::array<double, 3> rgb;
    switch (static_cast<int>(hue)) {
      case 0: rgb = {1, f, 0}; break;
      case 1: rgb = {q, 1, 0}; break;
      case 2: rgb = {0, 1, f}; break;
      case 3: rgb = {0, q, 1}; break;
      case 4: rgb = {f, 0, 1}; break;
      default: rgb = {1, 0, q}; break;
    }
    for (auto& x : rgb) x = 0.35 + 0.6 * x;
    auto at = [&](std::uint32_t k) { return c.centroid + shrink * (c.vertices[k] - c.centroid); };
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
      for (auto k = b + 1; k + 1 < e; ++k) {  // convex faces: a fan
        ViewTriangle v;
        v.corners = {at(c.face_vertices[b]), at(c.face_vertices[k]), at(c.face_vertices[k + 1])};
        v.colour = rgb;
        tris.push_back(v);
      }
    }
  }
  write_view_png(path, tris, w, h);
}

}  // namespace dtlab
