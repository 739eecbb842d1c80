#pragma once
// What the machine running dtlab offers beyond the build's baseline (x86-64: SSE2), for
// the loops compiled twice and chosen at run time (voronoi/above_plane.cpp,
// voronoi_check/vertex_filter.cpp). Not `target_clones`: its ifunc resolver runs before
// ThreadSanitizer's runtime is up and crashes the TSan build at load.

namespace dtlab {

// AVX2 instructions can run here (asked once).
inline bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return false;
#endif
}

}  // namespace dtlab
