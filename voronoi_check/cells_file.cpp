#include "voronoi_check/cells_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/peers/json_fields.hpp"

namespace dtlab {

namespace {

using nlohmann::json;

// A cells file larger than this is refused before it is parsed (a runaway peer).
constexpr std::uintmax_t kMaxCellsFile = std::uintmax_t{2} << 30;

[[noreturn]] void fail(const std::string& where, const std::string& why) {
  throw std::runtime_error(where + ": " + why);
}

// The file opened for reading after the checks that need no byte of it: a directory,
// missing, or larger than the cap. Its bytes are then parsed as they are read (no copy
// of the whole file in memory), so garbage is refused at its first bad byte.
std::ifstream open_capped(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) fail(path, "cannot open");
  if (size > kMaxCellsFile) fail(path, "larger than 2 GiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  return in;
}

// One cell being read: its vertices, face offsets, corners and neighbours.
struct CellParts {
  std::int64_t site = 0;
  std::vector<Point3> vertices;
  std::vector<std::uint32_t> offsets{0}, corners;
  std::vector<std::int32_t> neighbors;
};

// Turns each face to face away from the mean of the cell's vertices (Newell's normal),
// which lies inside a convex cell: a tool's faces may come in either orientation.
void orient_faces(CellParts& c) {
  Point3 mean{0, 0, 0};
  for (const Point3& p : c.vertices) mean += p;
  mean = (1.0 / static_cast<double>(std::max<std::size_t>(1, c.vertices.size()))) * mean;
  for (std::size_t f = 0; f + 1 < c.offsets.size(); ++f) {
    const auto b = c.corners.begin() + c.offsets[f], e = c.corners.begin() + c.offsets[f + 1];
    Point3 normal{0, 0, 0}, centre{0, 0, 0};
    for (auto k = b; k != e; ++k) {
      const Point3 p = c.vertices[*k] - mean, q = c.vertices[k + 1 == e ? *b : *(k + 1)] - mean;
      normal += cross(p, q);
      centre += p;
    }
    if (dot(normal, centre) < 0) std::reverse(b, e);
  }
}

void add_parts(ToolCells& cells, CellParts& c, const std::string& where) {
  orient_faces(c);
  try {
    cells.add_cell(c.site, c.vertices, c.offsets, c.corners, c.neighbors);
  } catch (const std::invalid_argument& e) {
    fail(where, e.what());
  }
}

// ---- JSON ----

std::int64_t json_integer(const json& j, const std::string& where, std::int64_t lo, std::int64_t hi) {
  if (!j.is_number_integer()) fail(where, "expected an integer, got " + std::string(j.type_name()));
  const std::string range = " out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
    fail(where, std::to_string(j.get<std::uint64_t>()) + range);
  const std::int64_t v = j.get<std::int64_t>();
  if (v < lo || v > hi) fail(where, std::to_string(v) + range);
  return v;
}

const json& json_array(const json& j, const std::string& where) {
  if (!j.is_array()) fail(where, "expected an array, got " + std::string(j.type_name()));
  return j;
}

Point3 json_point(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3) fail(where, "expected [x, y, z]");
  double xyz[3];
  for (int k = 0; k < 3; ++k) {
    if (!j[k].is_number()) fail(where + "[" + std::to_string(k) + "]", "not a number");
    xyz[k] = j[k].get<double>();
    if (!std::isfinite(xyz[k])) fail(where + "[" + std::to_string(k) + "]", "not finite");
  }
  return {xyz[0], xyz[1], xyz[2]};
}

void json_faces(const json& faces, const std::string& where, CellParts& c) {
  const auto nv = static_cast<std::int64_t>(c.vertices.size());
  for (std::size_t f = 0; f < json_array(faces, where).size(); ++f) {
    const std::string at = where + "[" + std::to_string(f) + "]";
    const json& loop = json_array(faces[f], at);
    if (loop.size() < 3) fail(at, "a face needs at least 3 vertices, got " + std::to_string(loop.size()));
    for (std::size_t k = 0; k < loop.size(); ++k)
      c.corners.push_back(
          static_cast<std::uint32_t>(json_integer(loop[k], at + "[" + std::to_string(k) + "]", 0, nv - 1)));
    c.offsets.push_back(static_cast<std::uint32_t>(c.corners.size()));
  }
}

void json_cell(const json& j, const std::string& where, CellParts& c) {
  if (!j.is_object()) fail(where, "expected {\"site\", \"vertices\", \"faces\", \"neighbors\"}");
  for (const auto& [key, value] : j.items())
    if (key != "site" && key != "vertices" && key != "faces" && key != "neighbors" && key != "volume")
      fail(where, "unknown field '" + key + "' (site, vertices, faces, neighbors, volume)");
  for (const char* key : {"site", "vertices", "faces", "neighbors"})
    if (!j.contains(key)) fail(where, std::string("no \"") + key + "\"");
  c = CellParts{};
  c.site = json_integer(j["site"], where + ".site", 0, std::numeric_limits<std::int64_t>::max());
  const json& vs = json_array(j["vertices"], where + ".vertices");
  if (vs.size() > std::numeric_limits<std::uint32_t>::max()) fail(where + ".vertices", "too many vertices");
  for (std::size_t k = 0; k < vs.size(); ++k)
    c.vertices.push_back(json_point(vs[k], where + ".vertices[" + std::to_string(k) + "]"));
  json_faces(j["faces"], where + ".faces", c);
  const json& nb = json_array(j["neighbors"], where + ".neighbors");
  if (nb.size() != c.offsets.size() - 1)
    fail(where + ".neighbors", std::to_string(nb.size()) + " neighbours for " + std::to_string(c.offsets.size() - 1) +
                                   " faces (one per face)");
  for (std::size_t k = 0; k < nb.size(); ++k)
    c.neighbors.push_back(static_cast<std::int32_t>(json_integer(nb[k], where + ".neighbors[" + std::to_string(k) + "]",
                                                                 -6, std::numeric_limits<std::int32_t>::max())));
}

// The line of byte `byte` (0-based) of the file: its newlines before it, counted in
// blocks (only on an error, so the parse itself keeps no line table).
long line_of_byte(const std::string& path, std::size_t byte) {
  std::ifstream in(path, std::ios::binary);
  long line = 1;
  char block[1 << 16];
  while (byte > 0 && in) {
    in.read(block, static_cast<std::streamsize>(std::min(byte, sizeof block)));
    const auto got = static_cast<std::size_t>(in.gcount());
    line += static_cast<long>(std::count(block, block + got, '\n'));
    byte -= got;
    if (got == 0) break;
  }
  return line;
}

// Byte `byte` (0-based) of the file, or -1 past its end.
int byte_at(const std::string& path, std::size_t byte) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(byte));
  const int ch = in.get();
  return in ? ch : -1;
}

