#pragma once
// The one flip-based incremental inserter (Edelsbrunner & Shah 1996, as explained by
// Ledoux 2007 and implemented in the thesis), templated on the predicate backend.
//
// Insert(p): walk to the tet containing p, split it (flip 1-4), then repeat on a
// stack of tets incident to p: take T = (p,a,b,c), its neighbour Ta = (a,b,c,d)
// across the facet opposite p; if p is inside Ta's circumsphere, flip. Which flip
// depends on where the segment pd meets the plane of abc; we read it off the
// orientations s_x of T with x replaced by d, for x in {a,b,c} (the three tets a
// flip 2-3 would create):
//
//   case 1: all s_x > 0            pd crosses triangle abc      -> flip 2-3
//   case 2: one s_x < 0, and the   pd passes outside edge yz    -> flip 3-2 on yz
//           tet (p,y,z,d) exists   (x is the third vertex)
//   case 3: one s_x = 0, T not     pd crosses edge yz; edge yz  -> flip 4-4
//           flat, config 4-4       has 4 tets: T, Ta, (y,z,d,e), (p,y,z,e)
//   case 4: one s_x = 0, T flat    p lies on edge yz            -> flip 2-3 (another
//                                                                 flat tet appears and
//                                                                 leaves in a later flip)
//   otherwise: no flip now; a later flip of a neighbour removes T.
//
//        flip 2-3 / 3-2                      flip 4-4 (seen along pd)
//           p                                     p
//          /|\                                 x  |  e
//         / | \        <->   T = pabc,        y---+---z     <->  y   p|d   z
//        a--+--c             Ta = abcd         x  |  e           x  / \  e
//         \ | /              vs pdab,pdbc,        d             (4 tets around pd)
//          \|/               pdca (edge pd)    (4 tets around yz)
//           d
//
// Every flip is a call of retriangulate() with the new tets listed explicitly, so
// the adjacency bookkeeping lives in one place. Flips and walks are bounded; a
// non-robust backend that would loop forever stops with a named failure instead.
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/build.hpp"
#include "kernel/geometry.hpp"
#include "kernel/id_stack.hpp"
#include "kernel/retriangulate.hpp"
#include "kernel/tet_mesh.hpp"

namespace dtlab {

template <PredicateBackend B>
class Inserter {
 public:
  enum class Outcome { inserted, duplicate, failed };
  static constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;  // `inf` when there is none

  Inserter(const std::vector<Point3>& points, const B& pred, std::uint32_t inf, std::uint64_t seed)
      : geo_(points, pred, inf), rng_(seed * 0x9E3779B97F4A7C15ull + 1) {}

  // The first tet (positively oriented) and, with an infinite vertex, the four
  // infinite tets on its facets: the one on facet f is the first tet with vertex f
  // replaced by inf, and two others swapped (inf lies across facet f, so the
  // orientation flips).
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    const std::uint32_t t0 = mesh_.create(a, b, c, d);
    last_ = t0;
    geo_.set_first_tet(a, b, c, d);
    if (geo_.infinite() == kNoVertex) return;
    std::uint32_t tets[5] = {t0};
    for (int f = 0; f < 4; ++f) {
      std::uint32_t v[4] = {a, b, c, d};
      v[f] = geo_.infinite();
      std::swap(v[(f + 1) & 3], v[(f + 2) & 3]);
      tets[f + 1] = mesh_.create(v[0], v[1], v[2], v[3]);
    }
    for (int i = 0; i < 5; ++i)
      for (int f = 0; f < 4; ++f)
        for (int j = i + 1; j < 5; ++j)
          for (int g = 0; g < 4; ++g)
            if (facet_key(mesh_.verts(tets[i]), f) == facet_key(mesh_.verts(tets[j]), g))
              mesh_.link(4 * tets[i] + f, 4 * tets[j] + g);
  }

  Outcome insert(std::uint32_t p) {
    std::uint32_t t;
    bool on_boundary = false;
    if (!locate(p, t, on_boundary)) return Outcome::failed;
    const std::uint32_t* v = mesh_.verts(t);
    for (int i = 0; i < 4; ++i)
      if (v[i] != geo_.infinite() && geo_.point(v[i]) == geo_.point(p)) {
        duplicate_of_ = v[i];
        return Outcome::duplicate;
      }
    flip14(t, p);
    ++stats_.flips14;
    if (!restore_delaunay(p, !on_boundary)) return Outcome::failed;
    ++stats_.inserted;
    return Outcome::inserted;
  }

