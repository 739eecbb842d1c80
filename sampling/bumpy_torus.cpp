#include "sampling/bumpy_torus.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dtlab {

TriangleMesh make_bumpy_torus(const BumpyTorusParams& p) {
  if (p.nu < 3 || p.nv < 3 || !(p.bump >= 0 && p.bump < 1) || !(p.minor > 0) ||
      !(p.minor * (1 + p.bump) < p.major))
    throw std::invalid_argument("make_bumpy_torus: parameters give no embedded torus");
  TriangleMesh m;
  const double tau = 2 * std::numbers::pi;
  for (int i = 0; i < p.nu; ++i) {
    const double u = tau * i / p.nu;
    for (int j = 0; j < p.nv; ++j) {
      const double v = tau * j / p.nv;
      const double r = p.minor * (1 + p.bump * std::sin(p.ku * u) * std::sin(p.kv * v));
      const double ring = p.major + r * std::cos(v);
      m.vertices.push_back({ring * std::cos(u), ring * std::sin(u), r * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % p.nu) * p.nv + (j % p.nv)); };
  // dP/du x dP/dv points away from the tube axis, so (i,j), (i+1,j), (i+1,j+1) turn
  // counter-clockwise seen from outside.
  for (int i = 0; i < p.nu; ++i)
    for (int j = 0; j < p.nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

double bumpy_torus_volume(const BumpyTorusParams& p) {
  const double pi = std::numbers::pi;
  return p.major * p.minor * p.minor * pi * pi * (2 + p.bump * p.bump / 2);
}

}  // namespace dtlab
