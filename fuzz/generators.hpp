#pragma once
// The point-set generators behind `dtlab fuzz --family`. Each returns exactly n
// points drawn from `rng`, so the same seed gives the same bits everywhere (see
// fuzz/rng.hpp). The one-line statement of what each targets lives in the
// registry (fuzz/families.cpp).
#include <cstddef>
#include <vector>

#include "fuzz/rng.hpp"
#include "predicates/point.hpp"

namespace dtlab::fuzz {

// General position and random-ish inputs (gen_random.cpp).
std::vector<Point3> uniform_points(std::size_t n, Rng& rng);
std::vector<Point3> clustered_points(std::size_t n, Rng& rng);
std::vector<Point3> duplicate_points(std::size_t n, Rng& rng);
std::vector<Point3> moment_curve_points(std::size_t n, Rng& rng);

// Exact integer degeneracies (gen_exact.cpp): every coordinate is an integer of
// magnitude below 2^31, so each claimed coplanarity / cosphericity holds exactly.
std::vector<Point3> lattice_points(std::size_t n, Rng& rng);
std::vector<Point3> lattice_subset_points(std::size_t n, Rng& rng);
std::vector<Point3> cospherical_points(std::size_t n, Rng& rng);
std::vector<Point3> ring_points(std::size_t n, Rng& rng);
std::vector<Point3> cylinder_points(std::size_t n, Rng& rng);
std::vector<Point3> coplanar_slab_points(std::size_t n, Rng& rng);
std::vector<Point3> coplanar_points(std::size_t n, Rng& rng);
std::vector<Point3> collinear_points(std::size_t n, Rng& rng);

// One of lattice_subset / cospherical / coplanar_slabs / cylinder, picked by rng:
// the exact seed configurations of the near-degenerate families. Coordinates are
// integers below 2^20 in magnitude.
std::vector<Point3> exact_configuration(std::size_t n, Rng& rng);

// Exact configurations moved to where floating point struggles (gen_near.cpp).
std::vector<Point3> near_degenerate_points(std::size_t n, Rng& rng);
std::vector<Point3> ulp_jitter_points(std::size_t n, Rng& rng);
std::vector<Point3> extreme_scale_points(std::size_t n, Rng& rng);
std::vector<Point3> far_translate_points(std::size_t n, Rng& rng);
std::vector<Point3> subnormal_points(std::size_t n, Rng& rng);
std::vector<Point3> kettner_grid_points(std::size_t n, Rng& rng);

// The Kettner grid's fixed geometry: anchors on the plane x - 2y + z = 0 (two of
// them on the line x = y = z) and the grid corner (0.5, 0.5, 0.5) on both.
inline constexpr Point3 kKettnerAnchors[4] = {{12, 12, 12}, {24, 24, 24}, {12, 18, 24}, {24, 18, 12}};
inline constexpr double kKettnerBase = 0.5;
inline constexpr double kKettnerStep = 0x1p-53;  // one ulp of 0.5
inline constexpr int kKettnerSide = 256;

}  // namespace dtlab::fuzz
