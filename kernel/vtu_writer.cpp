#include "kernel/vtu_writer.hpp"

#include <bit>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "kernel/output_file.hpp"

namespace dtlab {

VtuFormat parse_vtu_format(std::string_view name) {
  if (name == "ascii") return VtuFormat::ascii;
  if (name == "binary") return VtuFormat::binary;
  throw std::invalid_argument("VTU format must be ascii or binary, not '" + std::string(name) + "'");
}

const char* vtu_format_name(VtuFormat format) { return format == VtuFormat::ascii ? "ascii" : "binary"; }

void VtuGrid::add_polyhedron(std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
                             std::span<const std::uint32_t> face_vertices) {
  const auto base = static_cast<std::int64_t>(points.size());
  points.insert(points.end(), vertices.begin(), vertices.end());
  for (std::size_t k = 0; k < vertices.size(); ++k) connectivity.push_back(base + static_cast<std::int64_t>(k));
  offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  types.push_back(kVtkPolyhedron);
  const std::size_t nf = face_offsets.empty() ? 0 : face_offsets.size() - 1;
  faces.push_back(static_cast<std::int64_t>(nf));
  for (std::size_t f = 0; f < nf; ++f) {
    faces.push_back(static_cast<std::int64_t>(face_offsets[f + 1] - face_offsets[f]));
    for (auto k = face_offsets[f]; k < face_offsets[f + 1]; ++k) faces.push_back(base + face_vertices[k]);
  }
  faceoffsets.push_back(static_cast<std::int64_t>(faces.size()));
}

std::string base64_encode(const void* data, std::size_t bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes; i += 3) {
    const std::uint32_t v = (std::uint32_t{p[i]} << 16) | (std::uint32_t{p[i + 1]} << 8) | p[i + 2];
    for (int s = 18; s >= 0; s -= 6) out.push_back(kAlphabet[(v >> s) & 63]);
  }
  if (const std::size_t rest = bytes - i; rest > 0) {
    const std::uint32_t v = (std::uint32_t{p[i]} << 16) | (rest == 2 ? std::uint32_t{p[i + 1]} << 8 : 0);
    out.push_back(kAlphabet[(v >> 18) & 63]);
    out.push_back(kAlphabet[(v >> 12) & 63]);
    out.push_back(rest == 2 ? kAlphabet[(v >> 6) & 63] : '=');
    out.push_back('=');
  }
  return out;
}

namespace {
template <class T>
const char* vtk_type() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else return "UInt8";
}

class ArrayWriter {
 public:
  ArrayWriter(std::FILE* f, VtuFormat format) : f_(f), format_(format) {}

  template <class T>
  void write(const char* name, const std::vector<T>& values, int components = 1) {
    std::fprintf(f_, "    <DataArray type=\"%s\"", vtk_type<T>());
    if (name) std::fprintf(f_, " Name=\"%s\"", name);
    if (components != 1) std::fprintf(f_, " NumberOfComponents=\"%d\"", components);
    std::fprintf(f_, " format=\"%s\">\n", vtu_format_name(format_));
    if (format_ == VtuFormat::binary) {
      const std::uint64_t bytes = values.size() * sizeof(T);
      std::string raw(sizeof bytes + bytes, '\0');
      std::memcpy(raw.data(), &bytes, sizeof bytes);
      if (bytes) std::memcpy(raw.data() + sizeof bytes, values.data(), bytes);
      const std::string text = base64_encode(raw.data(), raw.size());
      std::fwrite(text.data(), 1, text.size(), f_);
      std::fputc('\n', f_);
    } else {
      for (std::size_t i = 0; i < values.size(); ++i) {
        if constexpr (std::is_same_v<T, double>) std::fprintf(f_, "%.17g", values[i]);
        else std::fprintf(f_, "%" PRId64, static_cast<std::int64_t>(values[i]));
        std::fputc((i + 1) % static_cast<std::size_t>(components * 6) == 0 || i + 1 == values.size() ? '\n' : ' ', f_);
      }
    }
    std::fprintf(f_, "    </DataArray>\n");
  }

 private:
  std::FILE* f_;
  VtuFormat format_;
};
}  // namespace

void write_vtu_grid(const std::string& path, const VtuGrid& g, VtuFormat format) {
  if (g.offsets.size() != g.cell_count() ||
      (!g.faceoffsets.empty() && g.faceoffsets.size() != g.cell_count()))
    throw std::logic_error("write_vtu_grid: one offset per cell");
  OutputFile file(path);
  std::FILE* f = file.get();
  std::fprintf(f,
               "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\" "
               "header_type=\"UInt64\">\n",
               std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian");
  std::fprintf(f, " <UnstructuredGrid>\n  <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", g.points.size(),
               g.cell_count());
  ArrayWriter w(f, format);
  std::vector<double> xyz;
  xyz.reserve(3 * g.points.size());
  for (const auto& p : g.points) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  std::fprintf(f, "   <Points>\n");
  w.write<double>("Points", xyz, 3);
  std::fprintf(f, "   </Points>\n   <Cells>\n");
  w.write<std::int64_t>("connectivity", g.connectivity);
  w.write<std::int64_t>("offsets", g.offsets);
  w.write<std::uint8_t>("types", g.types);
  if (!g.faceoffsets.empty()) {
    w.write<std::int64_t>("faces", g.faces);
    w.write<std::int64_t>("faceoffsets", g.faceoffsets);
  }
  std::fprintf(f, "   </Cells>\n");
  if (!g.cell_data.empty()) {
    std::fprintf(f, "   <CellData>\n");
    for (const auto& d : g.cell_data) {
      std::visit(
          [&](const auto& v) {
            using T = typename std::decay_t<decltype(v)>::value_type;
            if (v.size() != g.cell_count()) throw std::logic_error("write_vtu_grid: cell data " + d.name + ": one value per cell");
            w.write<T>(d.name.c_str(), v);
          },
          d.values);
    }
    std::fprintf(f, "   </CellData>\n");
  }
  std::fprintf(f, "  </Piece>\n </UnstructuredGrid>\n</VTKFile>\n");
  file.close();
}

}  // namespace dtlab
