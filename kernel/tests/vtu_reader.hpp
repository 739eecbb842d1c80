#pragma once
// A minimal .vtu reader for the tests, independent of kernel/vtu_writer.cpp: every
// DataArray (ascii, or binary: base64 of a UInt64 byte count and raw little-endian
// values) decoded to doubles (Int64 and UInt8 values are exact in a double here).
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dtlab::test {

struct VtuArray {
  std::string type, format;
  int components = 1;
  std::vector<double> values;
  std::uint64_t header_bytes = 0;  // binary: the byte count in the header
};

struct VtuFile {
  std::string first_lines;  // up to the end of the <VTKFile ...> tag
  std::size_t points = 0, cells = 0;
  std::map<std::string, VtuArray> arrays;  // by Name
};

inline std::vector<unsigned char> base64_decode(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<unsigned char> out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    const int v = value(c);
    if (v < 0) continue;  // whitespace and '=' padding
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((acc >> bits) & 0xff));
    }
  }
  return out;
}

inline std::string attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return {};
  const auto begin = at + name.size() + 3;
  return tag.substr(begin, tag.find('"', begin) - begin);
}

inline VtuFile read_vtu(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  VtuFile f;
  f.first_lines = s.substr(0, s.find('>', s.find("<VTKFile")) + 1);
  const auto piece = s.find("<Piece");
  const std::string piece_tag = s.substr(piece, s.find('>', piece) - piece);
  f.points = std::stoull(attribute(piece_tag, "NumberOfPoints"));
  f.cells = std::stoull(attribute(piece_tag, "NumberOfCells"));
  for (std::size_t pos = s.find("<DataArray"); pos != std::string::npos; pos = s.find("<DataArray", pos + 1)) {
    const auto close = s.find('>', pos);
    const std::string tag = s.substr(pos, close - pos);
    const auto end = s.find("</DataArray>", close);
    const std::string body = s.substr(close + 1, end - close - 1);
    VtuArray a;
    a.type = attribute(tag, "type");
    a.format = attribute(tag, "format");
    if (const auto c = attribute(tag, "NumberOfComponents"); !c.empty()) a.components = std::stoi(c);
    if (a.format == "ascii") {
      std::istringstream words(body);
      for (std::string w; words >> w;) a.values.push_back(std::stod(w));
    } else if (a.format == "binary") {
      const std::vector<unsigned char> raw = base64_decode(body);
      if (raw.size() < 8) throw std::runtime_error("binary DataArray shorter than its header");
      std::memcpy(&a.header_bytes, raw.data(), 8);
      const std::size_t size = a.type == "UInt8" ? 1 : 8;
      for (std::size_t k = 8; k + size <= raw.size(); k += size) {
        if (a.type == "Float64") {
          double v;
          std::memcpy(&v, &raw[k], 8);
          a.values.push_back(v);
        } else if (a.type == "Int64") {
          std::int64_t v;
          std::memcpy(&v, &raw[k], 8);
          a.values.push_back(static_cast<double>(v));
        } else {
          a.values.push_back(raw[k]);
        }
      }
      if (raw.size() - 8 != a.header_bytes) throw std::runtime_error("binary DataArray: byte count mismatch");
    } else {
      throw std::runtime_error("unknown DataArray format " + a.format);
    }
    f.arrays[attribute(tag, "Name")] = std::move(a);
  }
  return f;
}

}  // namespace dtlab::test
