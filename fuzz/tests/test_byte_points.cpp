#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fuzz/families.hpp"
#include "fuzz/libfuzzer/byte_points.hpp"

using namespace dtlab;
using namespace dtlab::fuzz;

TEST_CASE("raw byte encoding round-trips every family bit for bit", "[fuzz][libfuzzer]") {
  for (const Family& f : families()) {
    const std::vector<Point3> pts = f.generate(40, 17);
    const std::vector<Point3> back = decode_points(encode_raw(pts), 64);
    REQUIRE(back.size() == pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      INFO(f.name << " point " << i);
      CHECK(std::signbit(back[i].x) == std::signbit(pts[i].x));
      CHECK(back[i] == pts[i]);
    }
  }
}

TEST_CASE("byte decoding caps the count and keeps every point finite", "[fuzz][libfuzzer]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto raw = encode_raw(std::vector<Point3>{{inf, -inf, nan}, {1, 2, 3}, {4, 5, 6}});
  raw.push_back(7);  // a partial point is ignored
  const auto pts = decode_points(raw, 2);
  REQUIRE(pts.size() == 2);
  CHECK(std::isfinite(pts[0].x));
  CHECK(std::isfinite(pts[0].y));
  CHECK(std::isfinite(pts[0].z));
  CHECK(pts[1] == Point3{1, 2, 3});

  // Every encoding, on every prefix of a byte soup with NaN/inf patterns in it.
  std::vector<std::uint8_t> soup;
  for (int i = 0; i < 600; ++i) soup.push_back(static_cast<std::uint8_t>(i % 7 == 0 ? 0xff : i * 37));
  for (std::uint8_t mode = 0; mode < 4; ++mode) {
    soup[0] = mode;
    for (std::size_t len = 0; len <= soup.size(); len += 13)
      for (const Point3& p : decode_points(std::span(soup.data(), len), 64)) {
        INFO("mode " << int(mode) << " length " << len);
        REQUIRE(std::isfinite(p.x));
        REQUIRE(std::isfinite(p.y));
        REQUIRE(std::isfinite(p.z));
      }
  }
}

TEST_CASE("grid, scaled and jitter encodings decode as documented", "[fuzz][libfuzzer]") {
  const std::vector<std::uint8_t> grid = {1, 0xff, 2, 0x80};
  CHECK(decode_points(grid, 8) == std::vector<Point3>{{-1, 2, -128}});
  const std::vector<std::uint8_t> scaled = {2, 0x80, 3, 0, 0xfe, 0xff, 0, 0x80};  // k = -1024
  const auto s = decode_points(scaled, 8);
  REQUIRE(s.size() == 1);
  CHECK(s[0] == Point3{std::ldexp(3.0, -1024), std::ldexp(-2.0, -1024), std::ldexp(-32768.0, -1024)});
  auto jitter = encode_raw(std::vector<Point3>{{0.5, -0.5, 0.0}});
  jitter[0] = 3;
  jitter.insert(jitter.end(), {1, 0xff, 2});
  const auto j = decode_points(jitter, 8);
  REQUIRE(j.size() == 1);
  CHECK(j[0].x == std::nextafter(0.5, 1.0));
  CHECK(j[0].y == std::nextafter(-0.5, 0.0));
  CHECK(j[0].z == 2 * std::numeric_limits<double>::denorm_min());
}
