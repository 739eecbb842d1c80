#pragma once
// The tetrahedral mesh: one 32-byte record per tet, 32-bit ids (kernel/ids.hpp).
//
//   v[i]    vertex i of the tet (a point index; the infinite vertex is one index)
//   adj[f]  the facet across facet f (a Facet, kernel/ids.hpp), where facet f is the
//           one opposite vertex f; so adj(adj(Facet{t,f})) == Facet{t,f} and the mirror
//           vertex is apex(adj(Facet{t,f})). kNoFacet marks the outside of a bigtet.
//
// Vertices and adjacency share the record, so a flip or a walk step touching a tet
// reads one half cache line instead of two lines in separate arrays (measured in
// kernel/README.md). Every live tet is positively oriented (orient3d > 0, Shewchuk's
// sign; for a tet with the infinite vertex see kernel/geometry.hpp). A dead tet has
// v[0] == kNone and sits on a free list for reuse.
#include <cstdint>
#include <vector>

#include "kernel/id_stack.hpp"
#include "kernel/ids.hpp"

namespace dtlab {

struct TetRecord {
  std::uint32_t v[4];
  Facet adj[4];
};
static_assert(sizeof(TetRecord) == 32);

class TetMesh {
 public:
  // The serial mesh: nothing to claim (kernel/claimed_mesh.hpp is the parallel build's view).
  static constexpr bool kClaims = false;
  void claim(std::uint32_t) const {}
  // Where a walk starts: `hint`, or the first live tet when it died.
  std::uint32_t walk_start(std::uint32_t hint, std::uint32_t) const {
    std::uint32_t t = hint;
    if (dead(t))
      for (t = 0; dead(t); ++t) {}
    return t;
  }

  std::uint32_t size() const { return static_cast<std::uint32_t>(tets_.size()); }
  std::uint32_t live() const { return size() - static_cast<std::uint32_t>(free_.size()); }
  bool dead(std::uint32_t t) const { return tets_[t].v[0] == kNone; }

  const std::uint32_t* verts(std::uint32_t t) const { return tets_[t].v; }
  std::uint32_t vertex(std::uint32_t t, int i) const { return tets_[t].v[i]; }
  // The vertex opposite facet `facet`: vertex facet.face() of facet.tet().
  std::uint32_t apex(Facet facet) const { return tets_[facet.tet()].v[facet.face()]; }
  Facet adj(Facet facet) const { return tets_[facet.tet()].adj[facet.face()]; }

  void link(Facet f1, Facet f2) {
    tets_[f1.tet()].adj[f1.face()] = f2;
    if (!f2.none()) tets_[f2.tet()].adj[f2.face()] = f1;
  }

  std::uint32_t create(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    std::uint32_t t;
    if (!free_.empty()) {
      t = free_.back();
      free_.pop_back();
    } else {
      t = size();
      tets_.emplace_back();
    }
    tets_[t] = TetRecord{{a, b, c, d}, {}};
    return t;
  }

  void destroy(std::uint32_t t) {
    tets_[t].v[0] = kNone;
    free_.push_back(t);
  }

  int index_of(std::uint32_t t, std::uint32_t v) const {
    const std::uint32_t* w = tets_[t].v;
    return w[0] == v ? 0 : w[1] == v ? 1 : w[2] == v ? 2 : w[3] == v ? 3 : -1;
  }

  void reserve(std::size_t tets) { tets_.reserve(tets); }

  // The records, for the final compaction (detail::compact in build_impl.hpp),
  // which releases them page by page as it reads them.
  std::vector<TetRecord>& records() { return tets_; }

 private:
  std::vector<TetRecord> tets_;
  IdStack free_;
};

}  // namespace dtlab
