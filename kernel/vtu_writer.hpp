#pragma once
// ParaView's XML unstructured grid (.vtu), VTK file version 1.0 with UInt64 headers,
// for tetrahedralizations (kernel/tet_io), Voronoi cells (voronoi/voronoi_io) and
// fracture pieces (fracture/piece_io). Two encodings of every DataArray:
//  - ascii: the values as text (doubles with 17 significant digits: exact);
//  - binary (the default): VTK's inline uncompressed "binary" format, the base64 text
//    of one byte string: the array's byte count as a UInt64, then the raw values, all
//    in the machine's byte order (named in byte_order, LittleEndian here).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab {

enum class VtuFormat { ascii, binary };
// "ascii" or "binary"; throws std::invalid_argument otherwise.
VtuFormat parse_vtu_format(std::string_view name);
const char* vtu_format_name(VtuFormat format);

inline constexpr std::uint8_t kVtkTetra = 10;
inline constexpr std::uint8_t kVtkPolyhedron = 42;

// One value per cell: Float64, Int64 or UInt8.
struct VtuCellData {
  std::string name;
  std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::uint8_t>> values;
};

struct VtuGrid {
  std::vector<Point3> points;
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;  // end of each cell's points in connectivity
  std::vector<std::uint8_t> types;
  // Polyhedra only: per cell [face count, (point count, point ids)...] in `faces`, and
  // the end of each cell's stream in `faceoffsets`.
  std::vector<std::int64_t> faces, faceoffsets;
  std::vector<VtuCellData> cell_data;

  std::size_t cell_count() const { return types.size(); }
  // Appends a VTK_POLYHEDRON cell with its own copy of `vertices`; face f is
  // face_vertices[face_offsets[f] .. face_offsets[f + 1]) (indices into `vertices`),
  // counter-clockwise seen from outside.
  void add_polyhedron(std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
                      std::span<const std::uint32_t> face_vertices);
};

// Throws (InputError naming the file) when it cannot be written.
void write_vtu_grid(const std::string& path, const VtuGrid& grid, VtuFormat format);

// Standard base64 (RFC 4648, with '=' padding).
std::string base64_encode(const void* data, std::size_t bytes);

}  // namespace dtlab
