// libFuzzer target: predicate agreement. Bytes -> 4 or 5 points (fuzz/libfuzzer/
// byte_points.hpp) -> orient3d on every 4-subset and insphere on the 5 points, with
// every backend. naive and epsilon are run (for the sanitizers) but may disagree with
// exact: that is their documented failure. Asserted: adaptive == exact, the exact
// checker's FilteredExact (oracle/) == exact, Perturbed<adaptive> ==
// Perturbed<exact>, exact's antisymmetry under a swap, and that the perturbed
// insphere of 5 distinct points is never 0 unless a,b,c,d are coplanar.
// DTLAB_FUZZ_NO_CHECKER=1 in the environment skips the FilteredExact assertions
// (while a known checker bug is open, fuzz/README.md).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "fuzz/libfuzzer/byte_points.hpp"
#include "fuzz/libfuzzer/fuzz_report.hpp"
#include "oracle/check/filtered_exact.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/naive.hpp"
#include "predicates/perturbed.hpp"

using namespace dtlab;

namespace {

volatile int g_sink = 0;  // keeps the unchecked backends' answers alive

template <class B>
void exercise(const B& b, const Point3* p, std::size_t n) {
  g_sink = g_sink + b.orient3d(p[0], p[1], p[2], p[3]);
  if (n == 5) g_sink = g_sink + b.insphere(p[0], p[1], p[2], p[3], p[4]);
}

bool all_distinct(const Point3* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (p[i] == p[j]) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto pts = fuzz::decode_points(std::span(data, size), 5);
  if (pts.size() < 4) return 0;
  const Point3* p = pts.data();
  const std::size_t n = pts.size();

  exercise(NaivePredicates{}, p, n);
  exercise(EpsilonPredicates{1e-12, false}, p, n);
  exercise(EpsilonPredicates{1e-12, true}, p, n);

  static const bool check_checker = std::getenv("DTLAB_FUZZ_NO_CHECKER") == nullptr;
  const AdaptivePredicates adaptive;
  const ExactPredicates exact;
  const FilteredExact checker;
  // orient3d on each 4-subset (the one left out is `skip`; n == 4: just the first).
  for (std::size_t skip = n == 5 ? 0 : 4; skip < 5; ++skip) {
    const Point3* q[4];
    for (std::size_t i = 0, k = 0; i < n; ++i)
      if (i != skip) q[k++] = &p[i];
    const int e = exact.orient3d(*q[0], *q[1], *q[2], *q[3]);
    if (adaptive.orient3d(*q[0], *q[1], *q[2], *q[3]) != e)
      fuzz::fuzz_fail("adaptive orient3d != exact", pts);
    if (check_checker && checker.orient3d(*q[0], *q[1], *q[2], *q[3]) != e)
      fuzz::fuzz_fail("FilteredExact (checker) orient3d != exact", pts);
    if (exact.orient3d(*q[1], *q[0], *q[2], *q[3]) != -e)
      fuzz::fuzz_fail("exact orient3d not antisymmetric", pts);
  }
  if (n < 5) return 0;

  const int e = exact.insphere(p[0], p[1], p[2], p[3], p[4]);
  if (adaptive.insphere(p[0], p[1], p[2], p[3], p[4]) != e)
    fuzz::fuzz_fail("adaptive insphere != exact", pts);
  if (check_checker && checker.insphere(p[0], p[1], p[2], p[3], p[4]) != e)
    fuzz::fuzz_fail("FilteredExact (checker) insphere != exact", pts);
  if (exact.insphere(p[1], p[0], p[2], p[3], p[4]) != -e)
    fuzz::fuzz_fail("exact insphere not antisymmetric", pts);

  const Perturbed<AdaptivePredicates> padaptive{};
  const Perturbed<ExactPredicates> pexact{};
  const int pe = pexact.insphere(p[0], p[1], p[2], p[3], p[4]);
  if (padaptive.insphere(p[0], p[1], p[2], p[3], p[4]) != pe)
    fuzz::fuzz_fail("perturbed adaptive insphere != perturbed exact", pts);
  if (pe == 0 && all_distinct(p, n) && exact.orient3d(p[0], p[1], p[2], p[3]) != 0)
    fuzz::fuzz_fail("perturbed insphere is 0 on a non-coplanar a,b,c,d", pts);
  return 0;
}
