// The naive backend never crashes or hangs: every build ends with a named failure
// or finishes, and the exact checker's verdict on every finished mesh agrees with an
// independent truth (oracle/check/tests/mutation_truth.hpp: rationals and CGAL's DT).
// Moved here from the kernel's tests, which cannot link the checker.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>

#include "kernel/build.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/report_json.hpp"
#include "oracle/check/tests/mutation_truth.hpp"
#include "oracle/peers/cgal_oracle.hpp"

using namespace dtlab;

TEST_CASE("the naive backend never crashes or hangs; the checker judges every finished build", "[check][naive]") {
  // Rounded points of a cylinder: naive orientation and insphere signs are unreliable.
  int named = 0, valid = 0, invalid = 0;
  for (int c = 0; c < 40; ++c) {
    std::mt19937_64 rng(c);
    std::uniform_int_distribution<int> k(0, 34);
    std::vector<Point3> pts;
    for (int i = 0; i < 60 + 5 * c; ++i) {
      const double th = k(rng) * 2 * M_PI / 35;
      pts.push_back({5 * std::cos(th), 5 * std::sin(th), double(k(rng) % 5)});
    }
    auto r = build_delaunay(pts, PredicateSpec{"naive", 0, false, c % 2 == 0});
    INFO("case " << c);
    if (r.failure) {
      ++named;
      CHECK(r.failure->point >= 0);
      CHECK(r.skipped.size() + r.stats.inserted + r.duplicates.size() == pts.size());
      continue;
    }
    CheckOptions opt;
    opt.duplicates = r.duplicates;
    const CheckReport rep = check_tetrahedralization(r.mesh, opt);
    const OracleRun ref = cgal_delaunay(pts);
    REQUIRE(ref.mesh);
    const test::Truth truth = test::delaunay_truth(r.mesh.points, r.mesh.tets, ref.mesh->tets);
    std::string defects;
    for (const Defect& d : rep.defects) defects += format_defect(d) + "\n";
    INFO("truth: " << (truth.valid ? "valid" : truth.why) << "\nchecker:\n" << defects);
    CHECK(rep.ok() == truth.valid);
    (rep.ok() ? valid : invalid)++;
  }
  std::printf("naive on 40 rounded cylinders: %d named failures, %d finished valid, %d finished with defects\n", named,
              valid, invalid);
  CHECK(named + valid + invalid == 40);
}
