#pragma once
// A stack of 32-bit ids whose push stays inline (std::vector::push_back is often
// not inlined because of its reallocation path): the free list of dead tets and
// the inserter's flip stack of facets both push and pop tens of times per point.
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>

#include "kernel/ids.hpp"

namespace dtlab {

template <class Id>
class BasicIdStack {
  static_assert(std::is_trivially_copyable_v<Id> && sizeof(Id) == 4);

 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  Id back() const { return data_[size_ - 1]; }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }
  [[gnu::always_inline]] void push_back(Id v) {
    if (size_ == capacity_) [[unlikely]]
      grow(size_ + 1);
    data_[size_++] = v;
  }
  void reserve(std::size_t n) {
    if (n > capacity_) grow(n);
  }
  std::size_t capacity() const { return capacity_; }
  const Id* begin() const { return data_.get(); }
  const Id* end() const { return data_.get() + size_; }
  Id operator[](std::size_t i) const { return data_[i]; }

 private:
  [[gnu::noinline]] void grow(std::size_t need) {
    std::size_t cap = capacity_ ? 2 * capacity_ : 64;
    while (cap < need) cap *= 2;
    std::unique_ptr<Id[]> bigger(new Id[cap]);
    if (size_) std::memcpy(static_cast<void*>(bigger.get()), data_.get(), size_ * sizeof(Id));
    data_ = std::move(bigger);
    capacity_ = cap;
  }
  std::unique_ptr<Id[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

using IdStack = BasicIdStack<std::uint32_t>;
using FacetStack = BasicIdStack<Facet>;

}  // namespace dtlab
