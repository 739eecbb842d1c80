// The parallel loop and the fast writers: every index once, the first exception
// rethrown; .node/.xyz/.ele text identical for every thread count and read back to
// the same doubles and tets (shortest round-trip doubles, including the extremes);
// .npy headers as NumPy's format 1.0 wants them; a 0-based .node kept or copied.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include "kernel/node_reuse.hpp"
#include "kernel/npy_writer.hpp"
#include "kernel/parallel_for.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"

using namespace dtlab;
namespace fs = std::filesystem;

namespace {
fs::path temp_dir() {
  fs::path dir = fs::temp_directory_path() / ("dtlab_tests_parallel_io_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
// More points than one block of the writer (2^15 records), with hard doubles.
std::vector<Point3> hard_points() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3> p(100000);
  for (auto& q : p) q = {u(rng), u(rng) * 1e-300, u(rng) * 1e300};
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  p[0] = {0.1, -0.0, 1.0 / 3};
  p[1] = {big, -big, tiny};
  p[2] = {std::numeric_limits<double>::min(), 123456789012345678.0, 5e-324};
  return p;
}
}  // namespace

TEST_CASE("parallel_chunks visits every index once and rethrows the first exception", "[threads]") {
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<std::atomic<int>> seen(10007);
    std::atomic<unsigned> most{0};  // Catch's assertions are not thread-safe: checked after
    parallel_chunks(seen.size(), threads, 13, [&](std::size_t b, std::size_t e, unsigned w) {
      for (unsigned m = most; w > m && !most.compare_exchange_weak(m, w);) {
      }
      for (std::size_t i = b; i < e; ++i) ++seen[i];
    });
    CHECK(most < threads);
    for (const auto& s : seen) REQUIRE(s == 1);
    CHECK_THROWS_AS(parallel_for(1000, threads, 10,
                                 [](std::size_t i, unsigned) {
                                   if (i == 500) throw std::runtime_error("stop");
                                 }),
                    std::runtime_error);
  }
  CHECK(thread_count(0) >= 1);
  CHECK(thread_count(5) == 5);
}

TEST_CASE("fast .node/.xyz/.ele writers: the same bytes at every thread count, exact read-back", "[io][threads]") {
  const fs::path dir = temp_dir();
  const std::vector<Point3> pts = hard_points();
  write_node((dir / "a.node").string(), pts, 1);
  write_xyz((dir / "a.xyz").string(), pts, 1);
  const std::string node = slurp(dir / "a.node"), xyz = slurp(dir / "a.xyz");
  for (unsigned threads : {2u, 3u, 4u}) {
    write_node((dir / "b.node").string(), pts, threads);
    write_xyz((dir / "b.xyz").string(), pts, threads);
    CHECK(slurp(dir / "b.node") == node);
    CHECK(slurp(dir / "b.xyz") == xyz);
  }
  CHECK(node.rfind("100000 3 0 0\n0 0.1 -0 0.3333333333333333\n", 0) == 0);
  for (const PointFile& back : {read_node((dir / "a.node").string()), read_xyz((dir / "a.xyz").string())}) {
    REQUIRE(back.points.size() == pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      REQUIRE(back.points[i] == pts[i]);
      REQUIRE(std::signbit(back.points[i].y) == std::signbit(pts[i].y));
    }
  }
  std::vector<Tet> tets(70000);
  std::mt19937 rng(3);
  for (auto& k : tets)
    for (auto& v : k) v = static_cast<std::uint32_t>(rng() % pts.size());
  write_ele((dir / "a.ele").string(), tets, 1);
  write_ele((dir / "b.ele").string(), tets, 3);
  CHECK(slurp(dir / "a.ele") == slurp(dir / "b.ele"));
  CHECK(read_ele((dir / "b.ele").string(), 0, pts.size()) == tets);
  fs::remove_all(dir);
}

TEST_CASE(".npy files: format 1.0 header, 64-byte aligned, the records as in memory", "[io]") {
  const std::string h = npy_header("<u4", "(7, 4)");
  CHECK(h.size() % 64 == 0);
  CHECK(h.substr(0, 8) == std::string("\x93NUMPY\x01\x00", 8));
  CHECK(static_cast<unsigned char>(h[8]) + 256u * static_cast<unsigned char>(h[9]) == h.size() - 10);
  CHECK(h.find("{'descr': '<u4', 'fortran_order': False, 'shape': (7, 4), }") == 10);
  CHECK(h.back() == '\n');
  const fs::path dir = temp_dir();
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1.5}};
  t.tets = {{0, 1, 2, 3}};
  write_npy((dir / "m").string(), t);
  const std::string p = slurp(dir / "m.points.npy"), k = slurp(dir / "m.tets.npy");
  const std::string ph = npy_header("<f8", "(4, 3)"), kh = npy_header("<u4", "(1, 4)");
  REQUIRE(p.size() == ph.size() + 4 * 24);
  REQUIRE(k.size() == kh.size() + 16);
  CHECK(p.compare(0, ph.size(), ph) == 0);
  double z;
  std::memcpy(&z, p.data() + ph.size() + 11 * 8, 8);
  CHECK(z == 1.5);
  std::uint32_t last;
  std::memcpy(&last, k.data() + kh.size() + 12, 4);
  CHECK(last == 3);
  fs::remove_all(dir);
}

TEST_CASE("a 0-based input .node is kept when it is the output, else copied byte for byte", "[io]") {
  const fs::path dir = temp_dir();
  const std::string in = (dir / "in.node").string();
  std::ofstream(in) << "# a comment\n4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
  CHECK(reuse_node_file(in, in) == NodeReuse::same_file);
  CHECK(reuse_node_file(in, (dir / "." / "in.node").string()) == NodeReuse::same_file);
  CHECK(reuse_node_file(in, (dir / "out.node").string()) == NodeReuse::copied);
  CHECK(slurp(dir / "out.node") == slurp(in));
  CHECK(read_node((dir / "out.node").string()).points.size() == 4);
  CHECK(reuse_node_file((dir / "missing.node").string(), (dir / "out2.node").string()) == NodeReuse::none);
  CHECK_FALSE(fs::exists(dir / "out2.node"));
  fs::remove_all(dir);
}
