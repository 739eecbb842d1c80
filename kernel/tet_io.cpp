#include "kernel/tet_io.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "kernel/line_reader.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "predicates/adaptive.hpp"

namespace dtlab {

namespace {
// The tet's volume, positive for dtlab's orientation (orient3d > 0).
double orient3d_naive_volume(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  return (adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy)) / 6;
}
}  // namespace

void write_tetgen(const std::string& prefix, const Tetrahedralization& t) {
  write_node(prefix + ".node", t.points);
  OutputFile f(prefix + ".ele");
  std::fprintf(f.get(), "%zu 4 0\n", t.tets.size());
  for (std::size_t i = 0; i < t.tets.size(); ++i) {
    const Tet& k = t.tets[i];
    std::fprintf(f.get(), "%zu %u %u %u %u\n", i, k[1], k[0], k[2], k[3]);
  }
  f.close();
}

std::vector<Tet> read_ele(const std::string& path, int first_index, std::size_t point_count) {
  LineReader r(path);
  std::vector<std::string_view> tok;
  if (!r.next(tok)) r.fail("empty .ele file: missing header");
  if (tok.size() < 1 || tok.size() > 3) r.fail("header must be: <#tets> [nodes per tet] [#attributes]");
  const long n = r.to_count(tok[0], 5, "tetrahedron");
  const long per = tok.size() > 1 ? r.to_long(tok[1]) : 4;
  const long attrs = tok.size() > 2 ? r.to_long(tok[2]) : 0;
  if (per != 4) r.fail("only linear tetrahedra (4 nodes) are supported, got " + std::to_string(per));
  if (attrs < 0) r.fail("negative attribute count");
  if (attrs > kMaxAttributes) r.fail("attribute count too large: " + std::to_string(attrs));
  std::vector<Tet> tets;
  tets.reserve(std::min(static_cast<std::size_t>(n), kMaxReserve));
  for (long i = 0; i < n; ++i) {
    if (!r.next(tok)) r.fail("expected " + std::to_string(n) + " tetrahedra, file ends after " + std::to_string(i));
    if (tok.size() != static_cast<std::size_t>(5 + attrs))
      r.fail("expected " + std::to_string(5 + attrs) + " fields, got " + std::to_string(tok.size()));
    Tet k{};
    for (int j = 0; j < 4; ++j) {
      const long id = r.to_long(tok[1 + j]);
      // Compared before subtracting: an id near LONG_MIN must not overflow.
      if (id < first_index || static_cast<std::size_t>(id - first_index) >= point_count)
        r.fail("vertex index " + (tok[1 + j].size() <= 32 ? std::string(tok[1 + j]) : quote_token(tok[1 + j])) +
               " out of range");
      k[j] = static_cast<std::uint32_t>(id - first_index);
    }
    std::swap(k[0], k[1]);
    tets.push_back(k);
  }
  if (r.next(tok)) r.fail("unexpected data after the last tetrahedron (the header says " + std::to_string(n) + ")");
  return tets;
}

Tetrahedralization read_tetgen(const std::string& prefix) {
  PointFile pf = read_node(prefix + ".node");
  Tetrahedralization t;
  t.tets = read_ele(prefix + ".ele", pf.first_index, pf.points.size());
  t.points = std::move(pf.points);
  return t;
}

void write_vtu(const std::string& path, const Tetrahedralization& t, VtuFormat format) {
  VtuGrid g;
  g.points = t.points;
  g.connectivity.reserve(4 * t.tets.size());
  std::vector<double> volume;
  std::vector<std::uint8_t> defect;
  for (const Tet& k : t.tets) {
    // VTK_TETRA wants the right-handed order, like TetGen's.
    for (int j : {1, 0, 2, 3}) g.connectivity.push_back(k[j]);
    g.offsets.push_back(static_cast<std::int64_t>(g.connectivity.size()));
    g.types.push_back(kVtkTetra);
    const Point3 &a = t.points[k[0]], &b = t.points[k[1]], &c = t.points[k[2]], &d = t.points[k[3]];
    volume.push_back(orient3d_naive_volume(a, b, c, d));
    defect.push_back(adaptive_orient3d(a, b, c, d, nullptr) > 0 ? 0 : 1);
  }
  g.cell_data.push_back({"volume", std::move(volume)});
  g.cell_data.push_back({"defect", std::move(defect)});
  write_vtu_grid(path, g, format);
}

}  // namespace dtlab
