#pragma once
// The byte format of the libFuzzer targets: a fuzzer's byte string -> points.
//
// Byte 0 picks an encoding (its value mod 4); the rest is read point by point until
// the data or `max_points` runs out (a trailing partial point is ignored):
//   0 raw:     each coordinate is 8 bytes, an IEEE-754 double (little-endian). A NaN
//              or infinite pattern gets bit 62 (the exponent's top bit) cleared, which
//              makes it finite: every byte string decodes to finite points. Seeds
//              from the generators use this encoding (exact, bit for bit).
//   1 grid:    each coordinate is 1 byte, a signed integer in [-128, 127]: exact
//              coplanar, cospherical, collinear and duplicate points in abundance.
//   2 scaled:  byte 1 is a signed exponent k (times 8, clamped to [-1100, 1000]);
//              each coordinate is 2 bytes, a signed integer, times 2^k: exact
//              degeneracies near overflow and among subnormals.
//   3 jitter:  24 bytes (raw) give a base point; each point is then 3 signed bytes,
//              the base's coordinates moved by that many ulps: Kettner-style
//              near-degeneracies one ulp apart.
// encode_raw() is the inverse of the raw decoding, for seed corpora and reproducers.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::fuzz {

enum class ByteEncoding : std::uint8_t { raw = 0, grid = 1, scaled = 2, jitter = 3 };

namespace byte_points_detail {

inline std::uint64_t load_u64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

// Any bit pattern to a finite double.
inline double finite_from_bits(std::uint64_t bits) {
  constexpr std::uint64_t kExp = 0x7ffULL << 52;
  if ((bits & kExp) == kExp) bits &= ~(1ULL << 62);
  return std::bit_cast<double>(bits);
}

// x moved by `ulps` steps along the bit pattern (one step = one ulp within a
// binade), kept finite and on x's side of zero.
inline double jitter(double x, int ulps) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const std::uint64_t sign = bits & (1ULL << 63);
  std::int64_t mag = static_cast<std::int64_t>(bits & ~(1ULL << 63)) + ulps;
  if (mag < 0) mag = 0;
  return finite_from_bits(sign | static_cast<std::uint64_t>(mag));
}

}  // namespace byte_points_detail

inline std::vector<Point3> decode_points(std::span<const std::uint8_t> data, std::size_t max_points) {
  using namespace byte_points_detail;
  std::vector<Point3> pts;
  if (data.empty()) return pts;
  const auto mode = static_cast<ByteEncoding>(data[0] % 4);
  const std::uint8_t* p = data.data() + 1;
  std::size_t left = data.size() - 1;
  auto take = [&](std::size_t n) {
    const std::uint8_t* q = p;
    p += n;
    left -= n;
    return q;
  };
  switch (mode) {
    case ByteEncoding::raw:
      while (left >= 24 && pts.size() < max_points) {
        const std::uint8_t* q = take(24);
        pts.push_back({finite_from_bits(load_u64(q)), finite_from_bits(load_u64(q + 8)),
                       finite_from_bits(load_u64(q + 16))});
      }
      break;
    case ByteEncoding::grid:
      while (left >= 3 && pts.size() < max_points) {
        const std::uint8_t* q = take(3);
        pts.push_back({static_cast<double>(static_cast<std::int8_t>(q[0])),
                       static_cast<double>(static_cast<std::int8_t>(q[1])),
                       static_cast<double>(static_cast<std::int8_t>(q[2]))});
      }
      break;
    case ByteEncoding::scaled: {
      if (left < 1) break;
      int k = 8 * static_cast<std::int8_t>(*take(1));
      k = k < -1100 ? -1100 : (k > 1000 ? 1000 : k);
      auto coord = [&](const std::uint8_t* q) {
        const auto v = static_cast<std::int16_t>(static_cast<std::uint16_t>(q[0] | (q[1] << 8)));
        return std::ldexp(static_cast<double>(v), k);
      };
      while (left >= 6 && pts.size() < max_points) {
        const std::uint8_t* q = take(6);
        pts.push_back({coord(q), coord(q + 2), coord(q + 4)});
      }
      break;
    }
    case ByteEncoding::jitter: {
      if (left < 24) break;
      const std::uint8_t* q = take(24);
      const Point3 base{finite_from_bits(load_u64(q)), finite_from_bits(load_u64(q + 8)),
                        finite_from_bits(load_u64(q + 16))};
      while (left >= 3 && pts.size() < max_points) {
        const std::uint8_t* r = take(3);
        pts.push_back({jitter(base.x, static_cast<std::int8_t>(r[0])),
                       jitter(base.y, static_cast<std::int8_t>(r[1])),
                       jitter(base.z, static_cast<std::int8_t>(r[2]))});
      }
      break;
    }
  }
  return pts;
}

// The raw encoding of `pts` (decode_points(encode_raw(pts), n) == pts for finite pts).
inline std::vector<std::uint8_t> encode_raw(std::span<const Point3> pts) {
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(ByteEncoding::raw)};
  for (const Point3& q : pts)
    for (double v : {q.x, q.y, q.z}) {
      const auto bits = std::bit_cast<std::uint64_t>(v);
      for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
    }
  return out;
}

}  // namespace dtlab::fuzz
