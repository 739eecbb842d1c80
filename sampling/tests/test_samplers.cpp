#include <catch2/catch.hpp>

#include "meshes.hpp"
#include "sampling/mesh_report.hpp"
#include "sampling/mesh_sampler.hpp"
#include "sampling/sample_quality.hpp"

using namespace dtlab;

namespace {
SampleOutput run(const MeshSampler& s, SampleMethod m, std::size_t n, std::uint64_t seed) {
  return s.sample({.method = m, .count = n, .seed = seed});
}
}  // namespace

TEST_CASE("L prism helper is a closed oriented concave mesh") {
  const MeshReport r = analyze_mesh(test::l_prism());
  CHECK(r.closed);
  CHECK(r.oriented);
  CHECK(r.volume == Approx(3.0));
}

TEST_CASE("every sampler is reproducible and gives the requested count") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const MeshSampler s(m);
  for (SampleMethod method : {SampleMethod::surface, SampleMethod::rays, SampleMethod::sdf, SampleMethod::winding}) {
    INFO(method_name(method));
    const auto a = run(s, method, 500, 42), b = run(s, method, 500, 42), c = run(s, method, 500, 43);
    CHECK(a.points.size() == 500);
    CHECK(a.points == b.points);
    CHECK(a.points != c.points);
  }
}

TEST_CASE("surface samples lie on the mesh") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const MeshSampler s(m);
  for (const Point3& p : run(s, SampleMethod::surface, 300, 1).points)
    CHECK(s.bvh().closest_point(p).distance2 < 1e-20);
}

TEST_CASE("sdf and winding put no point outside the closed torus") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const MeshSampler s(m);
  for (SampleMethod method : {SampleMethod::sdf, SampleMethod::winding, SampleMethod::rays}) {
    INFO(method_name(method));
    const auto out = run(s, method, 3000, 5);
    CHECK(count_outside(s.bvh(), out.points).outside == 0);
  }
}

TEST_CASE("volume samples fill the torus evenly: the fraction in one half matches its volume") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const MeshSampler s(m);
  // By symmetry x > 0 holds half the volume.
  for (SampleMethod method : {SampleMethod::sdf, SampleMethod::winding}) {
    const auto out = run(s, method, 4000, 9);
    const double half = std::count_if(out.points.begin(), out.points.end(), [](const Point3& p) { return p.x > 0; });
    CHECK(half / 4000 == Approx(0.5).margin(0.04));
  }
}

TEST_CASE("on a mesh with holes, winding stays right where the thesis's methods fail") {
  const TriangleMesh m = test::holey_torus();
  const MeshSampler s(m);
  const double rays = count_outside(s.bvh(), run(s, SampleMethod::rays, 3000, 2).points).fraction();
  const double sdf = count_outside(s.bvh(), run(s, SampleMethod::sdf, 3000, 2).points).fraction();
  const double wind = count_outside(s.bvh(), run(s, SampleMethod::winding, 3000, 2).points).fraction();
  WARN("outside fraction: rays " << rays << ", sdf " << sdf << ", winding " << wind);
  CHECK(rays > 0.02);
  CHECK(wind < 0.01);
  CHECK(wind < rays);
}

TEST_CASE("rays on the concave L prism: parity right, density measurably uneven") {
  // Rays joining uniform points on opposite box faces cross the middle of the box more
  // often than its sides, so the ray method under-fills the mesh near the box faces.
  // Rejection sampling (sdf, winding) fills it evenly.
  const TriangleMesh m = test::l_prism();
  const MeshSampler s(m);
  const std::size_t n = 20000;
  auto slab_share = [&](const std::vector<Point3>& p) {
    return std::count_if(p.begin(), p.end(), [](const Point3& q) { return q.x < 0.25; }) / double(p.size());
  };
  const auto rays = run(s, SampleMethod::rays, n, 4);
  const auto wind = run(s, SampleMethod::winding, n, 4);
  // The slab x < 0.25 holds 0.5 of the prism's volume 3.
  const double expected = 0.5 / 3;
  WARN("share of the slab x < 0.25: rays " << slab_share(rays.points) << ", winding " << slab_share(wind.points)
                                           << ", volume " << expected);
  CHECK(slab_share(wind.points) == Approx(expected).margin(0.01));
  CHECK(slab_share(rays.points) < expected - 0.04);
  // With its faces on the bounding box and rays in general position, parity holds.
  CHECK(count_outside(s.bvh(), rays.points).outside == 0);
  // sdf and winding agree point for point on a clean closed mesh (same seed, same candidates).
  CHECK(run(s, SampleMethod::sdf, n, 4).points == wind.points);
}

TEST_CASE("meshes enclosing nothing: volume samplers return early instead of spinning") {
  TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  flat.triangles = {{0, 1, 2}, {2, 1, 3}};
  // Two copies of one triangle with opposite orientations: a closed surface of no volume.
  TriangleMesh sliver;
  sliver.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}};
  sliver.triangles = {{0, 1, 2}, {0, 2, 1}};
  for (const TriangleMesh* m : {&flat, &sliver}) {
    const MeshSampler s(*m);
    for (SampleMethod method : {SampleMethod::rays, SampleMethod::sdf, SampleMethod::winding}) {
      INFO(method_name(method));
      const std::size_t got = run(s, method, 100, 1).points.size();
      // On the sliver the pseudonormals of the two coincident faces disagree, so sdf
      // does "find" an inside: the thesis method's failure, returned rather than hung.
      if (!(m == &sliver && method == SampleMethod::sdf)) CHECK(got < 100);
    }
  }
}
