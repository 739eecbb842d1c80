#pragma once
// The naive determinants with a tolerance band: the thesis's "immediate fix".
// Answers 0 when the computed determinant lies inside the band:
//   absolute: |det| <= eps
//   relative: |det| <= eps * M^k, M the largest |coordinate difference| to the last
//             point and k the degree of the determinant (3 for orient3d, 5 for
//             insphere): the band scales with the configuration.
// Neither mode is correct in general; the testbed keeps it to show how it fails.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "predicates/naive.hpp"

namespace dtlab {

struct EpsilonPredicates {
  double eps = 1e-12;
  bool relative = false;

  static constexpr std::string_view name() { return "epsilon"; }

  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    const double det = orient3d_value(a, b, c, d);
    double band = eps;
    if (relative) {
      const double m = std::max({max_diff(a, d), max_diff(b, d), max_diff(c, d)});
      band = eps * (m * m * m);
    }
    return std::fabs(det) <= band ? 0 : sign_of(det);
  }

  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               const Point3& e) const {
    const double det = insphere_value(a, b, c, d, e);
    double band = eps;
    if (relative) {
      const double m = std::max({max_diff(a, e), max_diff(b, e), max_diff(c, e), max_diff(d, e)});
      band = eps * (m * m * m * m * m);
    }
    return std::fabs(det) <= band ? 0 : sign_of(det);
  }

 private:
  static double max_diff(const Point3& p, const Point3& q) {
    return std::max({std::fabs(p.x - q.x), std::fabs(p.y - q.y), std::fabs(p.z - q.z)});
  }
};

static_assert(PredicateBackend<EpsilonPredicates>);

}  // namespace dtlab
