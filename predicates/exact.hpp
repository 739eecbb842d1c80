#pragma once
// Exact predicates: the reference every other backend is checked against.
//
// A finite double is m * 2^k exactly, with m an integer of at most 53 bits. All
// coordinates of one call are rescaled by the same power of two 2^-kmin (kmin the
// smallest exponent among them), which turns them into integers without changing
// the sign of either determinant (both are homogeneous, of degree 3 and 5, and the
// scale is positive). The determinants are then evaluated in GMP integers, so the
// answer is exact for every finite input: subnormals, 1e+-300 and mixtures of them.
// Inputs must be finite: a NaN or an infinity throws std::domain_error (no sign to give).
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

struct ExactPredicates {
  static constexpr std::string_view name() { return "exact"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const;
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               const Point3& e) const;
};

// Free functions with the same meaning (used by the adaptive backend's fallback).
int exact_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d);
int exact_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                   const Point3& e);

inline int ExactPredicates::orient3d(const Point3& a, const Point3& b, const Point3& c,
                                     const Point3& d) const {
  return exact_orient3d(a, b, c, d);
}
inline int ExactPredicates::insphere(const Point3& a, const Point3& b, const Point3& c,
                                     const Point3& d, const Point3& e) const {
  return exact_insphere(a, b, c, d, e);
}

static_assert(PredicateBackend<ExactPredicates>);

}  // namespace dtlab
