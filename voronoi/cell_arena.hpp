#pragma once
// Flat storage for the arrays of many cells: blocks of 1 MiB (or one larger array)
// filled front to back that never move, so views into them stay valid as long as the
// arena lives (also after it is moved). One arena per worker thread, no locking.
// Blocks come from mmap with the pages populated up front where the system offers it:
// the output (~1 KB per cell) is written once, and one page fault per 4 KiB was a
// visible part of its cost. (Transparent huge pages were tried too: with the kernel's
// madvise defrag policy they made the cell phase slower and erratic.)
#include <cstddef>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace dtlab::vor {

class CellArena {
 public:
  CellArena() = default;
  CellArena(CellArena&& o) noexcept { *this = std::move(o); }
  CellArena& operator=(CellArena&& o) noexcept;
  CellArena(const CellArena&) = delete;
  CellArena& operator=(const CellArena&) = delete;
  ~CellArena() { release(); }

  // A copy of `a` inside the arena.
  template <class T>
  std::span<const T> copy(std::span<const T> a) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (a.empty()) return {};
    T* p = static_cast<T*>(take(a.size_bytes(), alignof(T)));
    std::memcpy(p, a.data(), a.size_bytes());
    return {p, a.size()};
  }

  std::size_t blocks() const { return blocks_.size(); }

 private:
  struct Block {
    std::byte* data;
    std::size_t size;
  };
  void* take(std::size_t bytes, std::size_t align);
  void release() noexcept;

  std::vector<Block> blocks_;
  std::byte* cur_ = nullptr;
  std::size_t left_ = 0;
};

}  // namespace dtlab::vor
