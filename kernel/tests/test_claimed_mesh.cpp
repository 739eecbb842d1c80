// The claim protocol of the parallel build (kernel/claimed_mesh.hpp) on hand-made
// states: where a walk may start, and the between-pass check that debug builds run.
#include <catch2/catch.hpp>

#include <vector>

#include "kernel/claimed_mesh.hpp"
#include "kernel/shared_tets.hpp"

using namespace dtlab;

namespace {

// Five live tets made and committed by view `a` (slots 0-4; the rest of a's block,
// 5-1023, stays a's spare slots). They share no facet: adjacency all kNoFacet.
void five_live_tets(ClaimedMesh& a) {
  for (std::uint32_t k = 0; k < 5; ++k) a.create(4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3);
  a.commit();
}

}  // namespace

TEST_CASE("claimed mesh: a walk starts only at slots handed out before the pass", "[threads]") {
  SharedTets store(1 << 13);
  ClaimedMesh a(store, 1);
  five_live_tets(a);
  ClaimedMesh b(store, 2);  // attached now: slots 0-1023 are published to it
  // Another thread takes a block during the pass: the shared size counts it before its
  // owner bytes are written. What a probe sees in that window: free slots whose records
  // look like live tets.
  std::uint32_t first = 0;
  REQUIRE(store.take(ClaimedMesh::kBlock, 3, first) == ClaimedMesh::kBlock);
  for (std::uint32_t t = first; t < first + ClaimedMesh::kBlock; ++t) {
    store.owners()[t] = 0;
    store.records()[t] = TetRecord{{0, 1, 2, 3}, {kNoFacet, kNoFacet, kNoFacet, kNoFacet}};
  }
  for (std::uint32_t seed = 0; seed < 200; ++seed) {
    INFO("seed " << seed);
    const std::uint32_t t = b.walk_start(7, seed);  // the hint is a spare slot of a: probes
    CHECK(t < 5);
    b.rollback();
  }
}

TEST_CASE("claimed mesh: the between-pass check finds broken ownership", "[threads]") {
  SharedTets store(1 << 12);
  ClaimedMesh a(store, 1), b(store, 2);
  five_live_tets(a);
  b.create(0, 1, 2, 3);  // b's block: slots 1024-2047, tet 1024 live
  b.commit();
  const std::vector<const ClaimedMesh*> views = {&a, &b};
  REQUIRE(ownership_defect(store, views) == "");
  SECTION("a spare slot lost its owner") {
    store.owners()[600] = 0;
    CHECK(ownership_defect(store, views) == "slot 600: a spare slot not owned by the view that keeps it");
  }
  SECTION("a live tet still held") {
    store.owners()[3] = 2;
    CHECK(ownership_defect(store, views) == "slot 3: a tet held between insertions");
  }
  SECTION("a one-way adjacency") {
    store.records()[2].adj[1] = Facet(1024, 3);
    CHECK(ownership_defect(store, views) == "slot 2: an adjacency that does not point back");
  }
  SECTION("a view left on the addresses from before a growth") {
    store.grow(1 << 24);  // the 4 KiB of owner bytes move to a new block
    a.attach();           // b is not told
    CHECK(ownership_defect(store, views) == "slot 0: a view uses the storage's addresses from before it grew");
    b.attach();
    CHECK(ownership_defect(store, views) == "");
  }
  SECTION("an insertion in progress") {
    a.claim(4);
    CHECK(ownership_defect(store, views) == "slot 0: a view is inside an insertion");
    a.rollback();
  }
}
