#pragma once
// Every geometric decision of the inserter, expressed through the predicate backend.
//
// The infinite vertex. Tets outside the convex hull share one "infinite" vertex
// (index inf_), as in CGAL. Orientation questions about them are answered as seen
// from a point O strictly inside the first tetrahedron (a,b,c,d) (TetGen puts a
// dummy point there): seen from O the hull boundary is a sphere, and an infinite
// tet (x,y,z,inf) is the cone from O over its hull facet xyz, beyond it. A valid
// hull facet has O on its inner side:
//
//        inf side (outside)        orient3d(x,y,z,q) > 0 for q outside,
//     x -------------- z           orient3d(x,y,z,O) < 0,
//            O                     so an infinite tet is "positive" iff
//                                  orient3d(x,y,z,O) < 0: orientation() negates it.
//
// O is symbolic: O = a + e1 (b-a) + e2 (c-a) + e3 (d-a) with 1 >> e1 >> e2 >> e3 > 0,
// whose barycentric coordinates are all positive, so O is strictly inside the first
// tet for every input (a double point may not exist there: four points one ulp apart
// span a tet with no double inside). orient3d(x,y,z,.) is affine, so
// orient3d(x,y,z,O) has the sign of the first non-zero of orient3d(x,y,z,a),
// orient3d(x,y,z,b), orient3d(x,y,z,c), orient3d(x,y,z,d): exact with any robust
// backend, and zero only when x,y,z are collinear (a,b,c,d are not coplanar): a real
// degeneracy, handled by the flips.
//
// Conflict (the Delaunay test) never uses O: a finite tet conflicts with p iff p is
// inside its circumsphere (insphere > 0; the Perturbed<> wrapper makes this never
// 0); an infinite tet (x,y,z,inf) conflicts iff p is strictly outside the hull facet
// xyz, or on its plane and inside its circumcircle. The circle test is
// insphere(x,y,z,w,p) for any point w off the plane (the first of a,b,c,d that is):
// the sphere through x,y,z,w cuts the plane in the circumcircle of xyz. It is asked
// of the unperturbed predicate: w is only a device to turn a circle into a sphere, so
// a perturbed answer would depend on w's lexicographic rank, which has nothing to do
// with the triangle and p, and it would never return the zero that sends cocircular
// ties to their own rule: Devillers & Teillaud's perturbation (the rule CGAL uses for
// its coplanar_side_of_bounded_circle): the lexicographically largest of x,y,z,p
// decides; if it is p, p is outside; otherwise replace it by p and ask whether the
// triangle keeps its orientation in the plane (inside) or flips (outside).
//
// Every answer is a Sign (predicates/sign.hpp), converted from the backend's int here.
//
// Counters: calls to orient3d and insphere are counted in plain members (one add in
// a line the caller already holds; kernel/README.md has the measured cost).
#include <cstdint>

#include "kernel/ids.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/backend.hpp"
#include "predicates/sign.hpp"

namespace dtlab {

template <class B>
concept PerturbingBackend = PredicateBackend<B> && requires { B::perturbs; };

// A backend with the fused insphere-and-sides filter (predicates/adaptive.hpp).
template <class B>
concept FusedSidesBackend = requires(const B& b, const Point3& p) {
  { b.insphere_sides(p, p, p, p, p) } -> std::same_as<InsphereSides>;
};

template <PredicateBackend B>
class Geometry {
 public:
  // points: indexed by vertex id; inf the infinite vertex's id, or kNone (bigtet).
  Geometry(const Point3* points, const B& pred, std::uint32_t inf) : p_(points), pred_(pred), inf_(inf) {}

  // The first tet, positively oriented: it defines the symbolic inner point O.
  void set_first_tet(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    first_[0] = a, first_[1] = b, first_[2] = c, first_[3] = d;
  }

  std::uint32_t infinite() const { return inf_; }
  const Point3& point(std::uint32_t v) const { return p_[v]; }

  std::uint64_t orient_calls = 0, insphere_calls = 0;

  Sign orient3d(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    ++orient_calls;
    return to_sign(pred_.orient3d(p_[a], p_[b], p_[c], p_[d]));
  }

