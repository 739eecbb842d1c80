#pragma once
// Splits [0, n) into contiguous chunks run on the available hardware threads: the
// kernel's parallel loop (kernel/parallel_for.hpp) with one chunk per thread.
#include <algorithm>
#include <cstddef>

#include "kernel/parallel_for.hpp"

namespace dtlab {

template <class F>
void parallel_chunks(std::size_t n, F&& body, std::size_t min_chunk = 1024) {
  const unsigned hw = thread_count(0);
  const std::size_t step = std::max<std::size_t>(min_chunk, (n + hw - 1) / hw);
  parallel_chunks(n, hw, step, [&](std::size_t b, std::size_t e, unsigned) { body(b, e); });
}

}  // namespace dtlab
