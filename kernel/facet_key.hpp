#pragma once
// A facet named by its three vertex ids in ascending order: two tets share a facet
// exactly when their keys are equal (start() glues its first tets this way).
#include <algorithm>
#include <cstdint>

namespace dtlab {

struct FacetKey {
  std::uint32_t v[3];
  bool operator==(const FacetKey&) const = default;
};

// The key of facet f (the one opposite vertex f) of a tet with vertices tv[0..3].
inline FacetKey facet_key(const std::uint32_t* tv, int f) {
  std::uint32_t a = tv[(f + 1) & 3], b = tv[(f + 2) & 3], c = tv[(f + 3) & 3];
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {{a, b, c}};
}

}  // namespace dtlab
