// dtlab's kernel from C++: the Delaunay tetrahedralization of the 8 corners of a cube
// and its centre, with the robust default backend (adaptive predicates + symbolic
// perturbation). The corners are cospherical, but the centre lies inside that sphere,
// so the answer is unique: the centre joined to the 12 triangles of the cube's faces.
#include <cstdio>
#include <vector>

#include "kernel/build.hpp"
#include "predicates/exact.hpp"

int main() {
  std::vector<dtlab::Point3> points;
  for (int i = 0; i < 8; ++i) points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  points.push_back({0.5, 0.5, 0.5});

  dtlab::PredicateSpec predicates;  // adaptive + sos
  const dtlab::BuildResult result = dtlab::build_delaunay(points, predicates);
  if (result.failure) {
    std::printf("build failed: %s\n", dtlab::failure_name(result.failure->kind));
    return 1;
  }
  std::size_t positive = 0, with_centre = 0;
  for (const auto& t : result.mesh.tets) {
    const auto& p = result.mesh.points;
    positive += dtlab::exact_orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) > 0;
    with_centre += t[0] == 8 || t[1] == 8 || t[2] == 8 || t[3] == 8;
  }
  std::printf("%zu tets, %zu positively oriented (exact), %zu with the centre\n", result.mesh.tets.size(),
              positive, with_centre);
  const std::size_t n = result.mesh.tets.size();
  return n == 12 && positive == n && with_centre == n ? 0 : 1;
}
