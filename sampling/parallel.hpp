#pragma once
// Splits [0, n) into contiguous chunks run on the available hardware threads.
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace dtlab {

template <class F>
void parallel_chunks(std::size_t n, F&& body, std::size_t min_chunk = 1024) {
  const std::size_t hw = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t workers = std::min(hw, (n + min_chunk - 1) / min_chunk);
  if (workers <= 1) {
    body(std::size_t{0}, n);
    return;
  }
  std::vector<std::thread> pool;
  const std::size_t step = (n + workers - 1) / workers;
  for (std::size_t w = 1; w < workers; ++w) {
    const std::size_t b = w * step, e = std::min(n, b + step);
    if (b < e) pool.emplace_back([&body, b, e] { body(b, e); });
  }
  body(std::size_t{0}, std::min(n, step));
  for (auto& t : pool) t.join();
}

}  // namespace dtlab