  const TetMesh& mesh() const { return mesh_; }
  void release_adjacency() { mesh_.release_adjacency(); }
  Geometry<B>& geometry() { return geo_; }
  BuildStats& stats() { return stats_; }
  FailureKind failure() const { return failure_; }
  const std::string& failure_detail() const { return detail_; }
  std::uint32_t duplicate_of() const { return duplicate_of_; }
  void reserve(std::size_t points) {
    mesh_.reserve(7 * points + 64);
    stack_.reserve(1024);
  }

 private:
  std::uint32_t next_random() {
    rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;
    return static_cast<std::uint32_t>(rng_ >> 32);
  }

  int orientation(const std::uint32_t* w) { return geo_.orientation(w[0], w[1], w[2], w[3]); }

  bool fail(FailureKind k, std::string detail) {
    failure_ = k;
    detail_ = std::move(detail);
    return false;
  }

  // Visibility walk from the last tet touched, leaving each tet through a facet
  // that separates it from p, chosen in random order so the walk cannot cycle
  // (with exact predicates). Stops in a tet whose closure contains p; on_boundary
  // tells whether p lies on its boundary (a facet, an edge or a vertex).
  bool locate(std::uint32_t p, std::uint32_t& out, bool& on_boundary) {
    std::uint32_t t = last_;
    if (mesh_.dead(t))
      for (t = 0; mesh_.dead(t); ++t) {}
    std::uint32_t entry = TetMesh::kNoFacet;
    const std::uint64_t max_steps = 1000 + 2 * std::uint64_t(mesh_.live());
    for (std::uint64_t step = 0; step < max_steps; ++step) {
      const std::uint32_t r = next_random();
      bool moved = false;
      on_boundary = false;
      for (int k = 0; k < 4 && !moved; ++k) {
        const int f = (r + k) & 3;
        if (4 * t + f == entry) continue;
        std::uint32_t w[4] = {mesh_.vertex(t, 0), mesh_.vertex(t, 1), mesh_.vertex(t, 2), mesh_.vertex(t, 3)};
        w[f] = p;
        const int s = orientation(w);
        on_boundary |= s == 0;
        if (s < 0) {
          const std::uint32_t nb = mesh_.adj(4 * t + f);
          if (nb == TetMesh::kNoFacet)
            return fail(FailureKind::outside_boundary, "point lies outside the enclosing tetrahedron");
          entry = nb;
          t = nb >> 2;
          moved = true;
        }
      }
      ++stats_.walk_steps;
      if (!moved) {
        out = t;
        return true;
      }
    }
    return fail(FailureKind::walk_cycle, "walk exceeded " + std::to_string(max_steps) + " steps");
  }

  bool replace(const std::uint32_t* old_tets, int n_old, const std::array<std::uint32_t, 4>* new_tets,
               int n_new) {
    std::uint32_t created[4];
    if (!retriangulate(mesh_, old_tets, n_old, new_tets, n_new, created))
      return fail(FailureKind::inconsistent_adjacency, "facets of a flip did not match up");
    for (int i = 0; i < n_new; ++i) stack_.push_back(created[i]);
    last_ = created[0];
    return true;
  }

  // T (tet t, p at position i) with the vertex at position j replaced by d.
  static std::array<std::uint32_t, 4> swap_in(const std::uint32_t* tv, int j, std::uint32_t d) {
    std::array<std::uint32_t, 4> w = {tv[0], tv[1], tv[2], tv[3]};
    w[j] = d;
    return w;
  }

