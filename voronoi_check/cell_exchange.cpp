#include "voronoi_check/cell_exchange.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace dtlab {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

template <class T>
void put(std::FILE* f, const T* data, std::size_t n) {
  if (n && std::fwrite(data, sizeof(T), n, f) != n) throw std::runtime_error("write failed");
}

class Reader {
 public:
  explicit Reader(const std::string& path) : f_(std::fopen(path.c_str(), "rb")), path_(path) {
    if (!f_) throw std::runtime_error(path + ": cannot open");
    std::fseek(f_.get(), 0, SEEK_END);
    left_ = static_cast<std::uint64_t>(std::ftell(f_.get()));
    std::fseek(f_.get(), 0, SEEK_SET);
  }
  template <class T>
  void get(T* data, std::uint64_t n) {
    if (n > left_ / sizeof(T)) throw std::runtime_error(path_ + ": file too short for its counts");
    if (n && std::fread(data, sizeof(T), n, f_.get()) != n) throw std::runtime_error(path_ + ": read failed");
    left_ -= n * sizeof(T);
  }
  template <class T>
  T get() {
    T v;
    get(&v, 1);
    return v;
  }
  std::uint64_t left() const { return left_; }

 private:
  File f_;
  std::string path_;
  std::uint64_t left_ = 0;
};

}  // namespace

void write_peer_cells(const std::string& path, double seconds, const ToolCells& cells) {
  File f(std::fopen(path.c_str(), "wb"));
  if (!f) throw std::runtime_error(path + ": cannot write");
  const std::uint64_t n = cells.size();
  put(f.get(), "DTLV", 4);
  put(f.get(), &seconds, 1);
  put(f.get(), &n, 1);
  std::vector<std::uint32_t> sizes;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const VoronoiCell v = cells.cell(c);
    const std::int64_t site = cells.site(c);
    const std::uint32_t counts[3] = {static_cast<std::uint32_t>(v.vertices.size()),
                                     static_cast<std::uint32_t>(v.face_count()),
                                     static_cast<std::uint32_t>(v.face_vertices.size())};
    sizes.clear();
    for (std::size_t k = 0; k < v.face_count(); ++k) sizes.push_back(v.face_offsets[k + 1] - v.face_offsets[k]);
    put(f.get(), &site, 1);
    put(f.get(), counts, 3);
    put(f.get(), v.vertices.data(), v.vertices.size());
    put(f.get(), v.face_neighbor.data(), v.face_count());
    put(f.get(), sizes.data(), sizes.size());
    put(f.get(), v.face_vertices.data(), v.face_vertices.size());
  }
  if (std::fflush(f.get()) != 0) throw std::runtime_error(path + ": write failed");
}

PeerCells read_peer_cells(const std::string& path) {
  Reader in(path);
  char magic[4];
  in.get(magic, 4);
  if (std::memcmp(magic, "DTLV", 4) != 0) throw std::runtime_error(path + ": not a cell file (no DTLV)");
  PeerCells out;
  out.seconds = in.get<double>();
  const auto n = in.get<std::uint64_t>();
  if (n > in.left() / 20) throw std::runtime_error(path + ": cell count too large");
  std::vector<Point3> v;
  std::vector<std::int32_t> nb;
  std::vector<std::uint32_t> sizes, offsets, corners;
  for (std::uint64_t c = 0; c < n; ++c) {
    const auto site = in.get<std::int64_t>();
    std::uint32_t counts[3];
    in.get(counts, 3);
    v.resize(counts[0]);
    nb.resize(counts[1]);
    sizes.resize(counts[1]);
    corners.resize(counts[2]);
    in.get(v.data(), v.size());
    in.get(nb.data(), nb.size());
    in.get(sizes.data(), sizes.size());
    in.get(corners.data(), corners.size());
    offsets.assign(1, 0);
    for (auto s : sizes) offsets.push_back(offsets.back() + s);
    try {
      out.cells.add_cell(site, v, offsets, corners, nb);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path + ": " + e.what());
    }
  }
  return out;
}

}  // namespace dtlab
