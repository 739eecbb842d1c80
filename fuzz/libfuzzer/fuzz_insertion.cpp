// libFuzzer target: insertion validity. Bytes -> up to 64 points (fuzz/libfuzzer/
// byte_points.hpp; byte 0 / 4 also seeds the BRIO order) -> build_delaunay with
// adaptive+sos -> the exact checker (through fuzz::run_case, which also proves a
// "lower-dimensional" answer exactly). Anything but a valid tetrahedralization, or a
// correct lower-dimensional verdict, aborts. The perturbed Delaunay tetrahedralization
// is unique, so exact+sos must build the same tets: compared as sorted vertex sets.
// adaptive and exact without perturbation must be valid too. Every backend (naive,
// epsilon absolute and relative included) is also run with both boundaries (infinite,
// bigtet): their promise is to end valid or with a named failure, never to crash or
// hang, which the sanitizers and libFuzzer's time-out watch.
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
volatile std::size_t g_tets = 0;  // keeps the unchecked builds alive

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

  for (const char* robust : {"adaptive", "exact"}) {
    const fuzz::CaseRun r = fuzz::run_case(pts, PredicateSpec{robust, 1e-12, false, false}, options);
    if (!r.ok()) {
      const std::string what = std::string(robust) + " (no perturbation): " + r.outcome + " (" + r.detail + ")";
      fuzz::fuzz_fail(what.c_str(), pts);
    }
  }
  // Every backend with both boundaries: a result or a named failure, nothing else.
  BuildOptions bigtet = options;
  bigtet.boundary = Boundary::bigtet;
  for (const PredicateSpec& spec : {PredicateSpec{"naive", 1e-12, false, true}, PredicateSpec{"naive", 1e-12, false, false},
                                    PredicateSpec{"epsilon", 1e-12, false, true}, PredicateSpec{"epsilon", 1e-9, true, false},
                                    adaptive_sos, exact_sos}) {
    for (const BuildOptions& o : {options, bigtet}) {
      // bigtet may lose hull tets (the thesis's failure): no assertion on the mesh. An
      // escaping exception, a sanitizer report or a hang is the finding.
      const BuildResult b = build_delaunay(pts, spec, o);
      g_tets = g_tets + b.mesh.tets.size();
    }
  }
  return 0;
}
