#pragma once
// The tet records of a parallel build, shared by its threads: the 32-byte records of
// kernel/tet_mesh.hpp, one owner byte per slot (0: free, else the id of the thread that
// holds it), and a counter of the slots handed out. Threads take fresh slots in blocks;
// the storage grows only between passes, when no thread runs (kernel/parallel_build.hpp).
//
// Both arrays are malloc'd and never initialised ahead of use: pages the build does not
// reach are never resident, and growth is a realloc (an mremap for large blocks: no copy,
// no second buffer at the peak).
#include <atomic>
#include <cassert>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>

#include "kernel/tet_mesh.hpp"

namespace dtlab {

class SharedTets {
 public:
  // Facet ids 4t + f are 32-bit: at most 2^30 slots.
  static constexpr std::size_t kMaxSlots = std::size_t(1) << 30;

  explicit SharedTets(std::size_t capacity) { grow(capacity); }
  ~SharedTets() {
    std::free(records_);
    std::free(owners_);
  }
  SharedTets(const SharedTets&) = delete;
  SharedTets& operator=(const SharedTets&) = delete;

  TetRecord* records() const { return records_; }
  std::uint8_t* owners() const { return owners_; }
  std::uint32_t size() const { return size_.load(std::memory_order_relaxed); }
  std::size_t capacity() const { return capacity_; }

  // Up to `count` fresh slots for thread `owner` (their owner bytes set to it):
  // [first, first + got), got == 0 when the capacity is reached.
  std::uint32_t take(std::uint32_t count, std::uint8_t owner, std::uint32_t& first) {
    std::uint32_t s = size_.load(std::memory_order_relaxed), got = 0;
    do {
      got = static_cast<std::uint32_t>(std::min<std::size_t>(count, capacity_ - s));
      if (got == 0) return 0;
    } while (!size_.compare_exchange_weak(s, s + got, std::memory_order_relaxed));
    first = s;
    // The slots counted in size_ but not yet marked are free to a probe that reaches
    // them; exchange instead of store, so that debug builds see any probe that did.
    for (std::uint32_t t = s; t < s + got; ++t) {
      [[maybe_unused]] const std::uint8_t before =
          std::atomic_ref<std::uint8_t>(owners_[t]).exchange(owner, std::memory_order_relaxed);
      assert(before == 0 && "a fresh slot was taken before its block was marked");
    }
    return got;
  }

  // Only while no thread uses the storage. Throws std::length_error beyond kMaxSlots.
  void grow(std::size_t capacity) {
    capacity = std::min(capacity, kMaxSlots);
    if (capacity <= capacity_) {
      if (capacity_ == kMaxSlots) throw std::length_error("build_delaunay: more than 2^30 tet slots");
      return;
    }
    auto* r = static_cast<TetRecord*>(std::realloc(records_, capacity * sizeof(TetRecord)));
    if (!r) throw std::bad_alloc();
    records_ = r;
    // The first allocation by calloc (zero pages, untouched); a growth zeroes the new tail.
    auto* o = static_cast<std::uint8_t*>(owners_ ? std::realloc(owners_, capacity) : std::calloc(capacity, 1));
    if (!o) throw std::bad_alloc();
    if (owners_) std::memset(o + capacity_, 0, capacity - capacity_);
    owners_ = o;
    capacity_ = capacity;
  }

  // Hands the records over (for the final compaction, which frees them with std::free).
  TetRecord* release_records() {
    TetRecord* r = records_;
    records_ = nullptr;
    return r;
  }

 private:
  TetRecord* records_ = nullptr;
  std::uint8_t* owners_ = nullptr;
  std::atomic<std::uint32_t> size_{0};
  std::size_t capacity_ = 0;
};

}  // namespace dtlab
