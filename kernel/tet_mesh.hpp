#pragma once
// The tetrahedral mesh: one 32-byte record per tet, 32-bit ids (kernel/ids.hpp).
//
//   v[i]    vertex i of the tet (a point index; the infinite vertex is one index)
//   adj[f]  the facet across facet f, encoded 4t2 + f2, where facet f is the one
//           opposite vertex f; so adj(adj(4t+f)) == 4t+f and the mirror vertex is
//           vertex(adj(4t+f)). kNone marks the outside of a bigtet.
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
  std::uint32_t adj[4];
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
  // The vertex opposite facet `facet` (4t + f): vertex f of t.
  std::uint32_t apex(std::uint32_t facet) const { return tets_[facet >> 2].v[facet & 3]; }
  std::uint32_t adj(std::uint32_t facet) const { return tets_[facet >> 2].adj[facet & 3]; }

  void link(std::uint32_t f1, std::uint32_t f2) {
    tets_[f1 >> 2].adj[f1 & 3] = f2;
    if (f2 != kNone) tets_[f2 >> 2].adj[f2 & 3] = f1;
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
    tets_[t] = TetRecord{{a, b, c, d}, {kNone, kNone, kNone, kNone}};
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
