#include "voronoi/above_plane.hpp"

#include <cstring>

#include "kernel/cpu_features.hpp"

// Compiled with -ffp-contract=off (no fused multiply-add: each lane rounds as the scalar
// expression) and -fno-trapping-math (the comparisons may then run on vectors; no
// floating-point exception is ever read).

namespace dtlab {

namespace {

// Four points per step in GCC's generic vectors (two SSE2 instructions each in the
// default build, one AVX2 instruction in the other), the rest one at a time.
[[gnu::always_inline]] inline bool above_loop(const double* X, const double* Y, const double* Z, std::size_t count,
                                              const Point3& n, const Point3& o, double tol) {
  using V4 = double __attribute__((vector_size(32)));
  using M4 = long long __attribute__((vector_size(32)));
  std::size_t i = 0;
  M4 any = {0, 0, 0, 0};
  for (; i + 4 <= count; i += 4) {
    V4 x, y, z;
    std::memcpy(&x, X + i, sizeof x), std::memcpy(&y, Y + i, sizeof y), std::memcpy(&z, Z + i, sizeof z);
    any |= n.x * (x - o.x) + n.y * (y - o.y) + n.z * (z - o.z) > tol;
  }
  bool above = (any[0] | any[1] | any[2] | any[3]) != 0;
  for (; i < count; ++i) above |= n.x * (X[i] - o.x) + n.y * (Y[i] - o.y) + n.z * (Z[i] - o.z) > tol;
  return above;
}

[[gnu::always_inline]] inline std::size_t planes_loop(const double* X, const double* Y, const double* Z,
                                                      std::size_t points, const FacePlane* planes, std::size_t count) {
  for (std::size_t f = 0; f < count; ++f)
    if (above_loop(X, Y, Z, points, planes[f].n, planes[f].o, planes[f].t)) return f;
  return count;
}

// Two builds of the loop, picked at run time (kernel/cpu_features.hpp).
[[gnu::target("avx2")]] std::size_t planes_avx2(const double* X, const double* Y, const double* Z, std::size_t points,
                                                const FacePlane* planes, std::size_t count) {
  return planes_loop(X, Y, Z, points, planes, count);
}
std::size_t planes_default(const double* X, const double* Y, const double* Z, std::size_t points,
                           const FacePlane* planes, std::size_t count) {
  return planes_loop(X, Y, Z, points, planes, count);
}

}  // namespace

std::size_t first_plane_exceeded(const double* X, const double* Y, const double* Z, std::size_t points,
                                 const FacePlane* planes, std::size_t count) {
  return (cpu_has_avx2() ? planes_avx2 : planes_default)(X, Y, Z, points, planes, count);
}

}  // namespace dtlab
