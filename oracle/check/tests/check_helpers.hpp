#pragma once
// Helpers shared by the checker's tests.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "oracle/check/check.hpp"
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

// The checker's two entry points must agree: the one that renumbers the mesh it is
// given (by first appearance) reports in the caller's numbering. With every witness
// kept, the two reports hold the same defects, possibly in another order.
inline std::string report_key(const CheckReport& r) {
  auto number = [](std::string& s, auto x) { s.append(" ").append(std::to_string(x)); };
  std::vector<std::string> lines;
  for (const auto& d : r.defects) {
    std::string s = defect_name(d.kind);
    number(s, d.sign);
    s.append(" tets");
    for (auto t : d.tets) number(s, t);
    s.append(" vertices");
    for (auto v : d.vertices) number(s, v);
    lines.push_back(s.append(": ").append(d.detail));
  }
  std::sort(lines.begin(), lines.end());
  std::string key;
  for (const auto& l : lines) key.append(l).append("\n");
  for (auto c : r.counts) number(key, c);
  const CheckStats& st = r.stats;
  key.append("\nstats");
  for (auto x : {st.vertices, st.edges, st.interior_facets, st.boundary_facets, st.duplicates, st.cospherical_facets,
                 std::uint64_t{st.cover_proven}})
    number(key, x);
  number(key, st.volume_hull);
  key.append("\ncospherical");
  auto pairs = r.cospherical_pairs;
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [a, b] : pairs) number(key, std::uint64_t{a} << 32 | b);
  return key;
}

// Checks t both ways, every witness kept; requires the same report, returns it.
inline CheckReport check_both_ways(const Tetrahedralization& t, CheckOptions o = {}) {
  o.witnesses_per_kind = std::size_t{1} << 30;
  const CheckReport kept = check_tetrahedralization(t, o);
  const CheckReport renumbered = check_tetrahedralization(Tetrahedralization(t), o);
  CHECK(report_key(renumbered) == report_key(kept));
  return kept;
}

}  // namespace dtlab::test
