#include "kernel/tet_io.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>

#include "kernel/input_file.hpp"
#include "kernel/line_reader.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "kernel/record_writer.hpp"
#include "predicates/adaptive.hpp"

namespace dtlab {

namespace {
// The tet's volume, positive for dtlab's orientation (orient3d > 0).
double orient3d_naive_volume(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  return (adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy)) / 6;
}
}  // namespace

void write_tetgen(const std::string& prefix, const Tetrahedralization& t, unsigned threads) {
  write_node(prefix + ".node", t.points, threads);
  write_ele(prefix + ".ele", t.tets, threads);
}

void write_ele(const std::string& path, std::span<const Tet> tets, unsigned threads) {
  OutputFile f(path);
  std::fprintf(f.get(), "%zu 4 0\n", tets.size());
  write_records(f, tets.size(), 5 * (kMaxIntChars + 1), threads, [&](std::size_t i, char* out) {
    const Tet& k = tets[i];
    out = put_chars(out, std::uint64_t{i});
    for (int j : {1, 0, 2, 3}) *out++ = ' ', out = put_chars(out, std::uint64_t{k[j]});
    *out++ = '\n';
    return out;
  });
  f.close();
}

namespace {

// The common shape of an .ele file, read in 1 MiB blocks without tokenizing:
// a header `N [4 [0]]`, then exactly N lines of five unsigned integers separated by
// blanks, then nothing but blanks. Anything else (comments, attributes, CR, commas,
// signs, an index out of range, a short file) returns nothing and the strict reader
// below reads the file again: it is the authority on every error message, and on
// the files this path takes it would give the same tets.
class PlainEleReader {
 public:
  PlainEleReader(const std::string& path, int first_index, std::size_t point_count)
      : path_(path), f_(std::fopen(path.c_str(), "rb")), first_(first_index), points_(point_count), buf_(1 << 20) {
    at_ = end_ = buf_.data();
  }
  ~PlainEleReader() {
    if (f_) std::fclose(f_);
  }
  PlainEleReader(const PlainEleReader&) = delete;
  PlainEleReader& operator=(const PlainEleReader&) = delete;

  std::optional<std::vector<Tet>> read() {
    if (!f_) return std::nullopt;
    std::uint64_t head[3] = {0, 4, 0};
    if (line(head, 3) < 1 || head[1] != 4 || head[2] != 0) return std::nullopt;
    // The whole count is reserved when the (regular) file can hold it: no regrowth, no copy.
    std::vector<Tet> tets;
    const auto bytes = input_file_size(path_);
    tets.reserve(bytes && count_fits(static_cast<long>(std::min<std::uint64_t>(head[0], LONG_MAX)), 5, bytes)
                     ? head[0]
                     : std::min<std::uint64_t>(head[0], kMaxReserve));
    std::uint64_t v[5];
    for (std::uint64_t i = 0; i < head[0]; ++i) {
      if (line(v, 5) != 5) return std::nullopt;
      Tet k{};
      for (int j = 0; j < 4; ++j) {
        if (v[1 + j] < std::uint64_t(first_) || v[1 + j] - std::uint64_t(first_) >= points_) return std::nullopt;
        k[j] = static_cast<std::uint32_t>(v[1 + j] - std::uint64_t(first_));
      }
      std::swap(k[0], k[1]);
      tets.push_back(k);
    }
    // Nothing but blanks after the last tet.
    for (;;) {
      for (; at_ != end_; ++at_)
        if (*at_ != ' ' && *at_ != '\t' && *at_ != '\n') return std::nullopt;
      if (!refill()) return tets;
    }
  }

 private:
  // Moves the unread bytes to the front and reads more; false when nothing was added.
  bool refill() {
    const std::size_t left = static_cast<std::size_t>(end_ - at_);
    if (left == buf_.size()) return false;  // a line longer than the buffer: not this path's
    std::memmove(buf_.data(), at_, left);
    at_ = buf_.data();
    const std::size_t got = std::fread(buf_.data() + left, 1, buf_.size() - left, f_);
    end_ = buf_.data() + left + got;
    return got > 0;
  }
  // One newline-terminated line of 1..max unsigned integers (18 digits at most) separated
  // by blanks; their number, or -1 on anything else.
  int line(std::uint64_t* out, int max) {
    const char* nl;
    while (!(nl = static_cast<const char*>(std::memchr(at_, '\n', static_cast<std::size_t>(end_ - at_)))))
      if (!refill()) return -1;
    const char* c = at_;
    at_ = const_cast<char*>(nl) + 1;
    int count = 0;
    for (;;) {
      while (c != nl && (*c == ' ' || *c == '\t')) ++c;
      if (c == nl) return count > 0 ? count : -1;
      if (count == max) return -1;
      const char* first = c;
      std::uint64_t x = 0;
      for (; c != nl && *c >= '0' && *c <= '9'; ++c) x = 10 * x + std::uint64_t(*c - '0');
      if (c == first || c - first > 18 || (c != nl && *c != ' ' && *c != '\t')) return -1;
      out[count++] = x;
    }
  }
  std::string path_;
  std::FILE* f_;
  int first_;
  std::size_t points_;
  std::vector<char> buf_;
  char* at_ = nullptr;
  char* end_ = nullptr;
};

}  // namespace

