#pragma once
// The predicate-backend concept: every structural decision of the kernel goes
// through one of these.
//
// Sign convention (Shewchuk's, used everywhere in dtlab):
//   orient3d(a,b,c,d) > 0  iff d lies below the plane through a,b,c, where a,b,c
//                           appear counter-clockwise seen from above; equivalently
//                           det[a-d; b-d; c-d] > 0.
//   insphere(a,b,c,d,e) > 0 iff e lies inside the sphere through a,b,c,d when
//                           orient3d(a,b,c,d) > 0 (the sign flips with the
//                           orientation: it is the sign of the lifted 5x5 determinant).
// A backend returns the raw sign in {-1, 0, +1}; zero is a legal answer.
#include <concepts>
#include <string_view>

#include "predicates/point.hpp"

namespace dtlab {

template <class B>
concept PredicateBackend = requires(const B& b, const Point3& p) {
  { b.orient3d(p, p, p, p) } -> std::same_as<int>;
  { b.insphere(p, p, p, p, p) } -> std::same_as<int>;
  { b.name() } -> std::convertible_to<std::string_view>;
};

constexpr int sign_of(double v) { return (v > 0) - (v < 0); }

}  // namespace dtlab
