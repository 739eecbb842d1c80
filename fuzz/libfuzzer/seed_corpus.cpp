// dtlab_fuzz_seed_corpus DIR: writes the seed corpora of the libFuzzer targets,
// DIR/predicates/ (5 points each) and DIR/insertion/ (8 to 64 points each), from every
// generator family (raw encoding, exact), plus a few inputs in the other encodings.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
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