// nlohmann's parser takes a NUL byte for the end of the input: a value followed by one
// would be accepted and the rest of the file never read, and a NUL in place of a value
// is "unexpected end of input". The stream is at its end after a parse only when the
// parser met the real end, so a NUL is refused by name; any other error is the
// parser's own.
json parse_json(const std::string& path, std::istream& in) {
  const auto nul = [&](std::size_t byte) {
    fail(path + ":" + std::to_string(line_of_byte(path, byte)),
         "not JSON: a NUL byte (byte " + std::to_string(byte + 1) + ")");
  };
  try {
    json root = parse_unique_fields(in);
    if (!in.eof()) nul(static_cast<std::size_t>(in.tellg()) - 1);
    return root;
  } catch (const json::parse_error& e) {
    const std::size_t byte = e.byte ? e.byte - 1 : 0;
    if (!in.eof() && byte_at(path, byte) == 0) nul(byte);
    const std::string what = e.what();
    fail(path + ":" + std::to_string(line_of_byte(path, byte)), "not JSON: " + what.substr(what.find(':') + 2));
  } catch (const DuplicateField& e) {
    fail(path, e.what());
  } catch (const json::exception& e) {  // a number out of range of a double (1e400)
    const std::string what = e.what();
    fail(path, "not JSON: " + what.substr(what.find(']') + 2));
  }
}

// ---- voro++'s .vol ----

// The words of one line of a .vol file, read in order.
class VolLine {
 public:
  VolLine(const std::string& line, std::string where) : in_(line), where_(std::move(where)) {}
  std::string word(const char* what) {
    std::string w;
    if (!(in_ >> w)) fail(where_, std::string("line ends before ") + what);
    return w;
  }
  std::int64_t integer(const char* what, std::int64_t lo, std::int64_t hi) {
    const std::string w = word(what);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || v < lo || v > hi)
      fail(where_, std::string(what) + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                       "], got '" + w.substr(0, 40) + "'");
    return v;
  }
  // "(a,b,c,...)": numbers between parentheses, separated by commas.
  template <class T>
  std::vector<T> tuple(const char* what) {
    const std::string w = word(what);
    if (w.size() < 2 || w.front() != '(' || w.back() != ')')
      fail(where_, std::string(what) + ": expected (a,b,...), got '" + w.substr(0, 40) + "'");
    std::vector<T> out;
    for (std::size_t b = 1; b < w.size();) {
      const std::size_t e = std::min(w.find(',', b), w.size() - 1);
      T v{};
      const auto [end, ec] = std::from_chars(w.data() + b, w.data() + e, v);
      if (ec != std::errc() || end != w.data() + e)
        fail(where_, std::string(what) + ": not a number in '" + w.substr(0, 40) + "'");
      out.push_back(v);
      b = e + 1;
    }
    return out;
  }
  bool at_end() {
    std::string w;
    return !(in_ >> w);
  }

 private:
  std::istringstream in_;
  std::string where_;
};

