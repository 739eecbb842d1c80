#pragma once
// Symbolic perturbation of insphere (Devillers and Teillaud, "Perturbations for
// Delaunay and weighted Delaunay 3D triangulations", CGTA 2011).
//
// The rule. Each point p is lifted to (p, |p|^2 + eps^(n - r(p))), where r(p) is
// p's position in the lexicographic (x, y, z) order of the points (0 = smallest) and
// eps -> 0+: the lexicographically larger a point, the larger its perturbation.
// The lift column appears once in the 5x5 lifted determinant, so the perturbed
// determinant is linear in the offsets: raw insphere value + sum over points of
// offset * coefficient. When the raw value vanishes, the sign is the sign of the
// first non-zero coefficient, taken from the most perturbed point (the
// lexicographically largest) down. The coefficient of the lift of point v is, up to a sign fixed by
// v's column, the orientation of the four other points; writing it with the query
// point e in v's place gives the rule below (for e itself the coefficient is
// -orient3d(a,b,c,d): a perturbed e moves outward, since its lift grows).
//
//   raw = insphere(a,b,c,d,e); if raw != 0 return raw
//   for v in the two lexicographically largest of {a,b,c,d,e}, largest first:
//     if v == e: return -orient3d(a,b,c,d)
//     s = orient3d(a,b,c,d with v replaced by e); if s != 0 return s
//
// Two steps suffice when a,b,c,d are not coplanar (the paper's Lemma): the two
// orientations cannot both vanish. Because the order depends only on the points'
// coordinates, never on insertion order, the perturbed Delaunay tetrahedralization
// is unique; it is the one CGAL's Delaunay_triangulation_3 builds (CGAL uses the
// same order with its opposite orientation sign; see predicates/README note in the
// top-level README). orient3d is left unperturbed: flat configurations are handled
// by the kernel's flips.
//
// The points are compared by value, so the five points must be distinct.
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

template <PredicateBackend B>
struct Perturbed {
  B base;

  std::string_view name() const { return base.name(); }
  static constexpr bool perturbs = true;

  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return base.orient3d(a, b, c, d);
  }

  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               const Point3& e) const {
    const int raw = base.insphere(a, b, c, d, e);
    if (raw != 0) return raw;
    const Point3* pts[5] = {&a, &b, &c, &d, &e};
    // Find the two largest in lexicographic order (indices into pts).
    int first = 0;
    for (int i = 1; i < 5; ++i)
      if (lex_less(*pts[first], *pts[i])) first = i;
    int second = first == 0 ? 1 : 0;
    for (int i = 0; i < 5; ++i)
      if (i != first && lex_less(*pts[second], *pts[i])) second = i;
    for (int v : {first, second}) {
      if (v == 4) return -base.orient3d(a, b, c, d);
      const Point3* q[4] = {&a, &b, &c, &d};
      q[v] = &e;
      const int s = base.orient3d(*q[0], *q[1], *q[2], *q[3]);
      if (s != 0) return s;
    }
    return 0;  // a,b,c,d coplanar: no perturbation decides (the caller never asks)
  }

  // The fused filter of the base (adaptive.hpp), unchanged: a sign it decides is
  // nonzero, so the perturbation would not change it; an undecided insphere goes to
  // insphere() above.
  auto insphere_sides(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                      const Point3& e) const
    requires requires(const B& x, const Point3& q) { x.insphere_sides(q, q, q, q, q); }
  {
    return base.insphere_sides(a, b, c, d, e);
  }
};

}  // namespace dtlab