  // `clean`: p was strictly inside a tet, so every tet stays positively oriented
  // until some orientation test returns 0. In a clean state an edge of abc with
  // exactly three tets (T, Ta and (p,y,z,d)) pierces the triangle of its link, so
  // the flip 3-2 is valid without a test, and no other flip can be (the five points
  // span one 4-simplex; a valid mesh holds one side of its boundary). This is
  // Ledoux's case 2 with the combinatorial test first; it saves most orientation
  // tests. The first zero switches to the full case analysis for the rest of p.
  bool restore_delaunay(std::uint32_t p, bool clean) {
    const std::uint64_t max_flips = 1000 + 8 * std::uint64_t(mesh_.live());
    std::uint64_t flips = 0;
    while (!stack_.empty()) {
      const std::uint32_t t = stack_.back();
      stack_.pop_back();
      if (mesh_.dead(t)) continue;
      const int i = mesh_.index_of(t, p);
      if (i < 0) continue;
      const std::uint32_t across = mesh_.adj(4 * t + i);
      if (across == TetMesh::kNoFacet) continue;
      const std::uint32_t ta = across >> 2;
      if (!geo_.conflict(mesh_.verts(ta), p)) continue;
      const std::uint32_t d = mesh_.vertex(ta, across & 3);
      const std::uint32_t* tv = mesh_.verts(t);
      if (++flips > max_flips)
        return fail(FailureKind::flip_stuck, "more than " + std::to_string(max_flips) + " flips");

      if (clean) {
        int third = -1;
        for (int j = 0; j < 4 && third < 0; ++j) {
          if (j == i) continue;
          const std::uint32_t side = mesh_.adj(4 * t + j);
          if (side != TetMesh::kNoFacet && mesh_.vertex(side >> 2, side & 3) == d) third = j;
        }
        if (third >= 0) {
          if (!flip32(t, i, third, ta, mesh_.adj(4 * t + third) >> 2, d)) return false;
          continue;
        }
        bool positive = true;
        for (int j = 0; j < 4 && positive && clean; ++j) {
          if (j == i) continue;
          const auto w = swap_in(tv, j, d);
          const int s = orientation(w.data());
          positive = s > 0;
          clean = s != 0;
        }
        if (clean) {
          if (positive && !flip23(t, i, ta, d)) return false;
          continue;
        }
      }

      int neg = 0, zero = 0, which = -1;
      for (int j = 0; j < 4 && neg + zero < 2; ++j) {
        if (j == i) continue;
        const auto w = swap_in(tv, j, d);
        const int s = orientation(w.data());
        if (s < 0) ++neg, which = j;
        if (s == 0) ++zero, which = j;
      }

      if (neg == 0 && zero == 0) {
        if (!flip23(t, i, ta, d)) return false;
        continue;
      }
      if (neg + zero != 1) continue;
      const std::uint32_t side = mesh_.adj(4 * t + which);
      if (side != TetMesh::kNoFacet && mesh_.vertex(side >> 2, side & 3) == d) {
        if (!flip32(t, i, which, ta, side >> 2, d)) return false;
        continue;
      }
      if (zero == 1) {
        if (orientation(tv) == 0) {
          if (!flip23(t, i, ta, d)) return false;
        } else if (!flip44(t, i, which, ta, d)) {
          return false;
        }
      }
    }
    return true;
  }

