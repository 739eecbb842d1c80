// Inside queries per second of the fast winding number, and outside fractions of the
// samplers, on a mesh file (or the built-in torus).
//   dtlab_sampling_bench [MESH|builtin] [QUERIES] [holes]
// "holes" removes every 7th triangle (14% of the faces) before measuring.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <thread>
#include <random>

#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_io.hpp"
#include "sampling/mesh_report.hpp"
#include "sampling/mesh_sampler.hpp"
#include "sampling/sample_quality.hpp"

using namespace dtlab;
using Clock = std::chrono::steady_clock;

static double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "builtin";
  const std::size_t nq = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1000000;
  TriangleMesh mesh = path == "builtin" ? make_bumpy_torus() : read_mesh(path);
  // The reference inside/outside is always judged on the mesh as read (closed, for
  // the meshes we report), also when the sampled mesh has holes punched in it.
  const TriangleMesh original = mesh;
  const Bvh reference(original);
  if (argc > 3 && std::string(argv[3]) == "holes") {
    std::size_t kept = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (t % 7 != 3) mesh.triangles[kept++] = mesh.triangles[t];
    mesh.triangles.resize(kept);
  }
  const MeshReport r = analyze_mesh(mesh);
  std::printf("%s: %zu triangles, closed %d, manifold %d, oriented %d, boundary edges %zu, self-intersections %llu\n",
              path.c_str(), r.triangles, r.closed, r.manifold, r.oriented, r.boundary_edges,
              static_cast<unsigned long long>(r.self_intersections));
  auto t = Clock::now();
  const MeshSampler s(mesh);
  std::printf("build (BVH + winding tree + pseudonormals): %.3f s\n", since(t));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> U(0, 1);
  const Point3 e = s.box().extent();
  std::vector<Point3> q(nq);
  for (Point3& p : q) p = {s.box().lo.x + U(rng) * e.x, s.box().lo.y + U(rng) * e.y, s.box().lo.z + U(rng) * e.z};
  t = Clock::now();
  const std::clock_t c0 = std::clock();
  const auto flags = inside_flags(s.winding_number(), q);
  const double dt = since(t), cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  std::size_t in = 0;
  for (char f : flags) in += f;
  std::printf("fast winding number: %zu box queries in %.3f s = %.3g queries/s on %u threads, %.3g per CPU-second (%.1f%% inside)\n",
              nq, dt, nq / dt, std::thread::hardware_concurrency(), nq / cpu, 100.0 * in / nq);
  const std::size_t n = 20000;
  // Plain one-ray parity (the ray method's inside test) on the same box points.
  std::size_t parity_wrong = 0;
  {
    const std::vector<char> truth = inside_flags_robust(reference, std::vector<Point3>(q.begin(), q.begin() + std::min<std::size_t>(nq, 100000)));
    for (std::size_t i = 0; i < truth.size(); ++i) {
      std::size_t hits = 0;
      s.bvh().for_each_ray_hit(q[i], {e.x * 3, e.y * 0.0123, e.z * 0.0077}, 1.0, [&](std::uint32_t, double) { ++hits; });
      parity_wrong += (hits % 2 == 1) != (truth[i] != 0);
    }
    std::size_t fwn_wrong = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) fwn_wrong += (flags[i] != 0) != (truth[i] != 0);
    std::printf("misclassified box points vs reference: one-ray parity %.3f%%, fast winding number %.3f%% (of %zu)\n",
                100.0 * parity_wrong / truth.size(), 100.0 * fwn_wrong / truth.size(), truth.size());
  }
  for (SampleMethod m : {SampleMethod::rays, SampleMethod::sdf, SampleMethod::winding}) {
    t = Clock::now();
    const auto out = s.sample({.method = m, .count = n, .seed = 1});
    const double st = since(t);
    const auto o = count_outside(reference, out.points);
    std::printf("%-8s %zu points in %.3f s (%.3g samples/s), outside %zu (%.3f%%)\n",
                std::string(method_name(m)).c_str(), out.points.size(), st, out.points.size() / st, o.outside,
                100 * o.fraction());
  }
}
