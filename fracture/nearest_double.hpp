#pragma once
// An exact number rounded to the nearest double (ties to even), so that a written
// coordinate depends on the exact value only, never on the build: a lazy number's
// interval differs between -O1 and -O3 builds, its exact value does not.
#include <bit>
#include <cmath>
#include <cstdint>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace dtlab {

// Any CGAL exact field type (Gmpq, mpq_class): its to_interval is the pair of adjacent
// doubles around the value (or the value twice), so the exact midpoint decides.
template <class ET>
double nearest_double(const ET& x) {
  const auto [lo, hi] = CGAL::to_interval(x);
  if (lo == hi) return lo;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return std::isfinite(lo) ? lo : hi;
  const ET mid = (ET(lo) + ET(hi)) / 2;
  if (x < mid) return lo;
  if (mid < x) return hi;
  return (std::bit_cast<std::uint64_t>(lo) & 1) == 0 ? lo : hi;
}

// A lazy-exact number: its interval when that is one double (then it is the value),
// else its exact value rounded.
inline double nearest_double(const CGAL::Epeck::FT& v) {
  const auto& i = v.approx();
  if (i.inf() == i.sup()) return i.inf();
  return nearest_double(v.exact());
}

}  // namespace dtlab
