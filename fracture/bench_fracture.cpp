// Fracture time: PIECES pieces of the bumpy torus at 65,536 triangles (nu 256, nv 128).
//   dtlab_fracture_bench [PIECES=200] [THREADS=0]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "fracture/fracture.hpp"
#include "sampling/bumpy_torus.hpp"

int main(int argc, char** argv) {
  using namespace dtlab;
  BumpyTorusParams bp;
  bp.nu = 256;
  bp.nv = 128;
  const TriangleMesh mesh = make_bumpy_torus(bp);
  FractureOptions o;
  o.pieces = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 200;
  o.threads = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 0;
  const auto t0 = std::chrono::steady_clock::now();
  FractureResult r = fracture_mesh(mesh, o);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double sum = 0;
  for (const auto& p : r.pieces) sum += p.volume;
  std::printf("triangles %zu  pieces %zu  booleans %zu  skipped %zu  threads %u\n", mesh.triangles.size(),
              r.pieces.size(), r.booleans, r.skipped, o.threads);
  std::printf("total %.3f s (validation+rest %.3f, sampling %.3f, voronoi %.3f, booleans %.3f)\n", total,
              total - r.seconds_sampling - r.seconds_voronoi - r.seconds_boolean, r.seconds_sampling,
              r.seconds_voronoi, r.seconds_boolean);
  std::printf("relative volume error %.3g\n", std::abs(sum - r.mesh_volume) / r.mesh_volume);
  return 0;
}
