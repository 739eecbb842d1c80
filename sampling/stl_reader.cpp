// STL, ASCII and binary. STL stores each triangle with its own three corners, so
// corners with bit-identical coordinates are welded into shared vertices.
#include <cctype>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "sampling/byte_source.hpp"
#include "sampling/mesh_io.hpp"

namespace dtlab {

namespace {

struct PointHash {
  std::size_t operator()(const Point3& p) const {
    std::uint64_t h = 1469598103934665603ull;
    for (double c : {p.x, p.y, p.z}) {
      if (c == 0) c = 0;  // +0 and -0 weld together
      std::uint64_t b;
      std::memcpy(&b, &c, sizeof b);
      h = (h ^ b) * 1099511628211ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
};

class Welder {
 public:
  explicit Welder(TriangleMesh& mesh) : mesh_(mesh) {}
  std::uint32_t id(const Point3& p) {
    auto [it, fresh] = ids_.try_emplace(p, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (fresh) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  std::unordered_map<Point3, std::uint32_t, PointHash> ids_;
};

TriangleMesh read_stl_binary(detail::ByteSource& src) {
  src.skip(80);
  std::uint32_t n = 0;
  src.read_raw(&n, 4, false, "triangle count");
  if (src.size() != 84 + 50ull * n)
    throw InputError(src.path(), 0,
                     "binary STL announces " + std::to_string(n) + " triangles, so " +
                         std::to_string(84 + 50ull * n) + " bytes, but the file has " +
                         std::to_string(src.size()));
  TriangleMesh mesh;
  mesh.triangles.reserve(n);
  Welder weld(mesh);
  for (std::uint32_t t = 0; t < n; ++t) {
    float f[12];
    for (float& x : f) src.read_raw(&x, 4, false, "triangle");
    src.skip(2);  // attribute byte count
    // The normal is not used, but a NaN there is refused as in an ASCII STL.
    if (!std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2]))
      throw InputError(src.path(), 0, "non-finite normal in triangle " + std::to_string(t));
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const Point3 p{f[3 + 3 * k], f[4 + 3 * k], f[5 + 3 * k]};
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InputError(src.path(), 0, "non-finite coordinate in triangle " + std::to_string(t));
      tri[k] = weld.id(p);
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

// STL keywords are matched without regard to case: some CAD exporters write
// "SOLID", "FACET NORMAL", "ENDSOLID".
bool is_keyword(std::string_view tok, std::string_view word) {
  if (tok.size() != word.size()) return false;
  for (std::size_t i = 0; i < tok.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(tok[i])) != word[i]) return false;
  return true;
}

TriangleMesh read_stl_ascii(detail::ByteSource& src) {
  TriangleMesh mesh;
  Welder weld(mesh);
  std::string_view tok;
  auto expect = [&](std::string_view word) {
    if (!src.next_token(tok)) throw InputError(src.path(), src.line() + 1, "file ends, expected '" + std::string(word) + "'");
    if (!is_keyword(tok, word))
      throw InputError(src.path(), src.token_line(),
                       "expected '" + std::string(word) + "', got '" + std::string(tok) + "'");
  };
  auto number = [&] {
    if (!src.next_token(tok)) throw InputError(src.path(), src.line() + 1, "file ends inside a facet");
    return src.parse_double(tok, src.token_line());
  };
  expect("solid");
  // The solid's name runs to the end of its line; so does endsolid's. A file may hold
  // several solids one after the other: all are read.
  std::string_view rest;
  src.next_line(rest);
  for (;;) {
    if (!src.next_token(tok)) throw InputError(src.path(), src.line() + 1, "file ends without 'endsolid'");
    if (is_keyword(tok, "endsolid")) {
      src.next_line(rest);
      if (!src.next_token(tok)) break;
      if (!is_keyword(tok, "solid"))
        throw InputError(src.path(), src.token_line(), "expected 'solid' or the end after 'endsolid', got " +
                                                           quote_token(tok));
      src.next_line(rest);
      continue;
    }
    if (!is_keyword(tok, "facet"))
      throw InputError(src.path(), src.token_line(), "expected 'facet' or 'endsolid', got '" + std::string(tok) + "'");
    expect("normal");
    for (int k = 0; k < 3; ++k) number();
    expect("outer");
    expect("loop");
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      const double x = number(), y = number(), z = number();
      tri[k] = weld.id({x, y, z});
    }
    expect("endloop");
    expect("endfacet");
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

}  // namespace

TriangleMesh read_stl(const std::string& path) {
  detail::ByteSource src(path);
  // Binary files may also begin with "solid"; their exact size gives them away. Text
  // may start with a byte order mark and blanks.
  const std::string& d = src.data();
  std::size_t text = d.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (text < d.size() && text < 80 && std::isspace(static_cast<unsigned char>(d[text]))) ++text;
  bool binary = !is_keyword(std::string_view(d).substr(text, 5), "solid");
  if (!binary && src.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, src.data().data() + 80, 4);
    // A NUL byte is no text: a binary file with a wrong count, reported as one.
    binary = src.size() == 84 + 50ull * n || src.data().find('\0') != std::string::npos;
  }
  if (binary) {
    if (src.size() < 84) throw InputError(path, 0, "binary STL shorter than its 84-byte header");
    return read_stl_binary(src);
  }
  src.skip_text_bom();
  return read_stl_ascii(src);
}

}  // namespace dtlab