  // Orientation of the tet (a,b,c,d), the infinite vertex allowed anywhere:
  // positive iff it is a valid (positively oriented) tet.
  Sign orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    // An even permutation that moves inf to the last slot keeps the sign.
    if (a == inf_) return -orient_from_inside(d, c, b);  // (a,b,c,d) ~ (d,c,b,a)
    if (b == inf_) return -orient_from_inside(c, d, a);  // ~ (c,d,a,b)
    if (c == inf_) return -orient_from_inside(b, a, d);  // ~ (b,a,d,c)
    if (d == inf_) return -orient_from_inside(a, b, c);
    return orient3d(a, b, c, d);
  }
  Sign orientation(const std::uint32_t* v) { return orientation(v[0], v[1], v[2], v[3]); }

  // orient3d(x, y, z, O) for the symbolic inner point O.
  Sign orient_from_inside(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    for (std::uint32_t w : first_)
      if (const Sign s = orient3d(x, y, z, w); s != Sign::zero) return s;
    return Sign::zero;
  }

  // Does p conflict with the tet v (positively oriented, not containing p)?
  // side[k] receives the sign of orientation(v with v[k] replaced by p) where the
  // backend's fused filter decided it on the way, FilterSign::undecided elsewhere.
  bool conflict(const std::uint32_t* v, std::uint32_t p, FilterSign side[4]) {
    side[0] = side[1] = side[2] = side[3] = FilterSign::undecided;
    const int k = v[0] == inf_ ? 0 : v[1] == inf_ ? 1 : v[2] == inf_ ? 2 : v[3] == inf_ ? 3 : -1;
    if (k < 0) {
      ++insphere_calls;
      if constexpr (FusedSidesBackend<B>) {
        const InsphereSides r = pred_.insphere_sides(p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]], p_[p]);
        side[0] = r.side[0], side[1] = r.side[1], side[2] = r.side[2], side[3] = r.side[3];
        if (decided(r.insphere)) return r.insphere == FilterSign::positive;
      }
      return pred_.insphere(p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]], p_[p]) > 0;
    }
    std::uint32_t x, y, z;  // (x,y,z,inf) an even permutation of v
    switch (k) {
      case 0: x = v[3], y = v[2], z = v[1]; break;
      case 1: x = v[2], y = v[3], z = v[0]; break;
      case 2: x = v[1], y = v[0], z = v[3]; break;
      default: x = v[0], y = v[1], z = v[2]; break;
    }
    const Sign side_of_hull = orient3d(x, y, z, p);
    if (side_of_hull != Sign::zero) return side_of_hull == Sign::positive;
    return in_hull_circle(x, y, z, p);
  }
  bool conflict(const std::uint32_t* v, std::uint32_t p) {
    FilterSign side[4];
    return conflict(v, p, side);
  }

 private:
  Sign raw_insphere(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::uint32_t e) {
    if constexpr (PerturbingBackend<B>)
      return to_sign(pred_.base.insphere(p_[a], p_[b], p_[c], p_[d], p_[e]));
    else
      return to_sign(pred_.insphere(p_[a], p_[b], p_[c], p_[d], p_[e]));
  }

  // p on the plane of the hull facet (x,y,z), whose O side is negative.
  bool in_hull_circle(std::uint32_t x, std::uint32_t y, std::uint32_t z, std::uint32_t p) {
    ++insphere_calls;
    Sign in = Sign::zero;
    for (std::uint32_t w : first_)
      if (const Sign side = orient3d(x, y, z, w); side != Sign::zero) {
        in = side * raw_insphere(x, y, z, w, p);
        break;
      }
    if (in != Sign::zero) return in == Sign::positive;
    if constexpr (!PerturbingBackend<B>) {
      return false;
    } else {
      std::uint32_t q[4] = {x, y, z, p};
      // The three largest of the four, largest first.
      for (int round = 0; round < 3; ++round) {
        int best = -1;
        for (int i = 0; i < 4; ++i) {
          if (q[i] == kNone) continue;
          if (best < 0 || lex_less(p_[q[best]], p_[q[i]])) best = i;
        }
        if (best == 3) return false;
        std::uint32_t t[3] = {x, y, z};
        t[best] = p;
        // Same orientation seen from O as (x,y,z), which is negative: inside.
        const Sign o = orient_from_inside(t[0], t[1], t[2]);
        if (o != Sign::zero) return o == Sign::negative;
        q[best] = kNone;
      }
      return false;
    }
  }

  const Point3* p_;
  B pred_;
  std::uint32_t inf_;
  std::uint32_t first_[4] = {0, 0, 0, 0};
};

}  // namespace dtlab