std::vector<Tet> read_ele(const std::string& path, int first_index, std::size_t point_count) {
  // Only a regular file is read twice: a FIFO's content is gone after the first try.
  if (first_index >= 0 && input_file_size(path))
    if (auto fast = PlainEleReader(path, first_index, point_count).read()) return std::move(*fast);
  LineReader r(path);
  std::vector<std::string_view> tok;
  if (!r.next(tok)) r.fail("empty .ele file: missing header");
  if (tok.size() < 1 || tok.size() > 3) r.fail("header must be: <#tets> [nodes per tet] [#attributes]");
  const long n = r.to_count(tok[0], 5, "tetrahedron");
  const long per = tok.size() > 1 ? r.to_long(tok[1]) : 4;
  const long attrs = tok.size() > 2 ? r.to_long(tok[2]) : 0;
  if (per != 4) r.fail("only linear tetrahedra (4 nodes) are supported, got " + std::to_string(per));
  if (attrs < 0) r.fail("negative attribute count");
  if (attrs > kMaxAttributes) r.fail("attribute count too large: " + std::to_string(attrs));
  std::vector<Tet> tets;
  tets.reserve(std::min(static_cast<std::size_t>(n), kMaxReserve));
  for (long i = 0; i < n; ++i) {
    if (!r.next(tok, static_cast<std::size_t>(5 + attrs) + 16))
      r.fail("expected " + std::to_string(n) + " tetrahedra, file ends after " + std::to_string(i));
    if (tok.size() != static_cast<std::size_t>(5 + attrs))
      r.fail("expected " + std::to_string(5 + attrs) + " fields, got " + std::to_string(tok.size()));
    Tet k{};
    for (int j = 0; j < 4; ++j) {
      const long id = r.to_long(tok[1 + j]);
      // Compared before subtracting: an id near LONG_MIN must not overflow.
      if (id < first_index || static_cast<std::size_t>(id - first_index) >= point_count)
        r.fail("vertex index " + (tok[1 + j].size() <= 32 ? std::string(tok[1 + j]) : quote_token(tok[1 + j])) +
               " out of range");
      k[j] = static_cast<std::uint32_t>(id - first_index);
    }
    std::swap(k[0], k[1]);
    tets.push_back(k);
  }
  if (r.next(tok)) r.fail("unexpected data after the last tetrahedron (the header says " + std::to_string(n) + ")");
  return tets;
}

Tetrahedralization read_tetgen(const std::string& prefix) {
  PointFile pf = read_node(prefix + ".node");
  Tetrahedralization t;
  t.tets = read_ele(prefix + ".ele", pf.first_index, pf.points.size());
  t.points = std::move(pf.points);
  return t;
}

void write_vtu(const std::string& path, const Tetrahedralization& t, VtuFormat format) {
  VtuGrid g;
  g.points = t.points;
  g.connectivity.reserve(4 * t.tets.size());
  std::vector<double> volume;
  std::vector<std::uint8_t> defect;
  for (const Tet& k : t.tets) {
    // VTK_TETRA wants the right-handed order, like TetGen's.
    for (int j : {1, 0, 2, 3}) g.connectivity.push_back(k[j]);
    g.offsets.push_back(static_cast<std::int64_t>(g.connectivity.size()));
    g.types.push_back(kVtkTetra);
    const Point3 &a = t.points[k[0]], &b = t.points[k[1]], &c = t.points[k[2]], &d = t.points[k[3]];
    volume.push_back(orient3d_naive_volume(a, b, c, d));
    defect.push_back(adaptive_orient3d(a, b, c, d, nullptr) > 0 ? 0 : 1);
  }
  g.cell_data.push_back({"volume", std::move(volume)});
  g.cell_data.push_back({"defect", std::move(defect)});
  write_vtu_grid(path, g, format);
}

}  // namespace dtlab
