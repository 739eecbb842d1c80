#pragma once
// The one flip-based incremental inserter (Edelsbrunner & Shah 1996, as explained by
// Ledoux 2007 and implemented in the thesis), templated on the predicate backend.
//
// insert(p): walk to the tet containing p, split it (flip 1-4), then repeat on a
// stack of facets opposite p: take T = (p,a,b,c), its neighbour Ta = (a,b,c,d)
// across the facet abc; if p is inside Ta's circumsphere, flip. Which flip depends
// on where the segment pd meets the plane of abc; we read it off the orientations
// s_x of T with x replaced by d, for x in {a,b,c} (the three tets a flip 2-3 would
// create):
//
//   case 1: all s_x > 0            pd crosses triangle abc      -> flip 2-3
//   case 2: one s_x < 0 or = 0,    pd passes outside edge yz    -> flip 3-2 on yz
//           and the tet N = pyzd   (x is the third vertex)
//           exists
//   case 3: one s_x = 0, T not     pd crosses edge yz; edge yz  -> flip 4-4
//           flat, no N             has 4 tets: T, Ta, (y,z,d,e), (p,y,z,e)
//   case 4: one s_x = 0, T flat,   p lies on edge yz            -> flip 2-3 (another
//           no N                                                  flat tet appears and
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
// The 1-4, 2-3, 3-2 and 4-4 flips are written out with their adjacency (one function
// each, with its contract; the 4-4 is degenerate but frequent on lattices). The
// orientations s_x mostly come for free: the insphere evaluation of Ta against p forms
// them as its minors, and a backend with a fused
// filter (predicates/adaptive.hpp) returns the signs its semi-static bound decides.
// Flips and walks are bounded; a non-robust backend that would loop forever stops
// with a named failure instead.
#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>

#include "kernel/build.hpp"
#include "kernel/claimed_mesh.hpp"
#include "kernel/facet_key.hpp"
#include "kernel/geometry.hpp"
#include "kernel/id_stack.hpp"
#include "kernel/ids.hpp"
#include "kernel/mesh_check.hpp"
#include "kernel/tet_mesh.hpp"

namespace dtlab {

// Mesh: TetMesh (the serial build) or ClaimedMesh (one thread of the parallel build,
// kernel/claimed_mesh.hpp). The flip code is the same; it calls mesh_.claim(t) before it
// first reads a tet that it reached by adjacency and that it did not create in this
// insertion (a no-op on TetMesh); every other tet it reads is one it created or one whose
// adjacency it wrote (ClaimedMesh::link claims the far tet). With ClaimedMesh an insertion
// that meets another thread's tet is rolled back whole (Outcome::conflict).
template <PredicateBackend B, class Mesh = TetMesh>
class Inserter {
 public:
  // conflict: another thread held a tet (ClaimedMesh only; nothing changed, retry later).
  // no_room: the shared storage is full (ClaimedMesh only; nothing changed, grow and retry).
  enum class Outcome { inserted, duplicate, failed, conflict, no_room };

  // points: indexed by vertex id; inf the infinite vertex's id, or kNone (bigtet).
  Inserter(const Point3* points, const B& pred, std::uint32_t inf, std::uint64_t seed, Mesh mesh = Mesh{})
      : mesh_(std::move(mesh)), geo_(points, pred, inf), rng_(seed * 0x9E3779B97F4A7C15ull + 1) {}

  // The first tet (positively oriented) and, with an infinite vertex, the four
  // infinite tets on its facets: the one on facet f is the first tet with vertex f
  // replaced by inf, and two others swapped (inf lies across facet f, so the
  // orientation flips).
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    const std::uint32_t t0 = mesh_.create(a, b, c, d);
    last_ = t0;
    geo_.set_first_tet(a, b, c, d);
    if (geo_.infinite() != kNone) add_infinite_tets(t0);
    if constexpr (Mesh::kClaims) mesh_.commit();
  }

  // Inserts vertex p. On Outcome::duplicate, found() is the vertex equal to p.
  Outcome insert(std::uint32_t p) {
    if constexpr (Mesh::kClaims) {
      const std::uint32_t last = last_;
      try {
        const Outcome o = insert_unclaimed(p);
        mesh_.commit();  // also after a named failure: the mesh stays as it stands
        return o;
      } catch (const ClaimConflict& c) {
        mesh_.rollback();
        stack_.clear();
        last_ = last;
        return c.out_of_slots ? Outcome::no_room : Outcome::conflict;
      }
    } else {
      return insert_unclaimed(p);
    }
  }

