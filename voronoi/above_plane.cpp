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

// Two builds of the loop, picked at run time (kernel/cpu_features.hpp).
[[gnu::target("avx2")]] bool above_avx2(const double* X, const double* Y, const double* Z, std::size_t count,
                                        const Point3& n, const Point3& o, double tol) {
  return above_loop(X, Y, Z, count, n, o, tol);
}
bool above_default(const double* X, const double* Y, const double* Z, std::size_t count, const Point3& n,
                   const Point3& o, double tol) {
  return above_loop(X, Y, Z, count, n, o, tol);
}

}  // namespace

bool any_above_plane(const double* X, const double* Y, const double* Z, std::size_t count, const Point3& n,
                     const Point3& o, double tol) {
  return (cpu_has_avx2() ? above_avx2 : above_default)(X, Y, Z, count, n, o, tol);
}

}  // namespace dtlab
