#pragma once
// One thread's view of the shared tet records of a parallel build (kernel/shared_tets.hpp):
// the interface of TetMesh (kernel/tet_mesh.hpp), so that the one inserter runs on either,
// plus claims. kernel/README.md ("The parallel build") states the protocol; in short:
//
//   - a thread reads or writes a record only while it holds the tet: claim(t) takes it by
//     a compare-and-swap of its owner byte from 0, or throws ClaimConflict when another
//     thread holds it; link() claims the far tet it writes; tets it creates are its own;
//   - the first claim of a tet in an insertion saves its record; commit() releases every
//     live tet the insertion holds, rollback() restores the saved records, returns the
//     created slots to the pool and releases the rest (strict two-phase locking: an
//     insertion is all or nothing, and what it read cannot change before it ends);
//   - dead slots stay owned by the thread that freed them (its pool, reused by its later
//     insertions, never within the one that freed them), as do the fresh slots of its
//     current block, so no other thread can reach a dead or unwritten record;
//   - a walk that starts away from its hint probes only the slots handed out before the
//     pass began (attach()): a block taken during the pass is counted in the shared size
//     before its owner bytes are written, and its unwritten records must not be taken.
#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/id_stack.hpp"
#include "kernel/ids.hpp"
#include "kernel/shared_tets.hpp"

namespace dtlab {

// Another thread holds a tet this insertion needs, or (out_of_slots) the shared storage
// is full: the insertion is rolled back and retried later.
struct ClaimConflict {
  bool out_of_slots = false;
};

class ClaimedMesh {
 public:
  static constexpr bool kClaims = true;
  static constexpr std::uint32_t kBlock = 1024;  // fresh slots taken at a time

  ClaimedMesh(SharedTets& tets, std::uint8_t id) : shared_(&tets), me_(id) { attach(); }

  // Refreshes the storage's addresses (after it grew) and the slots a walk may start
  // at: those handed out so far, all written. Only while no thread uses the storage.
  void attach() {
    rec_ = shared_->records();
    own_ = shared_->owners();
    published_ = shared_->size();
  }

  std::uint32_t size() const { return shared_->size(); }
  std::uint32_t live() const { return shared_->size(); }  // for bounds only
  bool dead(std::uint32_t t) const { return rec(t).v[0] == kNone; }
  const std::uint32_t* verts(std::uint32_t t) const { return rec(t).v; }
  std::uint32_t vertex(std::uint32_t t, int i) const { return rec(t).v[i]; }
  std::uint32_t apex(Facet facet) const { return rec(facet.tet()).v[facet.face()]; }
  Facet adj(Facet facet) const { return rec(facet.tet()).adj[facet.face()]; }
  int index_of(std::uint32_t t, std::uint32_t v) const {
    const std::uint32_t* w = rec(t).v;
    return w[0] == v ? 0 : w[1] == v ? 1 : w[2] == v ? 2 : w[3] == v ? 3 : -1;
  }

  // f1 is a facet of a tet this thread holds; the tet of f2 is claimed before it is written.
  void link(Facet f1, Facet f2) {
    rec(f1.tet()).adj[f1.face()] = f2;
    if (!f2.none()) {
      claim(f2.tet());
      rec_[f2.tet()].adj[f2.face()] = f1;
    }
  }

  std::uint32_t create(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    std::uint32_t t;
    if (!pool_.empty()) {
      t = pool_.back();
      pool_.pop_back();
    } else {
      if (fresh_ == fresh_end_) {
        const std::uint32_t got = shared_->take(kBlock, me_, fresh_);
        if (got == 0) throw ClaimConflict{true};
        fresh_end_ = fresh_ + got;
      }
      t = fresh_++;
    }
    rec_[t] = TetRecord{{a, b, c, d}, {}};
    created_.push_back(t);
    return t;
  }

  void destroy(std::uint32_t t) {
    rec(t).v[0] = kNone;
    destroyed_.push_back(t);
  }

  // Takes tet t for this insertion (no-op when already held); throws ClaimConflict when
  // another thread holds it. Inline for the test of the usual case (a tet this insertion
  // holds or created: most calls come from link()); the compare-and-swap out of line.
  void claim(std::uint32_t t) {
    if (std::atomic_ref<std::uint8_t>(own_[t]).load(std::memory_order_relaxed) != me_) take(t);
  }

  // A live tet, claimed, to start a walk at: `hint` (a slot this thread wrote: a tet of
  // its last insertion) if it can be taken, else slots drawn from `random` among the
  // published ones (attach()), else the first takeable one from there on. Between
  // insertions a thread holds no live tet, so a slot it already owns is dead (its pool
  // or block): skipped.
  std::uint32_t walk_start(std::uint32_t hint, std::uint32_t random) {
    const std::uint32_t n = published_;
    if (try_take_live(hint)) return hint;
    if (n == 0) throw ClaimConflict{};
    for (int k = 0; k < 64; ++k) {
      random = random * 1664525u + 1013904223u;
      const std::uint32_t t = static_cast<std::uint32_t>((std::uint64_t(random) * n) >> 32);
      if (try_take_live(t)) return t;
    }
    for (std::uint32_t k = 0, t = random % n; k < n; ++k, t = t + 1 == n ? 0 : t + 1)
      if (try_take_live(t)) return t;
    throw ClaimConflict{};
  }

