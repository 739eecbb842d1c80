#include <catch2/catch.hpp>

#include <cstring>

#include "sampling/mesh_io.hpp"
#include "sampling/mesh_report.hpp"
#include "scratch.hpp"

using namespace dtlab;
using test::input_error;
using test::write_file;

namespace {

// A unit tetrahedron, outward oriented, in each format.
const char* kTetOff =
    "OFF\n# comment\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

void check_tet(const TriangleMesh& m) {
  REQUIRE(m.vertices.size() == 4);
  REQUIRE(m.triangles.size() == 4);
  const MeshReport r = analyze_mesh(m);
  CHECK(r.closed);
  CHECK(r.oriented);
  CHECK(r.volume == Approx(1.0 / 6));
}

template <class T>
void put(std::string& s, T v) {
  char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  s.append(b, sizeof v);
}

std::string binary_stl(int triangles_announced) {
  const float tris[4][3][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}},
                               {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                               {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                               {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::string s(80, ' ');
  put<std::uint32_t>(s, static_cast<std::uint32_t>(triangles_announced));
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) put<float>(s, 0.f);
    for (const auto& v : t)
      for (float c : v) put<float>(s, c);
    put<std::uint16_t>(s, 0);
  }
  return s;
}

}  // namespace

TEST_CASE("OFF reader: tetrahedron, polygons split into fans, errors with line numbers") {
  check_tet(read_mesh(write_file("tet.off", kTetOff)));
  // A quad face becomes two triangles; colour values after the indices are ignored.
  auto quad = read_off(write_file("quad.off", "OFF 4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n"));
  CHECK(quad.triangles.size() == 2);
  // COFF: four colour values follow each vertex.
  auto coff = read_off(write_file("c.off", "COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n"));
  CHECK(coff.vertices[1] == Point3{1, 0, 0});
  CHECK(input_error([] { read_off(write_file("bad0.off", "4OFF\n")); }).rfind("1:expected 'OFF' header", 0) == 0);
  CHECK(input_error([] { read_off(write_file("bad1.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")); }) ==
        "6:vertex index 7 out of range (mesh has 3 vertices)");
  CHECK(input_error([] { read_off(write_file("bad2.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n")); }) ==
        "4:not a number: 'zero'");
  CHECK(input_error([] { read_off(write_file("bad3.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n")); }).rfind("4:file ends", 0) == 0);
  CHECK(input_error([] { read_off(write_file("bad4.off", "PLY\n")); }).rfind("1:expected 'OFF'", 0) == 0);
  CHECK(input_error([] { read_off(write_file("bad5.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n")); }) ==
        "6:face with 2 corner(s), need 3");
}

TEST_CASE("OBJ reader: slashes, negative indices, attributes skipped, other statements refused, errors") {
  check_tet(read_mesh(write_file("tet.obj",
                                 "# tet\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvt 0 0\n"
                                 "f 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf -4 -1 -2\ng x\nf 2 3 4\n")));
  CHECK(input_error([] { read_obj(write_file("bad1.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n")); }) ==
        "4:OBJ indices start at 1, got 0");
  // An index out of range is named as the file writes it (1-based, or counting back).
  CHECK(input_error([] { read_obj(write_file("bad2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")); }) ==
        "4:vertex index 4 out of range: 3 vertices so far (OBJ counts from 1, negative indices back from the last)");
  CHECK(input_error([] {
          read_obj(write_file("bad2n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"));
        }).rfind("4:vertex index -4 out of range: 3 vertices so far", 0) == 0);
  CHECK(input_error([] {
          read_obj(write_file("bad2s.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/2 7/3\n"));
        }).rfind("4:vertex index 7 out of range", 0) == 0);
  CHECK(input_error([] { read_obj(write_file("bad3.obj", "v 0 0\n")); }) == "1:vertex needs 3 coordinates");
  // Attribute and grouping statements are skipped; geometry a triangle surface cannot
  // hold, and statements OBJ does not have, are refused rather than dropped.
  check_tet(read_mesh(write_file("tet_attr.obj", "mtllib a.mtl\no t\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ns off\n"
                                                 "usemtl m\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")));
  CHECK(input_error([] { read_obj(write_file("bad4.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n")); })
            .rfind("3:OBJ 'l' elements", 0) == 0);
  CHECK(input_error([] { read_obj(write_file("bad5.obj", "v 0 0 0\nbogus line\n")); }) ==
        "2:unknown OBJ statement 'bogus'");
}

