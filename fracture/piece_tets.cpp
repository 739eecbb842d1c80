#include "fracture/piece_tets.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>

#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"
#include "oracle/check/exact_volume.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "predicates/adaptive.hpp"

namespace dtlab {

namespace {
std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// TetGen's .smesh: the vertices (shortest round-trip text, so TetGen reads our doubles)
// and one triangle facet each; no holes, no regions.
void write_smesh(const std::string& path, const TriangleMesh& m) {
  std::string s = std::to_string(m.vertices.size()) + " 3 0 0\n";
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const Point3& p = m.vertices[i];
    s += std::to_string(i) + ' ' + shortest(p.x) + ' ' + shortest(p.y) + ' ' + shortest(p.z) + '\n';
  }
  s += std::to_string(m.triangles.size()) + " 0\n";
  for (const auto& t : m.triangles)
    s += "3 " + std::to_string(t[0]) + ' ' + std::to_string(t[1]) + ' ' + std::to_string(t[2]) + '\n';
  s += "0\n0\n";
  write_text_file(path, s);
}

std::array<std::uint32_t, 3> sorted(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::array<std::uint32_t, 3> f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

// The tets tile the region the surface bounds: every tet positively oriented (exact
// sign), every tet face shared by two tets or a surface triangle (each used once), so
// the tets cover every point inside exactly once (the surface's winding number).
void check_tiling(const PieceTets& pt, const TriangleMesh& surface) {
  std::map<std::array<std::uint32_t, 3>, int> faces;  // count: tets minus surface uses
  for (std::size_t k = 0; k < pt.tets.size(); ++k) {
    const Tet& t = pt.tets[k];
    const Point3 &a = pt.points[t[0]], &b = pt.points[t[1]], &c = pt.points[t[2]], &d = pt.points[t[3]];
    if (adaptive_orient3d(a, b, c, d, nullptr) <= 0)
      throw std::runtime_error("tetgen: tet " + std::to_string(k) + " is flat or inverted");
    ++faces[sorted(t[1], t[2], t[3])];
    ++faces[sorted(t[0], t[2], t[3])];
    ++faces[sorted(t[0], t[1], t[3])];
    ++faces[sorted(t[0], t[1], t[2])];
  }
  for (const auto& t : surface.triangles) --faces[sorted(t[0], t[1], t[2])];
  for (const auto& [f, n] : faces)
    if (n != 0 && n != 2)
      throw std::runtime_error("tetgen: the tets' boundary is not the piece's surface (face " + std::to_string(f[0]) +
                               " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + ")");
}
}  // namespace

PieceTets tetrahedralize_piece(const TriangleMesh& surface, const TetgenRunOptions& options) {
  TempDir dir("dtlab-piece-tets");
  const std::string in = dir.file("piece.smesh");
  write_smesh(in, surface);
  // -p: the surface is a PLC; -Y: keep its triangles (no Steiner points on it); -z:
  // numbered from 0; -J: keep every input vertex, in order; -F: no .face/.edge; -Q quiet.
  const ChildResult c = run_child({options.binary, "-pYzJFQ", in}, ChildLimits::of(options.timeout_s, dir.file("log")));
  switch (c.status) {
    case ChildStatus::not_started: throw std::runtime_error("tetgen: " + c.message);
    case ChildStatus::timed_out:
      throw std::runtime_error("tetgen timed out after " + shortest(options.timeout_s) + " s");
    case ChildStatus::output_limit: throw std::runtime_error("tetgen wrote past its output limit");
    case ChildStatus::signaled:
      throw std::runtime_error("tetgen killed by signal " + std::to_string(c.signal) + ": " +
                               last_line_of(dir.file("log")));
    case ChildStatus::exited:
      if (c.exit_code != 0)
        throw std::runtime_error("tetgen exited with status " + std::to_string(c.exit_code) + ": " +
                                 last_line_of(dir.file("log")));
  }
  PieceTets pt;
  try {
    const PointFile node = read_node(dir.file("piece.1.node"));
    if (node.points.size() < surface.vertices.size())
      throw std::runtime_error("tetgen returned fewer vertices than the surface has");
    pt.points = surface.vertices;  // TetGen prints 16 digits: keep ours bit for bit
    pt.points.insert(pt.points.end(), node.points.begin() + static_cast<std::ptrdiff_t>(surface.vertices.size()),
                     node.points.end());
    pt.steiner = node.points.size() - surface.vertices.size();
    pt.tets = read_ele(dir.file("piece.1.ele"), 0, pt.points.size());
  } catch (const InputError& e) {
    throw std::runtime_error(std::string("tetgen output unreadable: ") + e.what());
  }
  check_tiling(pt, surface);
  const VolumeSums v = exact_volume_sums(pt.points, pt.tets, surface.triangles);
  pt.volume = v.tets;
  pt.surface_volume = v.hull;
  pt.exact_match = v.equal;
  return pt;
}

std::vector<PieceTets> tetrahedralize_pieces(const FractureResult& r, const TetgenRunOptions& options) {
  std::vector<PieceTets> out;
  out.reserve(r.pieces.size());
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    try {
      out.push_back(tetrahedralize_piece(r.pieces[i].geometry.mesh, options));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("piece " + std::to_string(i) + ": " + e.what());
    }
  }
  return out;
}

}  // namespace dtlab
