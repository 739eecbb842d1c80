#include "python/src/orientation.hpp"

#include <utility>

#include <pybind11/pybind11.h>

#include "oracle/check/filtered_exact.hpp"

namespace dtlab::python {

void check_orientation_mode(const std::string& mode) {
  if (mode != "positive" && mode != "negative" && mode != "consistent" && mode != "any")
    throw pybind11::value_error("orientation: '" + mode + "' not in {any, consistent, positive, negative}");
}

Orientation orient_tets(Tetrahedralization& t, const std::string& mode) {
  Orientation o{mode, 0};
  const FilteredExact pred;
  const auto sign = [&](const Tet& k) {
    return pred.orient3d(t.points[k[0]], t.points[k[1]], t.points[k[2]], t.points[k[3]]);
  };
  if (mode == "any") {
    for (Tet& k : t.tets)
      if (sign(k) < 0) std::swap(k[0], k[1]), ++o.swapped;
    return o;
  }
  bool flip = mode == "negative";
  if (mode == "consistent") {
    std::uint64_t pos = 0, neg = 0;
    for (const Tet& k : t.tets) {
      const int s = sign(k);
      pos += s > 0;
      neg += s < 0;
    }
    flip = neg > pos;
    o.handedness = flip ? "negative" : "positive";
  }
  if (flip) {
    for (Tet& k : t.tets) std::swap(k[0], k[1]);
    o.swapped = t.tets.size();
  }
  return o;
}

}  // namespace dtlab::python
