#pragma once
// A wrapper that counts calls and zero answers per predicate and, when the wrapped
// backend is AdaptivePredicates (bare or perturbed), which adaptive stage decided
// each call.
// Counters live in the wrapper (mutable): use one wrapper per thread.
#include <cstdint>
#include <string_view>
#include <type_traits>

#include "predicates/adaptive.hpp"
#include "predicates/backend.hpp"
#include "predicates/perturbed.hpp"

namespace dtlab {

struct PredicateCounts {
  std::uint64_t orient3d_calls = 0, orient3d_zero = 0;
  std::uint64_t insphere_calls = 0, insphere_zero = 0;
};

template <PredicateBackend B>
struct Counting {
  B base;
  mutable PredicateCounts counts;
  // Filled only when B is AdaptivePredicates or Perturbed<AdaptivePredicates> (then
  // it also counts the orient3d calls the perturbation makes).
  mutable AdaptiveStats stages;

  Counting() { attach(); }
  explicit Counting(B b) : base(std::move(b)) { attach(); }
  Counting(const Counting& o) : base(o.base), counts(o.counts), stages(o.stages) { attach(); }
  Counting& operator=(const Counting& o) {
    base = o.base;
    counts = o.counts;
    stages = o.stages;
    attach();
    return *this;
  }

  std::string_view name() const { return base.name(); }

  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    const int s = base.orient3d(a, b, c, d);
    ++counts.orient3d_calls;
    counts.orient3d_zero += (s == 0);
    return s;
  }
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               const Point3& e) const {
    const int s = base.insphere(a, b, c, d, e);
    ++counts.insphere_calls;
    counts.insphere_zero += (s == 0);
    return s;
  }

  void reset() {
    counts = {};
    stages = {};
  }

 private:
  void attach() {
    if constexpr (std::is_same_v<B, AdaptivePredicates>) base.stats = &stages;
    if constexpr (std::is_same_v<B, Perturbed<AdaptivePredicates>>) base.base.stats = &stages;
  }
};

}  // namespace dtlab
