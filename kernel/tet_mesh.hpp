#pragma once
// The tetrahedral mesh: flat arrays, 32-bit ids, like HXT and Geogram.
//
//   tv_[4*t + i]   vertex i of tet t (a point index; the infinite vertex is one index)
//   adj_[4*t + f]  the facet across facet f of t, encoded 4*t2 + f2, where facet f is the
//                  one opposite vertex f; so adj_[adj_[4t+f]] == 4t+f and the mirror
//                  vertex is tv_[adj_[4t+f]]. kNoFacet marks the outside of a bigtet.
//
// Every live tet is positively oriented (orient3d > 0, Shewchuk's sign; for a tet with
// the infinite vertex see kernel/orientation.hpp). Dead tets have tv_[4t] == kDead and
// sit on a free list for reuse. 32 bytes per tet.
#include <cstdint>
#include <vector>

#include "kernel/id_stack.hpp"

namespace dtlab {

class TetMesh {
 public:
  static constexpr std::uint32_t kDead = 0xFFFFFFFFu;
  static constexpr std::uint32_t kNoFacet = 0xFFFFFFFFu;

  std::uint32_t size() const { return static_cast<std::uint32_t>(tv_.size() / 4); }
  std::uint32_t live() const { return size() - static_cast<std::uint32_t>(free_.size()); }
  bool dead(std::uint32_t t) const { return tv_[4 * t] == kDead; }

  std::uint32_t* verts(std::uint32_t t) { return &tv_[4 * t]; }
  const std::uint32_t* verts(std::uint32_t t) const { return &tv_[4 * t]; }
  std::uint32_t vertex(std::uint32_t t, int i) const { return tv_[4 * t + i]; }
  std::uint32_t adj(std::uint32_t facet) const { return adj_[facet]; }

  void link(std::uint32_t f1, std::uint32_t f2) {
    adj_[f1] = f2;
    if (f2 != kNoFacet) adj_[f2] = f1;
  }

  std::uint32_t create(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    std::uint32_t t;
    if (!free_.empty()) {
      t = free_.back();
      free_.pop_back();
    } else {
      t = size();
      tv_.resize(tv_.size() + 4);
      adj_.resize(adj_.size() + 4, kNoFacet);
    }
    std::uint32_t* v = &tv_[4 * t];
    v[0] = a, v[1] = b, v[2] = c, v[3] = d;
    adj_[4 * t] = adj_[4 * t + 1] = adj_[4 * t + 2] = adj_[4 * t + 3] = kNoFacet;
    return t;
  }

  void destroy(std::uint32_t t) {
    tv_[4 * t] = kDead;
    free_.push_back(t);
  }

  int index_of(std::uint32_t t, std::uint32_t v) const {
    const std::uint32_t* w = &tv_[4 * t];
    return w[0] == v ? 0 : w[1] == v ? 1 : w[2] == v ? 2 : w[3] == v ? 3 : -1;
  }

  void reserve(std::size_t tets) {
    tv_.reserve(4 * tets);
    adj_.reserve(4 * tets);
  }
  // Frees the adjacency arrays (the mesh cannot be changed afterwards).
  void release_adjacency() { std::vector<std::uint32_t>().swap(adj_); }

  std::size_t bytes() const {
    return (tv_.capacity() + adj_.capacity() + free_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  std::vector<std::uint32_t> tv_;
  std::vector<std::uint32_t> adj_;
  IdStack free_;
};

}  // namespace dtlab