  std::uint32_t found() const { return found_; }
  Mesh& mesh() { return mesh_; }
  Geometry<B>& geometry() { return geo_; }
  BuildStats& stats() { return stats_; }
  FailureKind failure() const { return failure_; }
  const std::string& failure_detail() const { return detail_; }
  // Debug builds: check_combinatorics (kernel/mesh_check.hpp) after every flip and every
  // insertion when `on` or DTLAB_CHECK_COMBINATORICS=1 (serial mesh only; `points`: the
  // number of point ids). Release builds compile the checks out and ignore this.
  void check_combinatorics(bool on, std::size_t points) {
    if (!on) on = std::getenv("DTLAB_CHECK_COMBINATORICS") && *std::getenv("DTLAB_CHECK_COMBINATORICS") == '1';
    check_points_ = on && kMeshChecksCompiled && !Mesh::kClaims ? static_cast<std::uint32_t>(points) : 0;
  }
  void reserve(std::size_t points) {
    if constexpr (!Mesh::kClaims) mesh_.reserve(7 * points + 64);
    stack_.reserve(1024);
  }

 private:
  // The four infinite tets on the facets of the first tet t0 = (a,b,c,d).
  void add_infinite_tets(std::uint32_t t0) {
    const std::uint32_t a = mesh_.vertex(t0, 0), b = mesh_.vertex(t0, 1), c = mesh_.vertex(t0, 2),
                        d = mesh_.vertex(t0, 3);
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
              mesh_.link(Facet(tets[i], f), Facet(tets[j], g));
  }

  Outcome insert_unclaimed(std::uint32_t p) {
    std::uint32_t t;
    bool on_boundary = false;
    if (!locate(p, t, on_boundary)) return Outcome::failed;
    const std::uint32_t* v = mesh_.verts(t);
    for (int i = 0; i < 4; ++i)
      if (v[i] != geo_.infinite() && geo_.point(v[i]) == geo_.point(p)) {
        found_ = v[i];
        return Outcome::duplicate;
      }
    flip14(t, p);
    if (!checked("flip 1-4") || !restore_delaunay(p, !on_boundary) || !checked("the insertion", true))
      return Outcome::failed;
    ++stats_.inserted;
    return Outcome::inserted;
  }

  // The mesh check after a flip or insertion (check_combinatorics above): a broken
  // invariant fails the build as inconsistent-adjacency, naming it. All tets positive
  // only after an insertion: a flip may leave flat tets that later flips remove.
  bool checked(const char* after, bool all_positive = false) {
    if constexpr (kMeshChecksCompiled && !Mesh::kClaims) {
      if (check_points_ == 0) return true;
      ++stats_.mesh_checks;
      const std::uint64_t calls = geo_.orient_calls;  // the check's calls are not the build's
      const std::string e = dtlab::check_combinatorics(mesh_, geo_, check_points_, all_positive);
      geo_.orient_calls = calls;
      if (!e.empty())
        return fail(FailureKind::inconsistent_adjacency, std::string("check_combinatorics after ") + after + ": " + e);
    }
    return true;
  }

  std::uint32_t next_random() {
    rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;
    return static_cast<std::uint32_t>(rng_ >> 32);
  }

  bool fail(FailureKind k, std::string detail) {
    failure_ = k;
    detail_ = std::move(detail);
    return false;
  }

