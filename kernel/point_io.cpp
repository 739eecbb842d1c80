#include "kernel/point_io.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>

#include "kernel/line_reader.hpp"
#include "kernel/output_file.hpp"
#include "kernel/record_writer.hpp"

namespace dtlab {

namespace {

// The extension in lower case, with its dot ("" when the name has none).
std::string extension_of(const std::string& path) {
  const auto dot = path.find_last_of("./");
  std::string ext = dot == std::string::npos || path[dot] == '/' ? "" : path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// x y z and at most this many more numeric columns (normals, colours, weights).
constexpr std::size_t kMaxXyzFields = 256;

}  // namespace

PointFile read_points(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".node") return read_node(path);
  if (ext == ".xyz" || ext == ".txt" || ext == ".pwn") return read_xyz(path);
  throw InputError(path, 0, "unknown point file extension (expected .node, .xyz, .pwn or .txt)");
}

PointFile read_node(const std::string& path) {
  LineReader r(path);
  std::vector<std::string_view> tok;
  if (!r.next(tok)) r.fail("empty .node file: missing header");
  if (tok.size() < 1 || tok.size() > 4) r.fail("header must be: <#points> [dim] [#attributes] [#markers]");
  const long dim = tok.size() > 1 ? r.to_long(tok[1]) : 3;
  if (dim != 3) r.fail("dimension must be 3, got " + std::to_string(dim));
  const long n = r.to_count(tok[0], 4, "point");
  const long attrs = tok.size() > 2 ? r.to_long(tok[2]) : 0;
  const long markers = tok.size() > 3 ? r.to_long(tok[3]) : 0;
  if (attrs < 0 || markers < 0 || markers > 1) r.fail("bad attribute or marker count");
  if (attrs > kMaxAttributes) r.fail("attribute count too large: " + std::to_string(attrs));
  PointFile out;
  out.points.reserve(std::min(static_cast<std::size_t>(n), kMaxReserve));
  const std::size_t want = 4 + static_cast<std::size_t>(attrs + markers);
  for (long i = 0; i < n; ++i) {
    if (!r.next(tok, want + 16))
      r.fail("expected " + std::to_string(n) + " points, file ends after " + std::to_string(i));
    if (tok.size() != want)
      r.fail("expected " + std::to_string(want) + " fields, got " + std::to_string(tok.size()));
    const long index = r.to_long(tok[0]);
    if (i == 0) {
      if (index != 0 && index != 1) r.fail("first point index must be 0 or 1");
      out.first_index = static_cast<int>(index);
    } else if (index != i + out.first_index) {
      r.fail("point index " + std::to_string(index) + " out of sequence (expected " +
             std::to_string(i + out.first_index) + ")");
    }
    out.points.push_back({r.to_double(tok[1]), r.to_double(tok[2]), r.to_double(tok[3])});
  }
  if (r.next(tok)) r.fail("unexpected data after the last point");
  return out;
}

PointFile read_xyz(const std::string& path) {
  LineReader r(path);
  std::vector<std::string_view> tok;
  PointFile out;
  std::size_t fields = 0;  // set by the first line: every line has as many
  long first_line = 0;
  while (r.next(tok, kMaxXyzFields)) {
    if (tok.size() < 3) r.fail("expected 'x y z', got " + std::to_string(tok.size()) + " field(s)");
    if (fields == 0) {
      fields = tok.size();
      first_line = r.line();
    } else if (tok.size() != fields) {
      r.fail("expected " + std::to_string(fields) + " fields as on line " + std::to_string(first_line) + ", got " +
             std::to_string(tok.size()));
    }
    out.points.push_back({r.to_double(tok[0]), r.to_double(tok[1]), r.to_double(tok[2])});
    for (std::size_t k = 3; k < tok.size(); ++k) r.to_double(tok[k]);  // attributes: numbers too, not read
  }
  return out;
}

void write_node(const std::string& path, const std::vector<Point3>& points, unsigned threads) {
  OutputFile f(path);
  std::fprintf(f.get(), "%zu 3 0 0\n", points.size());
  write_records(f, points.size(), kMaxIntChars + 3 * (kMaxDoubleChars + 1) + 1, threads, [&](std::size_t i, char* out) {
    out = put_chars(out, std::uint64_t{i});
    for (double c : {points[i].x, points[i].y, points[i].z}) *out++ = ' ', out = put_chars(out, c);
    *out++ = '\n';
    return out;
  });
  f.close();
}

void write_xyz(const std::string& path, const std::vector<Point3>& points, unsigned threads) {
  OutputFile f(path);
  write_records(f, points.size(), 3 * (kMaxDoubleChars + 1), threads, [&](std::size_t i, char* out) {
    out = put_chars(out, points[i].x);
    *out++ = ' ', out = put_chars(out, points[i].y);
    *out++ = ' ', out = put_chars(out, points[i].z);
    *out++ = '\n';
    return out;
  });
  f.close();
}

}  // namespace dtlab
