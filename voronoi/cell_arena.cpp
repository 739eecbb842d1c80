#include "voronoi/cell_arena.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>

#include <sys/mman.h>

namespace dtlab::vor {

namespace {
constexpr std::size_t kBlock = std::size_t(1) << 20;

std::byte* allocate(std::size_t size) {
#ifdef MAP_POPULATE
  constexpr int kFlags = MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE;
#else
  constexpr int kFlags = MAP_PRIVATE | MAP_ANONYMOUS;
#endif
  void* m = mmap(nullptr, size, PROT_READ | PROT_WRITE, kFlags, -1, 0);
  if (m == MAP_FAILED) throw std::bad_alloc();
  return static_cast<std::byte*>(m);
}
}  // namespace

CellArena& CellArena::operator=(CellArena&& o) noexcept {
  if (this != &o) {
    release();
    blocks_ = std::exchange(o.blocks_, {});
    cur_ = std::exchange(o.cur_, nullptr);
    left_ = std::exchange(o.left_, 0);
  }
  return *this;
}

void CellArena::release() noexcept {
  for (const auto& b : blocks_) munmap(b.data, b.size);
  blocks_.clear();
  cur_ = nullptr;
  left_ = 0;
}

void* CellArena::take(std::size_t bytes, std::size_t align) {
  std::size_t pad = cur_ ? (align - reinterpret_cast<std::uintptr_t>(cur_) % align) % align : 0;
  if (!cur_ || pad + bytes > left_) {
    const std::size_t size = std::max(kBlock, (bytes + kBlock - 1) / kBlock * kBlock);
    blocks_.reserve(blocks_.size() + 1);  // no leak if the push below could throw
    std::byte* p = allocate(size);
    blocks_.push_back({p, size});
    cur_ = p;
    left_ = size;
    pad = 0;
  }
  void* r = cur_ + pad;
  cur_ += pad + bytes;
  left_ -= pad + bytes;
  return r;
}

}  // namespace dtlab::vor
