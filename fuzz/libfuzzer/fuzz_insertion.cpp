// libFuzzer target: insertion validity. Bytes -> up to 64 points (fuzz/libfuzzer/
// byte_points.hpp; byte 0 / 4 also seeds the BRIO order) -> build_delaunay with
// adaptive+sos -> the exact checker (through fuzz::run_case, which also proves a
// "lower-dimensional" answer exactly). Anything but a valid tetrahedralization, or a
// correct lower-dimensional verdict, aborts. The perturbed Delaunay tetrahedralization
// is unique, so exact+sos must build the same tets: compared as sorted vertex sets.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fuzz/libfuzzer/byte_points.hpp"
#include "fuzz/libfuzzer/fuzz_report.hpp"
#include "fuzz/outcome.hpp"
#include "kernel/build.hpp"

using namespace dtlab;

namespace {

constexpr std::size_t kMaxPoints = 64;

std::vector<Tet> canonical_tets(const Tetrahedralization& t) {
  std::vector<Tet> tets = t.tets;
  for (Tet& tet : tets) std::sort(tet.begin(), tet.end());
  std::sort(tets.begin(), tets.end());
  return tets;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto pts = fuzz::decode_points(std::span(data, size), kMaxPoints);
  if (pts.empty()) return 0;
  BuildOptions options;
  options.seed = 1 + data[0] / 4;

  const PredicateSpec adaptive_sos{"adaptive", 1e-12, false, true};
  const fuzz::CaseRun run = fuzz::run_case(pts, adaptive_sos, options);
  if (!run.ok()) {
    const std::string what = "adaptive+sos: " + run.outcome + " (" + run.detail + ")";
    fuzz::fuzz_fail(what.c_str(), pts);
  }
  if (run.outcome != "valid") return 0;

  const PredicateSpec exact_sos{"exact", 1e-12, false, true};
  const BuildResult a = build_delaunay(pts, adaptive_sos, options);
  const BuildResult e = build_delaunay(pts, exact_sos, options);
  if (e.failure || canonical_tets(a.mesh) != canonical_tets(e.mesh))
    fuzz::fuzz_fail("adaptive+sos and exact+sos built different tetrahedralizations", pts);
  return 0;
}
