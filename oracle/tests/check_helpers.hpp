#pragma once
// Helpers shared by the checker's tests.
#include <cstdint>
#include <string>
#include <utility>

#include "oracle/check.hpp"
#include "predicates/exact.hpp"

namespace dtlab::test {

inline std::uint64_t count(const CheckReport& r, DefectKind k) { return r.counts[static_cast<std::size_t>(k)]; }

// Every listed defect, one line each: what a failing CHECK prints.
inline std::string summary(const CheckReport& r) {
  std::string s;
  for (const auto& d : r.defects) s.append(defect_name(d.kind)).append(": ").append(d.detail).append("\n");
  return s;
}

// Swaps two vertices where needed so that every tet has orient3d > 0.
inline void orient(Tetrahedralization& t) {
  for (Tet& k : t.tets)
    if (ExactPredicates{}.orient3d(t.points[k[0]], t.points[k[1]], t.points[k[2]], t.points[k[3]]) < 0)
      std::swap(k[0], k[1]);
}

}  // namespace dtlab::test
