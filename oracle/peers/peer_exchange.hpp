#pragma once
// The binary files dtlab and a peer process exchange (little-endian, this machine's
// doubles). Points: "DTLP", u64 n, n x 3 f64. Answer: "DTLA", f64 seconds of the
// triangulation alone, u64 e, e x 3 f64 extra vertices (points the peer added, e.g.
// a bounding box or a point at infinity), u64 t, t x 4 u32 vertex indices, where
// i < n is input point i and n + j is extra vertex j. A peer's orientation and
// index base are its adapter's business; the file holds what the peer gave.
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct PeerAnswer {
  double seconds = 0;
  std::vector<Point3> extra;  // vertices that are not input points (by index)
  std::vector<Tet> tets;
};

void write_peer_points(const std::string& path, const std::vector<Point3>& points);
std::vector<Point3> read_peer_points(const std::string& path);  // throws std::runtime_error
void write_peer_answer(const std::string& path, const PeerAnswer& answer);
PeerAnswer read_peer_answer(const std::string& path);  // throws std::runtime_error

}  // namespace dtlab