  // Visibility walk from the last tet touched: leave each tet through a facet whose
  // plane separates it from p, trying the facets in random order; stop in a tet
  // whose closure holds p (on_boundary: p on one of its facets, edges or vertices).
  // Infinite tets take part as the cones from O beyond their hull facets (see
  // geometry.hpp), so the tets tile space and the walk can always go on.
  // Termination: with exact signs a visibility walk on a Delaunay triangulation
  // cannot cycle even in a fixed facet order (the in-front-of relation of a regular
  // triangulation is acyclic, Edelsbrunner 1990), and on any triangulation the random
  // order ends it with probability 1 (Devillers, Pion & Teillaud 2002). The mesh
  // between insertions is Delaunay only among finite tets, and a non-robust backend
  // voids both arguments, so the walk is also bounded: walk-cycle after
  // 1000 + 2 tets steps.
  bool locate(std::uint32_t p, std::uint32_t& out, bool& on_boundary) {
    std::uint32_t t = mesh_.walk_start(last_, Mesh::kClaims ? next_random() : 0);
    Facet entry = kNoFacet;
    const std::uint64_t max_steps = 1000 + 2 * std::uint64_t(mesh_.live());
    for (std::uint64_t step = 0; step < max_steps; ++step) {
      const std::uint32_t r = next_random();
      bool moved = false;
      on_boundary = false;
      const std::uint32_t* v = mesh_.verts(t);
      for (int k = 0; k < 4 && !moved; ++k) {
        const int f = (r + k) & 3;
        if (Facet(t, f) == entry) continue;
        std::uint32_t w[4] = {v[0], v[1], v[2], v[3]};
        w[f] = p;
        const Sign s = geo_.orientation(w);
        on_boundary |= s == Sign::zero;
        if (s == Sign::negative) {
          const Facet nb = mesh_.adj(Facet(t, f));
          if (nb.none()) return fail(FailureKind::outside_boundary, "point lies outside the enclosing tetrahedron");
          entry = nb;
          t = nb.tet();
          mesh_.claim(t);
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

  // The roles of one flip decision, named as in the header's diagrams: T = (p,a,b,c)
  // is tet t with p at position i; Ta = (a,b,c,d) is tet ta across T's facet i, with
  // d at position ja; in_ta[j] is the position in Ta of T's vertex j (j != i), and
  // side[j] the orientation s_x of T with its vertex x = T[j] replaced by d
  // (FilterSign::undecided until known).
  struct Roles {
    std::uint32_t t;
    int i;
    std::uint32_t ta;
    int ja;
    std::uint32_t d;
    int in_ta[4];
    FilterSign side[4];
  };

  // s_x, from the fused filter's answer or asked now. T with x replaced by d and Ta
  // with x replaced by p are the same four points in orders of equal parity (T and Ta
  // induce opposite orientations on their common facet), so the filter's signs for Ta
  // are T's too.
  Sign side(Roles& r, int j) {
    if (!decided(r.side[j])) {
      std::uint32_t w[4] = {mesh_.vertex(r.t, 0), mesh_.vertex(r.t, 1), mesh_.vertex(r.t, 2), mesh_.vertex(r.t, 3)};
      w[j] = r.d;
      r.side[j] = to_filter_sign(geo_.orientation(w));
    }
    return to_sign(r.side[j]);
  }

  // The tet N = (p,y,z,d) on T's facet j (opposite x = T[j]), if it exists.
  std::uint32_t third_tet(const Roles& r, int j) const {
    const Facet f = mesh_.adj(Facet(r.t, j));
    return !f.none() && mesh_.apex(f) == r.d ? f.tet() : kNone;
  }

  // Pops facets opposite p until the stack is empty: every facet opposite p is then
  // locally Delaunay. `clean`: p was strictly inside a tet, so every tet stays
  // positively oriented until some side() returns 0. In a clean state an edge yz of
  // abc with the three tets T, Ta and N = (p,y,z,d) pierces the triangle of its link,
  // so the flip 3-2 is valid without a test, and no other flip can be (the five points
  // span one 4-simplex; a valid mesh holds one side of its boundary): when the fused
  // filter left sides undecided, that combinatorial test comes first and saves them.
  bool restore_delaunay(std::uint32_t p, bool clean) {
    const std::uint64_t max_flips = 1000 + 8 * std::uint64_t(mesh_.live());
    std::uint64_t flips = 0;
    while (!stack_.empty()) {
      const Facet facet = stack_.back();
      stack_.pop_back();
      Roles r;
      r.t = facet.tet(), r.i = facet.face();
      if (mesh_.dead(r.t) || mesh_.vertex(r.t, r.i) != p) continue;  // gone, or its slot reused
      const Facet across = mesh_.adj(facet);
      if (across.none()) continue;  // the outside of a bigtet
      r.ta = across.tet(), r.ja = across.face();
      mesh_.claim(r.ta);
      FilterSign ta_side[4];
      if (!geo_.conflict(mesh_.verts(r.ta), p, ta_side)) continue;
      if (++flips > max_flips)
        return fail(FailureKind::flip_stuck, "more than " + std::to_string(max_flips) + " flips");
      r.d = mesh_.vertex(r.ta, r.ja);
      bool undecided = false;
      for (int j = 0; j < 4; ++j) {
        if (j == r.i) continue;
        r.in_ta[j] = mesh_.index_of(r.ta, mesh_.vertex(r.t, j));
        if (r.in_ta[j] < 0) return fail(FailureKind::inconsistent_adjacency, "neighbour lacks a vertex of the facet");
        r.side[j] = ta_side[r.in_ta[j]];
        undecided |= !decided(r.side[j]);
      }
      if (!flip_case(r, p, clean && undecided, clean)) return false;
    }
    return true;
  }

  // The case analysis of the header for T and Ta in conflict; does the flip it finds.
  bool flip_case(Roles& r, std::uint32_t p, bool combinatorial_first, bool& clean) {
    if (combinatorial_first)
      for (int j = 0; j < 4; ++j)
        if (j != r.i)
          if (const std::uint32_t n = third_tet(r, j); n != kNone) return flip32(r, j, n);
    int neg = 0, zero = 0, x = -1;
    for (int j = 0; j < 4 && neg + zero < 2; ++j) {
      if (j == r.i) continue;
      const Sign s = side(r, j);
      if (s == Sign::negative) ++neg, x = j;
      if (s == Sign::zero) ++zero, x = j;
    }
    if (zero) clean = false;
    if (neg == 0 && zero == 0) return flip23(r);                                  // case 1
    if (neg + zero != 1) return true;                                             // none now
    if (const std::uint32_t n = third_tet(r, x); n != kNone) return flip32(r, x, n);  // case 2
    if (zero == 0) return true;                                                   // none now
    if (geo_.orientation(mesh_.verts(r.t)) == Sign::zero) return flip23(r);       // case 4
    return flip44(r, x, p);                                                       // case 3
  }

  // Flip 1-4: tet t, whose closure holds p, becomes N_k = t with vertex k replaced by
  // p (k = 0..3). N_k's facet k is t's old facet k; its facet l (l != k) is N_l's facet
  // k. Pushes the four facets opposite p.
  void flip14(std::uint32_t t, std::uint32_t p) {
    std::uint32_t tv[4], n[4];
    Facet outer[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(t, k), outer[k] = mesh_.adj(Facet(t, k));
    mesh_.destroy(t);
    for (int k = 0; k < 4; ++k) {
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[k] = p;
      n[k] = mesh_.create(w[0], w[1], w[2], w[3]);
    }
    for (int k = 0; k < 4; ++k) {
      mesh_.link(Facet(n[k], k), outer[k]);
      for (int l = k + 1; l < 4; ++l) mesh_.link(Facet(n[k], l), Facet(n[l], k));
      stack_.push_back(Facet(n[k], k));
    }
    last_ = n[0];
    ++stats_.flips14;
  }

  // Flip 2-3 (cases 1 and 4): T and Ta become N_k = T with its vertex x = T[k]
  // replaced by d, for k != i. N_k's facet k is T's old facet k, its facet i is Ta's
  // old facet opposite x, and its facet l (l != i, k) is N_l's facet k. Pushes the
  // three facets opposite p.
  bool flip23(const Roles& r) {
    const int i = r.i;
    std::uint32_t tv[4];
    Facet outer_t[4], outer_ta[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(r.t, k), outer_t[k] = mesh_.adj(Facet(r.t, k));
    for (int k = 0; k < 4; ++k)
      if (k != i) outer_ta[k] = mesh_.adj(Facet(r.ta, r.in_ta[k]));
    mesh_.destroy(r.t);
    mesh_.destroy(r.ta);
    std::uint32_t n[4];
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[k] = r.d;
      n[k] = mesh_.create(w[0], w[1], w[2], w[3]);
    }
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      mesh_.link(Facet(n[k], k), outer_t[k]);
      mesh_.link(Facet(n[k], i), outer_ta[k]);
      for (int l = k + 1; l < 4; ++l)
        if (l != i) mesh_.link(Facet(n[k], l), Facet(n[l], k));
      stack_.push_back(Facet(n[k], i));
    }
    last_ = n[(i + 1) & 3];
    ++stats_.flips23;
    return checked("flip 2-3");
  }

  // Flip 3-2 (case 2) on the edge yz of T opposite p and x = T[x_pos]: T, Ta and
  // N = (p,y,z,d) (tet n, across T's facet x_pos) become M_y, M_z (T with y, resp. z,
  // replaced by d). M_y's facet at y's position is T's old one, its facet i is Ta's
  // facet opposite y, its facet x_pos is N's facet opposite y, and its facet at z's
  // position is M_z's facet at y's position. Pushes the two facets opposite p.
  bool flip32(const Roles& r, int x_pos, std::uint32_t n) {
    const int i = r.i;
    std::uint32_t tv[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(r.t, k);
    int yz[2], q = 0;
    for (int k = 0; k < 4; ++k)
      if (k != i && k != x_pos) yz[q++] = k;
    Facet outer_t[2], outer_ta[2], outer_n[2];
    for (int m = 0; m < 2; ++m) {
      const int k = yz[m];
      const int in_n = mesh_.index_of(n, tv[k]);
      if (in_n < 0) return fail(FailureKind::inconsistent_adjacency, "flip 3-2: neighbour lacks a vertex");
      outer_t[m] = mesh_.adj(Facet(r.t, k));
      outer_ta[m] = mesh_.adj(Facet(r.ta, r.in_ta[k]));
      outer_n[m] = mesh_.adj(Facet(n, in_n));
    }
    mesh_.destroy(r.t);
    mesh_.destroy(r.ta);
    mesh_.destroy(n);
    std::uint32_t made[2];
    for (int m = 0; m < 2; ++m) {
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[yz[m]] = r.d;
      made[m] = mesh_.create(w[0], w[1], w[2], w[3]);
    }
    for (int m = 0; m < 2; ++m) {
      mesh_.link(Facet(made[m], yz[m]), outer_t[m]);
      mesh_.link(Facet(made[m], i), outer_ta[m]);
      mesh_.link(Facet(made[m], x_pos), outer_n[m]);
      stack_.push_back(Facet(made[m], i));
    }
    mesh_.link(Facet(made[0], yz[1]), Facet(made[1], yz[0]));
    last_ = made[0];
    ++stats_.flips32;
    return checked("flip 3-2");
  }

  // Flip 4-4 (case 3): p, d and the edge yz of T (opposite p and x = T[x_pos]) are
  // coplanar, T is not flat. If yz has exactly the four tets T, Ta, N2 = (y,z,d,e),
  // N1 = (p,y,z,e) and the two new tets on N1's side are positive, the octahedron's
  // diagonal yz is swapped for pd. Otherwise does nothing (a later flip removes T).
  // Returns false only on a broken mesh. Pushes the new facets opposite p.
  //
  //            x                         x
  //          /   \                     / | \        before: 4 tets around yz
  //   T, Ta /     \             MT_z  /  |  \  MT_y
  //        /       \                 /   |   \      after: 4 tets around pd
  //       y---------z      ->       y---p,d---z     (seen along pd, p in front;
  //        \       /                 \   |   /       y, z, p, d coplanar)
  //   N1,N2 \     /             MN_z  \  |  /  MN_y
  //          \   /                     \ | /
  //            e                         e
  //
  // MT_y, MT_z: T with y, resp. z, replaced by d; MN_y, MN_z: N1 likewise. MT_y's facet
  // opposite d is T's old facet opposite y, opposite p Ta's facet opposite y, opposite x
  // MN_y's facet opposite e, opposite z MT_z's facet opposite y; MN_y's facet opposite
  // d is N1's old facet opposite y, opposite p N2's facet opposite y, opposite z MN_z's
  // facet opposite y (and the same with y and z swapped).
  bool flip44(const Roles& r, int x_pos, std::uint32_t p) {
    const Facet n1f = mesh_.adj(Facet(r.t, x_pos));
    if (n1f.none()) return true;
    const Facet n2f = mesh_.adj(Facet(r.ta, r.in_ta[x_pos]));
    if (n2f.none()) return true;
    const std::uint32_t n1 = n1f.tet(), n2 = n2f.tet();
    mesh_.claim(n2);
    const std::uint32_t e = mesh_.apex(n1f);
    if (mesh_.apex(n2f) != e) return true;
    std::uint32_t tv[4], nv[4];
    for (int k = 0; k < 4; ++k) tv[k] = mesh_.vertex(r.t, k), nv[k] = mesh_.vertex(n1, k);
    int s[2], q = 0;  // T's slots of y and z
    for (int k = 0; k < 4; ++k)
      if (k != r.i && k != x_pos) s[q++] = k;
    int n1s[2], n2s[2];  // N1's and N2's slots of y and z
    for (int m = 0; m < 2; ++m) {
      n1s[m] = mesh_.index_of(n1, tv[s[m]]);
      n2s[m] = mesh_.index_of(n2, tv[s[m]]);
      if (n1s[m] < 0 || n2s[m] < 0) return fail(FailureKind::inconsistent_adjacency, "flip 4-4: a tet lacks y or z");
    }
    const int n1p = mesh_.index_of(n1, p), n1e = n1f.face();
    if (n1p < 0) return fail(FailureKind::inconsistent_adjacency, "flip 4-4: N1 lacks p");
    // In a simplicial complex e is not x, N2 holds d, N1 and N2 share their facet yze,
    // and no outer facet of the four tets leads back into them; a mesh that a
    // non-robust backend has tangled can break each.
    const Facet n12 = mesh_.adj(Facet(n1, n1p));  // N1's facet yze: N2's, closing the ring
    if (e == tv[x_pos] || mesh_.index_of(n2, r.d) < 0 || n12.none() || n12.tet() != n2 ||
        mesh_.adj(n12) != Facet(n1, n1p))
      return fail(FailureKind::inconsistent_adjacency, "flip 4-4: facets did not match up");
    std::uint32_t mn_v[2][4];
    for (int m = 0; m < 2; ++m) {
      std::copy(nv, nv + 4, mn_v[m]);
      mn_v[m][n1s[m]] = r.d;
    }
    if (geo_.orientation(mn_v[0]) != Sign::positive || geo_.orientation(mn_v[1]) != Sign::positive) return true;
    Facet outer_t[2], outer_ta[2], outer_n1[2], outer_n2[2];
    for (int m = 0; m < 2; ++m) {
      outer_t[m] = mesh_.adj(Facet(r.t, s[m]));
      outer_ta[m] = mesh_.adj(Facet(r.ta, r.in_ta[s[m]]));
      outer_n1[m] = mesh_.adj(Facet(n1, n1s[m]));
      outer_n2[m] = mesh_.adj(Facet(n2, n2s[m]));
      for (const Facet f : {outer_t[m], outer_ta[m], outer_n1[m], outer_n2[m]})
        if (!f.none() && (f.tet() == r.t || f.tet() == r.ta || f.tet() == n1 || f.tet() == n2))
          return fail(FailureKind::inconsistent_adjacency, "flip 4-4: facets did not match up");
    }
    mesh_.destroy(r.t);
    mesh_.destroy(r.ta);
    mesh_.destroy(n1);
    mesh_.destroy(n2);
    std::uint32_t mt[2], mn[2];
    for (int m = 0; m < 2; ++m) {
      std::uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
      w[s[m]] = r.d;
      mt[m] = mesh_.create(w[0], w[1], w[2], w[3]);
      mn[m] = mesh_.create(mn_v[m][0], mn_v[m][1], mn_v[m][2], mn_v[m][3]);
    }
    for (int m = 0; m < 2; ++m) {
      mesh_.link(Facet(mt[m], s[m]), outer_t[m]);
      mesh_.link(Facet(mt[m], r.i), outer_ta[m]);
      mesh_.link(Facet(mt[m], x_pos), Facet(mn[m], n1e));
      mesh_.link(Facet(mn[m], n1s[m]), outer_n1[m]);
      mesh_.link(Facet(mn[m], n1p), outer_n2[m]);
    }
    for (int m = 0; m < 2; ++m) stack_.push_back(Facet(mt[m], r.i));
    for (int m = 0; m < 2; ++m) stack_.push_back(Facet(mn[m], n1p));
    mesh_.link(Facet(mt[0], s[1]), Facet(mt[1], s[0]));
    mesh_.link(Facet(mn[0], n1s[1]), Facet(mn[1], n1s[0]));
    last_ = mt[0];
    ++stats_.flips44;
    return checked("flip 4-4");
  }

  Mesh mesh_;
  Geometry<B> geo_;
  std::uint64_t rng_;
  std::uint32_t last_ = 0;
  FacetStack stack_;  // facets (t, i) with p at position i of t
  BuildStats stats_;
  FailureKind failure_ = FailureKind::walk_cycle;
  std::string detail_;
  std::uint32_t found_ = kNone;
  std::uint32_t check_points_ = 0;  // 0: no mesh checks (check_combinatorics)
};

}  // namespace dtlab