  // Flip 1-4, written out: N_k is T with vertex k replaced by p. Its facet k is T's
  // old facet k; its facet l (l != k) is N_l's facet k.
  void flip14(std::uint32_t t, std::uint32_t p) {
    std::uint32_t tv[4], outer[4], n[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(t, k), outer[k] = mesh_.adj(4 * t + k);
    mesh_.destroy(t);
    for (int k = 0; k < 4; ++k) {
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[k] = p;
      n[k] = mesh_.create(w[0], w[1], w[2], w[3]);
    }
    for (int k = 0; k < 4; ++k) {
      mesh_.link(4 * n[k] + k, outer[k]);
      for (int l = k + 1; l < 4; ++l) mesh_.link(4 * n[k] + l, 4 * n[l] + k);
      stack_.push_back(n[k]);
    }
    last_ = n[0];
  }

  // Flip 2-3, written out: N_k (k != i) is T with its vertex at position k replaced
  // by d. Its facet k is T's old facet k, its facet i is Ta's old facet opposite
  // T[k], and its facet l (l != i, k) is N_l's facet k.
  bool flip23(std::uint32_t t, int i, std::uint32_t ta, std::uint32_t d) {
    std::uint32_t tv[4], outer_t[4], outer_ta[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(t, k), outer_t[k] = mesh_.adj(4 * t + k);
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      const int m = mesh_.index_of(ta, tv[k]);
      if (m < 0) return fail(FailureKind::inconsistent_adjacency, "flip 2-3: neighbour lacks a vertex");
      outer_ta[k] = mesh_.adj(4 * ta + m);
    }
    mesh_.destroy(t);
    mesh_.destroy(ta);
    std::uint32_t n[4];
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[k] = d;
      n[k] = mesh_.create(w[0], w[1], w[2], w[3]);
    }
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      mesh_.link(4 * n[k] + k, outer_t[k]);
      mesh_.link(4 * n[k] + i, outer_ta[k]);
      for (int l = k + 1; l < 4; ++l)
        if (l != i) mesh_.link(4 * n[k] + l, 4 * n[l] + k);
      stack_.push_back(n[k]);
    }
    last_ = n[(i + 1) & 3];
    ++stats_.flips23;
    return true;
  }

  // Flip 3-2 on the edge yz of T opposite p and x (positions i and x): the tets T,
  // Ta and N = (p,y,z,d) become M_y, M_z (T with y, resp. z, replaced by d). M_y's
  // facet at y's position is T's old one, its facet i is Ta's facet opposite y,
  // its facet x is N's facet opposite y, and its facet at z's position is M_z's
  // facet at y's position.
  bool flip32(std::uint32_t t, int i, int x, std::uint32_t ta, std::uint32_t third, std::uint32_t d) {
    std::uint32_t tv[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(t, k);
    int yz[2], q = 0;
    for (int k = 0; k < 4; ++k)
      if (k != i && k != x) yz[q++] = k;
    std::uint32_t outer_t[2], outer_ta[2], outer_n[2];
    for (int r = 0; r < 2; ++r) {
      const int k = yz[r];
      const int ma = mesh_.index_of(ta, tv[k]), mn = mesh_.index_of(third, tv[k]);
      if (ma < 0 || mn < 0) return fail(FailureKind::inconsistent_adjacency, "flip 3-2: neighbour lacks a vertex");
      outer_t[r] = mesh_.adj(4 * t + k);
      outer_ta[r] = mesh_.adj(4 * ta + ma);
      outer_n[r] = mesh_.adj(4 * third + mn);
    }
    mesh_.destroy(t);
    mesh_.destroy(ta);
    mesh_.destroy(third);
    std::uint32_t m[2];
    for (int r = 0; r < 2; ++r) {
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[yz[r]] = d;
      m[r] = mesh_.create(w[0], w[1], w[2], w[3]);
    }
    for (int r = 0; r < 2; ++r) {
      mesh_.link(4 * m[r] + yz[r], outer_t[r]);
      mesh_.link(4 * m[r] + i, outer_ta[r]);
      mesh_.link(4 * m[r] + x, outer_n[r]);
      stack_.push_back(m[r]);
    }
    mesh_.link(4 * m[0] + yz[1], 4 * m[1] + yz[0]);
    last_ = m[0];
    ++stats_.flips32;
    return true;
  }

  // p, d and the edge yz of T (opposite p and x) are coplanar. If yz has exactly the
  // four tets T, Ta, N2 = (y,z,d,e), N1 = (p,y,z,e), swap the octahedron's diagonal
  // yz for pd. Returns false only on a broken mesh; true also when it does nothing.
  bool flip44(std::uint32_t t, int i, int x, std::uint32_t ta, std::uint32_t d) {
    const std::uint32_t* tv = mesh_.verts(t);
    const std::uint32_t n1f = mesh_.adj(4 * t + x);
    const int xa = mesh_.index_of(ta, tv[x]);
    if (n1f == TetMesh::kNoFacet || xa < 0) return true;
    const std::uint32_t n2f = mesh_.adj(4 * ta + xa);
    if (n2f == TetMesh::kNoFacet) return true;
    const std::uint32_t n1 = n1f >> 2, n2 = n2f >> 2;
    const std::uint32_t e = mesh_.vertex(n1, n1f & 3);
    if (mesh_.vertex(n2, n2f & 3) != e) return true;
    const std::uint32_t* n1v = mesh_.verts(n1);
    std::array<std::uint32_t, 4> nt[4];
    int k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i && j != x) nt[k++] = swap_in(tv, j, d);
    for (int j = 0; j < 4; ++j)
      if (n1v[j] == tv[(i + 1) & 3] || n1v[j] == tv[(i + 2) & 3] || n1v[j] == tv[(i + 3) & 3])
        if (n1v[j] != tv[x]) nt[k++] = swap_in(n1v, j, d);
    if (k != 4) return true;
    if (orientation(nt[2].data()) <= 0 || orientation(nt[3].data()) <= 0) return true;
    const std::uint32_t old[4] = {t, ta, n2, n1};
    ++stats_.flips44;
    return replace(old, 4, nt, 4);
  }

  TetMesh mesh_;
  Geometry<B> geo_;
  std::uint64_t rng_;
  std::uint32_t last_ = 0;
  IdStack stack_;
  BuildStats stats_;
  FailureKind failure_ = FailureKind::walk_cycle;
  std::string detail_;
  std::uint32_t duplicate_of_ = 0;
};

}  // namespace dtlab
