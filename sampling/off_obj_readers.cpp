// The two line-oriented polygon formats: OFF and Wavefront OBJ.
#include <algorithm>
#include <cctype>

#include "kernel/line_reader.hpp"
#include "sampling/mesh_builder.hpp"
#include "sampling/mesh_io.hpp"

namespace dtlab {

TriangleMesh read_off(const std::string& path) {
  LineReader r(path);
  std::vector<std::string_view> tok;
  if (!r.next(tok)) r.fail("empty file: missing OFF header");
  // The header keyword may be followed by the counts on the same line. Prefixes ST, C
  // and N announce texture, colour and normal values after each vertex's x y z: skipped.
  {
    std::string_view h = tok[0];
    if (h.starts_with("ST")) h.remove_prefix(2);
    if (h.starts_with("C")) h.remove_prefix(1);
    if (h.starts_with("N")) h.remove_prefix(1);
    if (h != "OFF") r.fail("expected 'OFF' header (or ST/C/N variants), got '" + std::string(tok[0]) + "'");
  }
  tok.erase(tok.begin());
  if (tok.empty() && !r.next(tok)) r.fail("missing vertex and face counts");
  if (tok.size() < 2 || tok.size() > 3) r.fail("expected '<#vertices> <#faces> [#edges]'");
  const long nv = r.to_count(tok[0], 3, "vertex"), nf = r.to_count(tok[1], 4, "face");
  TriangleMesh mesh;
  // Counts come from the file: reserve no more than a sane amount up front.
  mesh.vertices.reserve(std::min(static_cast<std::size_t>(nv), kMaxReserve));
  for (long i = 0; i < nv; ++i) {
    if (!r.next(tok)) r.fail("file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (tok.size() < 3) r.fail("vertex needs 3 coordinates, got " + std::to_string(tok.size()));
    mesh.vertices.push_back({r.to_double(tok[0]), r.to_double(tok[1]), r.to_double(tok[2])});
    for (std::size_t j = 3; j < tok.size(); ++j) r.to_double(tok[j]);  // colour, normal: numbers too
  }
  mesh.triangles.reserve(std::min(static_cast<std::size_t>(nf), kMaxReserve));
  std::vector<long> poly;
  for (long i = 0; i < nf; ++i) {
    if (!r.next(tok)) r.fail("file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    const long k = r.to_long(tok[0]);
    if (k < 3) r.fail("face with " + std::to_string(k) + " corner(s), need 3");
    if (k > static_cast<long>(tok.size()) - 1)  // not k + 1: k may be LONG_MAX
      r.fail("face announces " + std::to_string(k) + " corners, lists " + std::to_string(tok.size() - 1));
    poly.clear();
    for (long j = 1; j <= k; ++j) poly.push_back(r.to_long(tok[j]));
    for (std::size_t j = static_cast<std::size_t>(k) + 1; j < tok.size(); ++j) r.to_double(tok[j]);  // colour
    detail::add_polygon(mesh, poly, path, r.line());
  }
  if (r.next(tok))
    r.fail("unexpected data after the last face (the header says " + std::to_string(nv) + " vertices, " +
           std::to_string(nf) + " faces)");
  return mesh;
}

namespace {

// OBJ statements other than v and f. Attributes and grouping (texture coordinates,
// normals, groups, smoothing, materials, display settings) do not change the surface:
// skipped. Lines, points and free-form curves or surfaces are geometry a triangle mesh
// cannot hold, and anything else is not OBJ: both refused rather than dropped.
void check_obj_statement(LineReader& r, std::string_view keyword) {
  static constexpr std::string_view kSkipped[] = {"vt",      "vn",     "g",      "o",      "s",       "mg",
                                                  "usemtl",  "mtllib", "usemap", "maplib", "lod",     "bevel",
                                                  "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech", "stech"};
  static constexpr std::string_view kUnsupported[] = {"l",    "p",     "vp",   "cstype", "deg", "bmat",
                                                      "step", "curv",  "curv2", "surf",  "parm", "trim",
                                                      "hole", "scrv",  "sp",    "end",   "con",  "call", "csh"};
  if (std::find(std::begin(kSkipped), std::end(kSkipped), keyword) != std::end(kSkipped)) return;
  if (std::find(std::begin(kUnsupported), std::end(kUnsupported), keyword) != std::end(kUnsupported))
    r.fail("OBJ '" + std::string(keyword) + "' elements (lines, points, free-form geometry) are not a triangle surface");
  r.fail("unknown OBJ statement '" + std::string(keyword) + "'");
}

}  // namespace

TriangleMesh read_obj(const std::string& path) {
  LineReader r(path);
  std::vector<std::string_view> tok;
  TriangleMesh mesh;
  std::vector<long> poly;
  while (r.next(tok)) {
    if (tok[0] == "v") {
      // v x y z, optionally w or r g b (a colour): the extra fields must be numbers.
      if (tok.size() < 4) r.fail("vertex needs 3 coordinates");
      if (tok.size() > 8) r.fail("vertex with " + std::to_string(tok.size() - 1) + " fields (x y z [w] [r g b])");
      mesh.vertices.push_back({r.to_double(tok[1]), r.to_double(tok[2]), r.to_double(tok[3])});
      for (std::size_t j = 4; j < tok.size(); ++j) r.to_double(tok[j]);
    } else if (tok[0] == "f") {
      poly.clear();
      for (std::size_t j = 1; j < tok.size(); ++j) {
        // "i", "i/t", "i//n" or "i/t/n": only the position index matters.
        std::string_view s = tok[j].substr(0, tok[j].find('/'));
        const long i = r.to_long(s);
        if (i == 0) r.fail("OBJ indices start at 1, got 0");
        const long nv = static_cast<long>(mesh.vertices.size());
        if (i > nv || i < -nv)  // named as the file writes it (1-based, or counting back)
          r.fail("vertex index " + std::string(s) + " out of range: " + std::to_string(nv) +
                 " vertices so far (OBJ counts from 1, negative indices back from the last)");
        // Negative indices count back from the last vertex read so far.
        poly.push_back(i > 0 ? i - 1 : static_cast<long>(mesh.vertices.size()) + i);
      }
      detail::add_polygon(mesh, poly, path, r.line());
    } else {
      check_obj_statement(r, tok[0]);
    }
  }
  return mesh;
}

}  // namespace dtlab
