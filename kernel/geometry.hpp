#pragma once
// Every geometric decision of the inserter, expressed through the predicate backend.
//
// The infinite vertex. Tets outside the convex hull share one "infinite" vertex
// (index inf_), as in CGAL. For orientation questions the infinite vertex gets the
// coordinates of a point O strictly inside the first tetrahedron (TetGen's trick):
// seen from O, the hull boundary is a sphere, and an infinite tet (x,y,z,inf) is
// the cone from O over the hull facet xyz, beyond it. Because O lies inside, a
// valid hull facet xyz has O on its inner side:
//
//        inf side (outside)        orient3d(x,y,z,q) > 0 for q outside,
//     x -------------- z           orient3d(x,y,z,O) < 0,
//            O                     so an infinite tet is "positive" iff
//                                  orient3d(x,y,z,O) < 0: orientation() negates it.
//
// A facet through O can never be a hull facet, yet orient3d(x,y,z,O) may vanish for
// a candidate facet by coincidence (lattice inputs). O is therefore perturbed
// symbolically: O' = O + e*(1, e', e'^2), e >> e' > 0 infinitesimal. Shewchuk's
// orient3d(x,y,z,q) = -n.(q - x) with n = (y-x) x (z-x), so the tie is broken by
// -sign(n_x), then -sign(n_y), then -sign(n_z); each n_k is a 2D orientation of
// the projected points, computed exactly by the backend through orient3d on
// points with one coordinate zeroed (exact copies of the input doubles). Only
// collinear x,y,z give 0: a real degeneracy, handled by the flips.
//
// Conflict (the Delaunay test) never uses O's position except to orient a plane:
// a finite tet conflicts with p iff p is inside its circumsphere (insphere > 0; the
// Perturbed<> wrapper makes this never 0); an infinite tet (x,y,z,inf) conflicts
// iff p is strictly outside the hull facet xyz, or on its plane and inside its
// circumcircle. The circle test is insphere(x,y,z,O,p): the sphere through x,y,z
// and any point off their plane cuts the plane in the circumcircle. Cocircular
// ties follow Devillers & Teillaud's perturbation (the rule CGAL uses for its
// coplanar_side_of_bounded_circle): the lexicographically largest of x,y,z,p
// decides; if it is p, p is outside; otherwise replace it by p and ask whether
// the triangle keeps its orientation in the plane (inside) or flips (outside).
#include <cstdint>
#include <vector>

#include "predicates/backend.hpp"

namespace dtlab {

template <class B>
concept PerturbingBackend = PredicateBackend<B> && requires { B::perturbs; };

template <PredicateBackend B>
class Geometry {
 public:
  Geometry(const std::vector<Point3>& points, const B& pred, std::uint32_t inf)
      : p_(points), pred_(pred), inf_(inf) {}

  std::uint32_t infinite() const { return inf_; }
  const Point3& point(std::uint32_t v) const { return p_[v]; }
  const B& predicates() const { return pred_; }

  std::uint64_t orient_calls = 0, insphere_calls = 0;

  int orient3d(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    ++orient_calls;
    return pred_.orient3d(p_[a], p_[b], p_[c], p_[d]);
  }

  // Orientation of the tet (a,b,c,d), the infinite vertex allowed anywhere:
  // > 0 iff it is a valid (positively oriented) tet.
  int orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    // An even permutation that moves inf to the last slot keeps the sign.
    if (a == inf_) return -orient_from_inside(d, c, b);  // (a,b,c,d) ~ (d,c,b,a)
    if (b == inf_) return -orient_from_inside(c, d, a);  // ~ (c,d,a,b)
    if (c == inf_) return -orient_from_inside(b, a, d);  // ~ (b,a,d,c)
    if (d == inf_) return -orient_from_inside(a, b, c);
    return orient3d(a, b, c, d);
  }

  // orient3d(x, y, z, O') with the symbolically perturbed O'.
  int orient_from_inside(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    const int s = orient3d(x, y, z, inf_);
    if (s != 0) return s;
    const Point3 &a = p_[x], &b = p_[y], &c = p_[z];
    if (int nx = orient2d(a.y, a.z, b.y, b.z, c.y, c.z)) return -nx;
    if (int ny = orient2d(a.z, a.x, b.z, b.x, c.z, c.x)) return -ny;
    return -orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
  }

  // Does p conflict with the tet (a,b,c,d) (which does not contain p)?
  bool conflict(const std::uint32_t* v, std::uint32_t p) {
    int k = v[0] == inf_ ? 0 : v[1] == inf_ ? 1 : v[2] == inf_ ? 2 : v[3] == inf_ ? 3 : -1;
    if (k < 0) {
      ++insphere_calls;
      return pred_.insphere(p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]], p_[p]) > 0;
    }
    std::uint32_t x, y, z;  // (x,y,z,inf) an even permutation of v
    switch (k) {
      case 0: x = v[3], y = v[2], z = v[1]; break;
      case 1: x = v[2], y = v[3], z = v[0]; break;
      case 2: x = v[1], y = v[0], z = v[3]; break;
      default: x = v[0], y = v[1], z = v[2]; break;
    }
    const int side = orient3d(x, y, z, p);
    if (side != 0) return side > 0;
    return in_hull_circle(x, y, z, p);
  }

 private:
  int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    // orient3d((a,0),(b,0),(c,0),(0,0,1)) = -orient2d(a,b,c): see the header comment.
    ++orient_calls;
    return -pred_.orient3d({ax, ay, 0}, {bx, by, 0}, {cx, cy, 0}, {0, 0, 1});
  }

  // p on the plane of the hull facet (x,y,z), whose O side is negative.
  bool in_hull_circle(std::uint32_t x, std::uint32_t y, std::uint32_t z, std::uint32_t p) {
    ++insphere_calls;
    // orient3d(x,y,z,O) < 0, so "p inside the sphere through x,y,z,O" is insphere < 0.
    const int in = -pred_.insphere(p_[x], p_[y], p_[z], p_[inf_], p_[p]);
    if (in != 0) return in > 0;
    if constexpr (!PerturbingBackend<B>) {
      return false;
    } else {
      std::uint32_t q[4] = {x, y, z, p};
      // The three largest of the four, largest first.
      for (int round = 0; round < 3; ++round) {
        int best = -1;
        for (int i = 0; i < 4; ++i) {
          if (q[i] == TetMesh_none) continue;
          if (best < 0 || lex_less(p_[q[best]], p_[q[i]])) best = i;
        }
        if (best == 3) return false;
        std::uint32_t t[3] = {x, y, z};
        t[best] = p;
        // Same orientation seen from O as (x,y,z), which is negative: inside.
        const int o = orient3d(t[0], t[1], t[2], inf_);
        if (o != 0) return o < 0;
        q[best] = TetMesh_none;
      }
      return false;
    }
  }

  static constexpr std::uint32_t TetMesh_none = 0xFFFFFFFFu;

  const std::vector<Point3>& p_;
  B pred_;
  std::uint32_t inf_;
};

}  // namespace dtlab
