#include "kernel/npy_writer.hpp"

#include <bit>
#include <cstdio>

#include "kernel/output_file.hpp"

namespace dtlab {

static_assert(std::endian::native == std::endian::little, "the .npy writer stores the records as they are in memory");
static_assert(sizeof(Point3) == 3 * sizeof(double) && sizeof(Tet) == 4 * sizeof(std::uint32_t),
              "records without padding");

std::string npy_header(const std::string& descr, const std::string& shape) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  constexpr std::size_t kPrefix = 10;  // magic (6), version (2), header length (2)
  const std::size_t total = (kPrefix + dict.size() + 1 + 63) / 64 * 64;
  dict.append(total - kPrefix - dict.size() - 1, ' ');
  dict.push_back('\n');
  std::string out("\x93NUMPY\x01\x00", 8);
  out.push_back(static_cast<char>(dict.size() & 0xff));
  out.push_back(static_cast<char>(dict.size() >> 8));
  return out + dict;
}

namespace {
// "(rows, columns)", built by append (GCC 12's -Wrestrict misfires on operator+ chains).
std::string shape_of(std::size_t rows, int columns) {
  std::string s("(");
  s.append(std::to_string(rows)).append(", ").append(std::to_string(columns)).append(")");
  return s;
}

void write_array(const std::string& path, const std::string& header, const void* data, std::size_t bytes) {
  OutputFile f(path, "wb");
  std::fwrite(header.data(), 1, header.size(), f.get());
  if (bytes) std::fwrite(data, 1, bytes, f.get());
  f.close();
}
}  // namespace

void write_npy_points(const std::string& path, std::span<const Point3> points) {
  write_array(path, npy_header("<f8", shape_of(points.size(), 3)), points.data(),
              points.size_bytes());
}

void write_npy_tets(const std::string& path, std::span<const Tet> tets) {
  write_array(path, npy_header("<u4", shape_of(tets.size(), 4)), tets.data(), tets.size_bytes());
}

void write_npy(const std::string& prefix, const Tetrahedralization& t) {
  write_npy_points(prefix + ".points.npy", t.points);
  write_npy_tets(prefix + ".tets.npy", t.tets);
}

}  // namespace dtlab
