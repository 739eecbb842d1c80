#pragma once
// The box the Voronoi cells are clipped to.
#include "predicates/vec3.hpp"

namespace dtlab::vor {

struct Box {
  Point3 lo{0, 0, 0}, hi{0, 0, 0};
  double volume() const { return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z); }
  double diagonal() const { return norm(hi - lo); }
  bool contains(const Point3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
};

}  // namespace dtlab::vor
