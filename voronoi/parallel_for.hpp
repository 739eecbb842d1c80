#pragma once
// A minimal parallel loop over [0, n) with std::thread: indices handed out in chunks
// from an atomic counter; the first exception thrown by `f` is rethrown after joining.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace dtlab {

// `f(begin, end, worker)` processes [begin, end); worker is 0..threads-1 (for scratch).
template <class F>
void parallel_chunks(std::size_t n, unsigned threads, std::size_t chunk, F&& f) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  chunk = std::max<std::size_t>(chunk, 1);
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>((n + chunk - 1) / chunk, 1)));
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](unsigned w) {
    for (std::size_t b; (b = next.fetch_add(chunk)) < n;) {
      try {
        f(b, std::min(n, b + chunk), w);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

inline unsigned thread_count(unsigned threads) {
  return threads ? threads : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace dtlab
