#pragma once
// The kernel's ids: 32-bit indices of points (vertices) and tets, and `Facet`, facet f
// of tet t (the one opposite its vertex f). One value means "none" for all three: no
// vertex (no infinite vertex with a bigtet), no tet, no facet (the outside of a bigtet),
// and it marks a dead tet's first vertex.
#include <cstdint>

namespace dtlab {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// Facet `face` of tet `tet`, packed as 4 tet + face in 32 bits, so an adjacency slot
// holds one and the mirror facet is known without a search. Default: no facet (kNone).
class Facet {
 public:
  constexpr Facet() = default;
  constexpr Facet(std::uint32_t tet, int face) : code_(4 * tet + static_cast<std::uint32_t>(face)) {}

  constexpr std::uint32_t tet() const { return code_ >> 2; }
  constexpr int face() const { return static_cast<int>(code_ & 3); }
  constexpr bool none() const { return code_ == kNone; }
  friend constexpr bool operator==(Facet, Facet) = default;

 private:
  std::uint32_t code_ = kNone;
};

inline constexpr Facet kNoFacet{};

}  // namespace dtlab