  // The insertion is complete (or failed by name): freed slots join the pool, every
  // other tet it holds is released.
  void commit() {
    for (const std::uint32_t t : destroyed_) pool_.push_back(t);
    // Without a branch (whether a tet died is unpredictable): a dead tet keeps its owner,
    // a live one gets 0. The addresses in locals: the byte stores may alias any member.
    TetRecord* const rec = rec_;
    std::uint8_t* const own = own_;
    const std::uint8_t me = me_;
    const auto settle = [&](std::uint32_t t) {
      const std::uint8_t keep = rec[t].v[0] == kNone ? me : 0;
      std::atomic_ref<std::uint8_t>(own[t]).store(keep, std::memory_order_release);
    };
    for (const std::uint32_t t : claimed_) settle(t);
    for (const std::uint32_t t : created_) settle(t);
    clear();
  }

  // Undoes the insertion: the claimed tets get their saved records back and are
  // released, the created ones go back to the pool.
  void rollback() {
    for (const std::uint32_t t : created_) {
      rec_[t].v[0] = kNone;
      pool_.push_back(t);
    }
    for (std::size_t k = claimed_.size(); k-- > 0;) {
      rec_[claimed_[k]] = saved_[k];
      release(claimed_[k]);
    }
    clear();
  }

  std::uint8_t id() const { return me_; }
  // The view uses the storage's current addresses (attach() ran since its last growth).
  bool attached() const { return rec_ == shared_->records() && own_ == shared_->owners(); }
  // No insertion in progress: the view holds no live tet.
  bool idle() const { return claimed_.empty() && created_.empty() && destroyed_.empty(); }
  // f(t) for each slot this view keeps for later tets: its pool and the rest of its block.
  template <class F>
  void for_each_spare(F&& f) const {
    for (const std::uint32_t t : pool_) f(t);
    for (std::uint32_t t = fresh_; t < fresh_end_; ++t) f(t);
  }

  // End of the build: the unused slots of the current block become dead records (the
  // compaction reads every slot handed out).
  void finish() {
    for (; fresh_ < fresh_end_; ++fresh_) rec_[fresh_].v[0] = kNone;
  }

 private:
  TetRecord& rec(std::uint32_t t) const {
    // Debug builds check the protocol on every access: the thread holds what it touches.
    assert(std::atomic_ref<std::uint8_t>(own_[t]).load(std::memory_order_relaxed) == me_);
    return rec_[t];
  }

  [[gnu::noinline]] void take(std::uint32_t t) {
    std::uint8_t free = 0;
    if (!std::atomic_ref<std::uint8_t>(own_[t]).compare_exchange_strong(free, me_, std::memory_order_acquire,
                                                                        std::memory_order_relaxed))
      throw ClaimConflict{};
    claimed_.push_back(t);
    saved_.push_back(rec_[t]);
  }

  bool try_take_live(std::uint32_t t) {
    std::atomic_ref<std::uint8_t> owner(own_[t]);
    std::uint8_t free = 0;
    if (owner.load(std::memory_order_relaxed) != 0 ||
        !owner.compare_exchange_strong(free, me_, std::memory_order_acquire, std::memory_order_relaxed))
      return false;
    if (rec_[t].v[0] == kNone) {  // never true while the protocol holds
      assert(!"a free published slot is dead");
      release(t);
      return false;
    }
    claimed_.push_back(t);
    saved_.push_back(rec_[t]);
    return true;
  }

  void release(std::uint32_t t) { std::atomic_ref<std::uint8_t>(own_[t]).store(0, std::memory_order_release); }

  void clear() {
    claimed_.clear();
    saved_.clear();
    created_.clear();
    destroyed_.clear();
  }

  SharedTets* shared_;
  TetRecord* rec_ = nullptr;
  std::uint8_t* own_ = nullptr;
  std::uint8_t me_;
  IdStack pool_;                             // dead slots this thread owns
  std::uint32_t fresh_ = 0, fresh_end_ = 0;  // the current block of fresh slots
  std::uint32_t published_ = 0;              // slots handed out before this pass
  IdStack claimed_, created_, destroyed_;    // this insertion's tets
  std::vector<TetRecord> saved_;             // claimed_[k]'s record before the insertion
};

// The protocol's state between passes (no thread running), for the debug builds' check
// after every pass and for tests: every view on the storage's current addresses; each
// slot handed out is either a spare slot (pool or unused block) of exactly one view,
// owned by it, or a live free tet whose neighbours are live and point back. "" or the
// first defect found. O(slots).
inline std::string ownership_defect(const SharedTets& store, std::span<const ClaimedMesh* const> views) {
  const std::uint32_t n = store.size();
  const TetRecord* rec = store.records();
  const std::uint8_t* own = store.owners();
  std::vector<std::uint8_t> spare(n, 0);
  std::string defect;
  const auto note = [&](std::uint32_t t, const char* what) {
    if (defect.empty()) defect = "slot " + std::to_string(t) + ": " + what;
  };
  for (const ClaimedMesh* v : views) {
    if (!v->idle()) note(0, "a view is inside an insertion");
    if (!v->attached()) note(0, "a view uses the storage's addresses from before it grew");
    v->for_each_spare([&](std::uint32_t t) {
      if (t >= n)
        note(t, "a spare slot beyond the slots handed out");
      else if (spare[t]++)
        note(t, "a spare slot kept twice");
      else if (own[t] != v->id())
        note(t, "a spare slot not owned by the view that keeps it");
    });
  }
  for (std::uint32_t t = 0; t < n && defect.empty(); ++t) {
    if (spare[t]) continue;
    if (own[t] != 0) note(t, "a tet held between insertions");
    if (rec[t].v[0] == kNone) note(t, "a dead slot in no pool");
    for (int f = 0; f < 4; ++f) {
      const Facet a = rec[t].adj[f];
      if (!a.none() && (a.tet() >= n || spare[a.tet()] || rec[a.tet()].adj[a.face()] != Facet(t, f)))
        note(t, "an adjacency that does not point back");
    }
  }
  return defect;
}

}  // namespace dtlab