// The next line of a .vol file into `line` (false at the end), read byte by byte: a
// byte that no text line holds (a NUL, a control byte, not ASCII) is refused where it
// is, so a binary file ends the reading at its first byte, and only one line is held.
bool vol_line(std::istream& in, std::string& line, const std::string& path, long number) {
  line.clear();
  std::streambuf& buf = *in.rdbuf();
  for (int ch; (ch = buf.sbumpc()) != std::char_traits<char>::eof();) {
    if (ch == '\n') return true;
    if ((ch < 0x20 && ch != '\t' && ch != '\r') || ch >= 0x7f) {
      char what[64];
      std::snprintf(what, sizeof what, "byte 0x%02x at column %zu: not a text file", static_cast<unsigned>(ch),
                    line.size() + 1);
      fail(path + ":" + std::to_string(number), what);
    }
    line.push_back(static_cast<char>(ch));
  }
  return !line.empty();
}

void vol_cell(VolLine& in, const std::string& where, CellParts& c) {
  c = CellParts{};
  c.site = in.integer("the cell's id", 0, std::numeric_limits<std::int64_t>::max());
  const auto nv = in.integer("the vertex count", 0, std::numeric_limits<std::uint32_t>::max());
  for (std::int64_t k = 0; k < nv; ++k) {
    const std::vector<double> p = in.tuple<double>("a vertex (x,y,z)");
    if (p.size() != 3) fail(where, "a vertex with " + std::to_string(p.size()) + " coordinates");
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) fail(where, "a vertex is not finite");
    c.vertices.push_back({p[0], p[1], p[2]});
  }
  const auto nf = in.integer("the face count", 0, std::numeric_limits<std::uint32_t>::max());
  for (std::int64_t k = 0; k < nf; ++k)
    c.neighbors.push_back(static_cast<std::int32_t>(
        in.integer("a neighbour id (a site, or -1..-6 for a wall)", -6, std::numeric_limits<std::int32_t>::max())));
  for (std::int64_t k = 0; k < nf; ++k) {
    const std::vector<std::int64_t> loop = in.tuple<std::int64_t>("a face (a,b,c,...)");
    if (loop.size() < 3) fail(where, "a face with fewer than 3 vertices");
    for (auto v : loop) {
      if (v < 0 || v >= nv)
        fail(where, "face vertex " + std::to_string(v) + " out of range (" + std::to_string(nv) + " vertices)");
      c.corners.push_back(static_cast<std::uint32_t>(v));
    }
    c.offsets.push_back(static_cast<std::uint32_t>(c.corners.size()));
  }
  if (!in.at_end()) fail(where, "more fields than the format \"%i %w %P %s %n %t\" has");
}

}  // namespace

PeerCells read_cells_json(const std::string& path) {
  std::ifstream in = open_capped(path);
  const json root = parse_json(path, in);
  if (!root.is_object() || !root.contains("cells")) fail(path, "expected {\"cells\": [...]}");
  PeerCells out;
  for (const auto& [key, value] : root.items()) {
    if (key == "seconds") {
      if (!value.is_number() || !std::isfinite(value.get<double>())) fail(path + ": seconds", "not a finite number");
      out.seconds = value.get<double>();
    } else if (key != "cells") {
      fail(path, "unknown field '" + key + "' (cells, seconds)");
    }
  }
  const json& cells = json_array(root["cells"], path + ": cells");
  CellParts c;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::string where = path + ": cells[" + std::to_string(i) + "]";
    json_cell(cells[i], where, c);
    add_parts(out.cells, c, where);
  }
  return out;
}

PeerCells read_cells_vol(const std::string& path) {
  std::ifstream in = open_capped(path);
  PeerCells out;
  CellParts c;
  long number = 0;
  for (std::string line; vol_line(in, line, path, ++number);) {
    const std::string where = path + ":" + std::to_string(number);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    VolLine words(line, where);
    vol_cell(words, where, c);
    add_parts(out.cells, c, where);
  }
  return out;
}

}  // namespace dtlab