TEST_CASE("PLY reader: ASCII and binary little/big endian, extra properties and elements") {
  const std::string header_tail =
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      "element face 4\nproperty list uchar int vertex_indices\nelement edge 1\nproperty int v1\nproperty int v2\n"
      "end_header\n";
  check_tet(read_mesh(write_file("tet_ascii.ply",
                                 "ply\nformat ascii 1.0\ncomment made by a test\n" + header_tail +
                                     "0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n0 1\n")));
  for (bool big : {false, true}) {
    std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\n" + header_tail;
    auto put_be = [&](auto v) {
      std::string t;
      put(t, v);
      if (big) std::reverse(t.begin(), t.end());
      s += t;
    };
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& p : v) {
      for (float c : p) put_be(c);
      put_be(std::uint8_t{9});
    }
    const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& t : f) {
      put_be(std::uint8_t{3});
      for (int i : t) put_be(std::int32_t{i});
    }
    put_be(std::int32_t{0});
    put_be(std::int32_t{1});
    check_tet(read_ply(write_file(big ? "tet_be.ply" : "tet_le.ply", s)));
    // Cut inside the face data: a binary defect, reported at line 0.
    const std::string cut = s.substr(0, s.size() - 20);
    CHECK(input_error([&] { read_ply(write_file("cut.ply", cut)); }).rfind("0:file truncated", 0) == 0);
  }
  CHECK(input_error([&] {
          read_ply(write_file("bad1.ply", "ply\nformat ascii 1.0\n" + header_tail + "0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n3 0 2 1\n3 0 1 9\n"));
        }) == "19:vertex index 9 out of range (mesh has 4 vertices)");
  CHECK(input_error([] { read_ply(write_file("bad2.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n")); }) ==
        "4:unknown property type 'quad'");
  CHECK(input_error([] { read_ply(write_file("bad3.ply", "ply\nformat ascii 1.0\nelement vertex 1\n")); }) ==
        "3:header has no 'end_header'");
}

TEST_CASE("STL reader: ASCII and binary, corners welded into shared vertices") {
  check_tet(read_mesh(write_file("tet.stl", binary_stl(4))));
  std::string ascii = "solid tet\n";
  const char* tris[4] = {"0 0 0\n vertex 0 1 0\n vertex 1 0 0", "0 0 0\n vertex 1 0 0\n vertex 0 0 1",
                         "0 0 0\n vertex 0 0 1\n vertex 0 1 0", "1 0 0\n vertex 0 1 0\n vertex 0 0 1"};
  for (const char* t : tris)
    ascii += std::string("facet normal 0 0 0\n outer loop\n vertex ") + t + "\n endloop\nendfacet\n";
  ascii += "endsolid tet\n";
  check_tet(read_stl(write_file("tet_ascii.stl", ascii)));
  CHECK(input_error([] { read_stl(write_file("short.stl", binary_stl(5))); }).rfind("0:binary STL announces 5", 0) == 0);
  std::string broken = ascii;
  broken.replace(broken.find("endloop"), 7, "endlop");
  CHECK(input_error([&] { read_stl(write_file("bad.stl", broken)); }) == "7:expected 'endloop', got 'endlop'");
  // Upper-case keywords (some CAD exporters) are the same file, not a binary one with a
  // wrong triangle count.
  std::string upper = ascii;
  for (char& ch : upper)
    if (ch >= 'a' && ch <= 'z') ch = static_cast<char>(ch - 'a' + 'A');
  check_tet(read_stl(write_file("tet_upper.stl", upper)));
}

TEST_CASE("read_mesh rejects unknown extensions and missing files") {
  CHECK(input_error([] { read_mesh("/nonexistent/x.off"); }) == "0:cannot open file");
  CHECK(input_error([] { read_mesh(write_file("x.dae", "")); }).rfind("0:unknown mesh extension", 0) == 0);
}

TEST_CASE("write_off round-trips through read_off") {
  TriangleMesh m = read_off(write_file("tet2.off", kTetOff));
  const auto p = test::scratch("round.off").string();
  write_off(p, m);
  TriangleMesh back = read_off(p);
  CHECK(back.vertices == m.vertices);
  CHECK(back.triangles == m.triangles);
}
