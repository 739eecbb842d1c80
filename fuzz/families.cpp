#include "fuzz/families.hpp"

#include "fuzz/generators.hpp"

namespace dtlab::fuzz {

namespace {

using Generator = std::vector<Point3> (*)(std::size_t, Rng&);

Family family(std::string name, std::string description, Generator g) {
  return {std::move(name), std::move(description),
          [g](std::size_t n, std::uint64_t seed) {
            Rng rng(seed);
            return g(n, rng);
          }};
}

}  // namespace

const std::vector<Family>& families() {
  static const std::vector<Family> all = {
      family("uniform", "uniform in the unit cube: general position, the baseline",
             uniform_points),
      family("clustered", "1-6 clusters of radius 2^-4..2^-40: extreme density ratios, near-coincident points",
             clustered_points),
      family("lattice", "a full integer grid block: massive exact cospherical and coplanar degeneracy",
             lattice_points),
      family("lattice_subset", "a random quarter of an integer grid: exact degeneracies, irregular neighbourhoods",
             lattice_subset_points),
      family("cospherical", "integer solutions of x^2+y^2+z^2=r^2: every point on one sphere (concentric shells past 1024)",
             cospherical_points),
      family("rings", "integer circles x^2+y^2=m (m a product of primes 1 mod 4): exact cocircular rings",
             ring_points),
      family("cylinder", "coaxial equal integer rings: cocircular, and any two rings cospherical",
             cylinder_points),
      family("coplanar_slabs", "2-5 parallel tilted integer lattice planes: exact coplanar facets",
             coplanar_slab_points),
      family("coplanar_all", "one tilted integer lattice plane: the whole input is flat (lower-dimensional)",
             coplanar_points),
      family("collinear", "1-4 integer lines carry ~75% of the points: exact collinear subsets",
             collinear_points),
      family("duplicates", "~30% exact repeats, some with 0.0 turned into -0.0: duplicate detection",
             duplicate_points),
      family("near_degenerate", "an exact configuration through a rounded rational rotation, scaling and translation",
             near_degenerate_points),
      family("ulp_jitter", "an exact configuration with each coordinate nudged by nextafter (one ulp)",
             ulp_jitter_points),
      family("extreme_scale", "an exact configuration scaled by 2^k, k in -500..500: overflow and underflow",
             extreme_scale_points),
      family("far_translate", "a box a few ulps wide 2^30..2^40 from the origin: coordinates snap to a coarse grid",
             far_translate_points),
      family("subnormal", "an exact configuration scaled by 2^-1060: every coordinate subnormal",
             subnormal_points),
      family("kettner_grid", "Kettner's grid 0.5 + i*2^-53 next to a line and a plane through far anchors",
             kettner_grid_points),
      family("moment_curve", "(t, t^2, t^3) for integer t: worst-case (quadratic) output size",
             moment_curve_points),
  };
  return all;
}

const Family* find_family(const std::string& name) {
  for (const auto& f : families())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace dtlab::fuzz
