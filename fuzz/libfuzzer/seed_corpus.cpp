// dtlab_fuzz_seed_corpus DIR: writes the seed corpora of the libFuzzer targets,
// DIR/predicates/ (5 points each) and DIR/insertion/ (8 to 64 points each), from every
// generator family (raw encoding, exact), plus a few inputs in the other encodings;
// DIR/readers/: one small valid file of each format (fuzz_readers.cpp's byte 0 first).
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "fuzz/families.hpp"
#include "fuzz/libfuzzer/byte_points.hpp"
#include "fuzz/rng.hpp"

namespace fs = std::filesystem;
using namespace dtlab;
using namespace dtlab::fuzz;

namespace {

void write(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Inputs in the grid, scaled and jitter encodings: the 8 corners of a cube (every
// 5 of them cospherical); the same scaled by 2^-1024 (subnormal) and 2^992; a cloud
// of points a few ulps from (0.5, 0.5, 0.5).
std::vector<std::vector<std::uint8_t>> other_encodings() {
  const std::vector<std::uint8_t> cube = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 2, 2, 0, 2, 0, 2, 0, 2, 2, 2, 2, 2};
  std::vector<std::vector<std::uint8_t>> out;
  std::vector<std::uint8_t> grid{static_cast<std::uint8_t>(ByteEncoding::grid)};
  grid.insert(grid.end(), cube.begin(), cube.end());
  out.push_back(grid);
  for (std::int8_t k : {std::int8_t{-128}, std::int8_t{124}}) {
    std::vector<std::uint8_t> scaled{static_cast<std::uint8_t>(ByteEncoding::scaled),
                                     static_cast<std::uint8_t>(k)};
    for (std::uint8_t c : cube) scaled.insert(scaled.end(), {c, 0});
    out.push_back(scaled);
  }
  std::vector<std::uint8_t> jitter = encode_raw(std::vector<Point3>{{0.5, 0.5, 0.5}});
  jitter[0] = static_cast<std::uint8_t>(ByteEncoding::jitter);
  for (int i = 0; i < 12; ++i)
    jitter.insert(jitter.end(), {static_cast<std::uint8_t>(i % 3), static_cast<std::uint8_t>(i / 3),
                                 static_cast<std::uint8_t>((i * 5) % 7 - 3)});
  out.push_back(jitter);
  return out;
}

// Byte 0 picks the reader (fuzz_readers.cpp), the rest is a small valid file.
std::vector<std::pair<std::string, std::vector<std::uint8_t>>> reader_seeds() {
  const std::pair<const char*, std::string> text[] = {
      {"tet.node", std::string(1, '\0') + "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n"},
      {"tet.xyz", "\x01" "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"},
      {"tet0.ele", "\x02" "1 4 0\n0 0 1 2 3\n"},
      {"tet1.ele", "\x09" "1 4 1\n1 1 2 3 4 7\n"},
      {"tet.off", "\x03" "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      {"tet.obj", "\x04" "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"},
      {"tet_ascii.ply", "\x05" "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"},
      {"tri_ascii.stl", "\x06" "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                        "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n"},
  };
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> out;
  for (const auto& [name, t] : text) out.push_back({name, std::vector<std::uint8_t>(t.begin(), t.end())});
  // Binary PLY (little endian, 3 float vertices, one uchar/int face) and binary STL.
  std::string ply = "\x05" "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                    "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "end_header\n";
  std::vector<std::uint8_t> bin(ply.begin(), ply.end());
  const auto put = [&](const void* p, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    bin.insert(bin.end(), b, b + n);  // the build machines are little endian, as the file says
  };
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  put(corners, sizeof corners);
  const std::uint8_t three = 3;
  put(&three, 1);
  const std::int32_t ids[3] = {0, 1, 2};
  put(ids, sizeof ids);
  out.push_back({"tri_binary.ply", bin});
  bin.assign(1, 6);
  bin.resize(1 + 80, ' ');
  const std::uint32_t one = 1;
  put(&one, 4);
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  put(facet, sizeof facet);
  bin.insert(bin.end(), {0, 0});
  out.push_back({"tri_binary.stl", bin});
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  const fs::path dir = argv[1];
  fs::create_directories(dir / "predicates");
  fs::create_directories(dir / "insertion");
  int files = 0;
  for (const Family& f : families()) {
    for (std::uint64_t i = 0; i < 4; ++i) {
      const std::uint64_t seed = mix64(i + 1);
      const std::string stem = f.name + "-" + std::to_string(i);
      write(dir / "predicates" / (stem + ".bin"), encode_raw(f.generate(5, seed)));
      const std::size_t n = std::size_t{8} << (2 * (i % 3));  // 8, 32, 128 -> capped at 64
      const auto pts = f.generate(n < 64 ? n : 64, seed);
      write(dir / "insertion" / (stem + ".bin"), encode_raw(pts));
      files += 2;
    }
  }
  fs::create_directories(dir / "readers");
  for (const auto& [name, bytes] : reader_seeds()) {
    write(dir / "readers" / name, bytes);
    ++files;
  }
  int k = 0;
  for (const auto& bytes : other_encodings()) {
    const std::string name = "encoding-" + std::to_string(k++) + ".bin";
    write(dir / "predicates" / name, bytes);
    write(dir / "insertion" / name, bytes);
    files += 2;
  }
  std::printf("wrote %d seed files under %s\n", files, dir.c_str());
  return 0;
}
