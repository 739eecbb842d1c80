// PLY (Stanford polygon format): ASCII, binary_little_endian and binary_big_endian.
// Reads the x, y, z properties of "vertex" and the index list of "face"; every
// other element and property is parsed only to be skipped.
#include <cmath>
#include <cstdint>
#include <vector>

#include "sampling/byte_source.hpp"
#include "sampling/mesh_builder.hpp"
#include "sampling/mesh_io.hpp"

namespace dtlab {

namespace {

enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64 };

struct Property {
  std::string name;
  Scalar type{};
  bool is_list = false;
  Scalar count_type{};
};

struct Element {
  std::string name;
  long count = 0;
  long header_line = 0;  // the line of its `element` keyword
  std::vector<Property> props;
};

bool parse_scalar(std::string_view s, Scalar& out) {
  static const std::pair<const char*, Scalar> names[] = {
      {"char", Scalar::i8},    {"int8", Scalar::i8},     {"uchar", Scalar::u8},    {"uint8", Scalar::u8},
      {"short", Scalar::i16},  {"int16", Scalar::i16},   {"ushort", Scalar::u16},  {"uint16", Scalar::u16},
      {"int", Scalar::i32},    {"int32", Scalar::i32},   {"uint", Scalar::u32},    {"uint32", Scalar::u32},
      {"float", Scalar::f32},  {"float32", Scalar::f32}, {"double", Scalar::f64},  {"float64", Scalar::f64}};
  for (const auto& [n, t] : names)
    if (s == n) {
      out = t;
      return true;
    }
  return false;
}

bool is_integer(Scalar t) { return t != Scalar::f32 && t != Scalar::f64; }

// An ASCII value of an integer property: a whole number within the type's range
// (checked before any cast: 1e30 has no integer to be cast to).
bool fits_integer_type(Scalar t, double v) {
  double lo = 0, hi = 0;
  switch (t) {
    case Scalar::i8: lo = -128, hi = 127; break;
    case Scalar::u8: hi = 255; break;
    case Scalar::i16: lo = -32768, hi = 32767; break;
    case Scalar::u16: hi = 65535; break;
    case Scalar::i32: lo = -2147483648.0, hi = 2147483647.0; break;
    case Scalar::u32: hi = 4294967295.0; break;
    default: return true;
  }
  return v >= lo && v <= hi && v == std::trunc(v);
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

class PlyData {
 public:
  PlyData(detail::ByteSource& src, bool binary, bool big_endian)
      : src_(src), binary_(binary), big_(big_endian) {}

  double read(Scalar t) {
    if (!binary_) {
      std::string_view tok;
      if (!src_.next_token(tok)) throw InputError(src_.path(), src_.line() + 1, "file ends inside the element data");
      const double v = src_.parse_double(tok, src_.token_line());
      if (is_integer(t) && v != std::trunc(v))
        throw InputError(src_.path(), src_.token_line(), "not an integer: " + quote_token(tok));
      if (!fits_integer_type(t, v))
        throw InputError(src_.path(), src_.token_line(), "integer out of range of its type: " + quote_token(tok));
      return v;
    }
    switch (t) {
      case Scalar::i8: return get<std::int8_t>();
      case Scalar::u8: return get<std::uint8_t>();
      case Scalar::i16: return get<std::int16_t>();
      case Scalar::u16: return get<std::uint16_t>();
      case Scalar::i32: return get<std::int32_t>();
      case Scalar::u32: return get<std::uint32_t>();
      case Scalar::f32: return get<float>();
      case Scalar::f64: return get<double>();
    }
    return 0;
  }
  long line() const { return binary_ ? 0 : src_.token_line(); }

 private:
  template <class T>
  double get() {
    T v;
    src_.read_raw(&v, sizeof v, big_, "element data");
    return static_cast<double>(v);
  }
  detail::ByteSource& src_;
  bool binary_, big_;
};

// After the last element: blanks only (ASCII), or nothing but a final newline (binary).
void reject_trailing_data(detail::ByteSource& src, bool binary) {
  if (!binary) {
    std::string_view tok;
    if (src.next_token(tok))
      throw InputError(src.path(), src.token_line(),
                       "unexpected data after the last element (the header's counts are read): " + quote_token(tok));
    return;
  }
  const std::string_view rest = std::string_view(src.data()).substr(std::min(src.pos(), src.size()));
  if (rest.find_first_not_of(" \t\r\n") != std::string_view::npos)
    throw InputError(src.path(), 0,
                     std::to_string(rest.size()) + " bytes after the last element (the header's counts are read)");
}

// The header: the format and the elements with their properties, up to end_header.
struct PlyHeader {
  bool binary = false, big = false;
  std::vector<Element> elements;
};

PlyHeader read_ply_header(detail::ByteSource& src, const std::string& path) {
  std::string_view line;
  auto fail = [&](const std::string& why) -> InputError { return InputError(path, src.line(), why); };
  src.skip_text_bom();
  if (!src.next_line(line) || line != "ply") throw fail("not a PLY file: first line must be 'ply'");
  PlyHeader h;
  bool have_format = false;
  for (;;) {
    if (!src.next_line(line)) throw fail("header has no 'end_header'");
    auto tok = split(line);
    if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "end_header") break;
    if (tok[0] == "format") {
      if (tok.size() != 3) throw fail("expected 'format <kind> 1.0'");
      if (tok[1] == "ascii")
        h.binary = false;
      else if (tok[1] == "binary_little_endian")
        h.binary = true, h.big = false;
      else if (tok[1] == "binary_big_endian")
        h.binary = true, h.big = true;
      else throw fail("unknown PLY format '" + std::string(tok[1]) + "'");
      have_format = true;
    } else if (tok[0] == "element") {
      if (tok.size() != 3) throw fail("expected 'element <name> <count>'");
      Element e;
      e.name = tok[1];
      const double count = src.parse_double(tok[2], src.line());
      if (count < 0 || count != std::trunc(count)) throw fail("bad element count " + quote_token(tok[2]));
      // Each element takes at least one byte of the file (ASCII: a digit and a separator).
      if (count > static_cast<double>(src.size())) throw fail("element count too large: " + quote_token(tok[2]));
      e.count = static_cast<long>(count);
      e.header_line = src.line();
      h.elements.push_back(std::move(e));
    } else if (tok[0] == "property") {
      if (h.elements.empty()) throw fail("property before any element");
      Property p;
      if (tok.size() == 5 && tok[1] == "list") {
        p.is_list = true;
        if (!parse_scalar(tok[2], p.count_type) || !is_integer(p.count_type) || !parse_scalar(tok[3], p.type))
          throw fail("bad list property types");
        p.name = tok[4];
      } else if (tok.size() == 3) {
        if (!parse_scalar(tok[1], p.type)) throw fail("unknown property type '" + std::string(tok[1]) + "'");
        p.name = tok[2];
      } else {
        throw fail("expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      }
      h.elements.back().props.push_back(std::move(p));
    } else {
      throw fail("unknown header keyword '" + std::string(tok[0]) + "'");
    }
  }
  if (!have_format) throw fail("header has no 'format' line");

  return h;
}

}  // namespace

TriangleMesh read_ply(const std::string& path) {
  detail::ByteSource src(path);
  const PlyHeader header = read_ply_header(src, path);
  const bool binary = header.binary, big = header.big;
  const std::vector<Element>& elements = header.elements;
  TriangleMesh mesh;
  PlyData in(src, binary, big);
  std::vector<long> poly;
  bool seen_vertex = false;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int ix = -1, iy = -1, iz = -1, ilist = -1;
    for (int k = 0; k < static_cast<int>(e.props.size()); ++k) {
      const Property& p = e.props[k];
      if (p.is_list) {
        if (p.name == "vertex_indices" || p.name == "vertex_index" || ilist < 0) ilist = k;
      } else if (p.name == "x") ix = k;
      else if (p.name == "y") iy = k;
      else if (p.name == "z") iz = k;
    }
    if (is_vertex && (ix < 0 || iy < 0 || iz < 0))
      throw InputError(path, e.header_line, "vertex element lacks x, y or z property");
    if (is_face && ilist < 0) throw InputError(path, e.header_line, "face element has no vertex index list");
    if (is_face && !seen_vertex && e.count > 0)
      throw InputError(path, e.header_line, "face element comes before the vertex element");
    if (is_vertex) {
      seen_vertex = true;
      mesh.vertices.reserve(std::min(static_cast<std::size_t>(e.count), kMaxReserve));  // count from the file
    }
    if (e.props.empty()) continue;  // nothing to read, however large the count
    for (long i = 0; i < e.count; ++i) {
      Point3 p{0, 0, 0};
      for (int k = 0; k < static_cast<int>(e.props.size()); ++k) {
        const Property& prop = e.props[k];
        if (prop.is_list) {
          const double n = in.read(prop.count_type);
          if (n < 0 || n > 1e9) throw InputError(path, in.line(), "bad list length");
          if (is_face && k == ilist) poly.clear();
          for (long j = 0; j < static_cast<long>(n); ++j) {
            const double v = in.read(prop.type);
            if (is_face && k == ilist && v != std::trunc(v))
              throw InputError(path, in.line(), "face index is not an integer: " + std::to_string(v));
            // An index no mesh could have becomes -1, reported as out of range below.
            if (is_face && k == ilist) poly.push_back(v >= 0 && v < 4e9 ? static_cast<long>(v) : -1);
          }
          if (is_face && k == ilist) detail::add_polygon(mesh, poly, path, in.line());
        } else {
          const double v = in.read(prop.type);
          if (k == ix) p.x = v;
          else if (k == iy) p.y = v;
          else if (k == iz) p.z = v;
        }
      }
      if (is_vertex) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw InputError(path, in.line(), "non-finite vertex coordinate");
        mesh.vertices.push_back(p);
      }
    }
  }
  reject_trailing_data(src, binary);
  return mesh;
}

}  // namespace dtlab
