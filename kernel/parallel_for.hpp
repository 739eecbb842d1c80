#pragma once
// The project's one parallel loop (std::thread): indices of [0, n) handed out in
// chunks from an atomic counter. Exception-safe: the first exception thrown by `f`
// (or by starting a thread) is rethrown after every started thread has joined; the
// other workers stop taking chunks once one has failed. std::thread rather than
// oneTBB or OpenMP: no dependency for the library and the Python module, and the
// loops here are coarse (chunks of thousands of items), where a work-stealing
// scheduler gains nothing measurable.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace dtlab {

// 0 means all hardware threads.
inline unsigned thread_count(unsigned threads) {
  return threads ? threads : std::max(1u, std::thread::hardware_concurrency());
}

// `f(begin, end, worker)` processes [begin, end); worker is 0..threads-1 (for scratch).
// With one thread (or one chunk) f runs on the calling thread only.
template <class F>
void parallel_chunks(std::size_t n, unsigned threads, std::size_t chunk, F&& f) {
  threads = thread_count(threads);
  chunk = std::max<std::size_t>(chunk, 1);
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>((n + chunk - 1) / chunk, 1)));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto keep = [&](std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(error_mutex);
    if (!error) error = e;
    failed.store(true, std::memory_order_relaxed);
  };
  auto work = [&](unsigned w) {
    for (std::size_t b; !failed.load(std::memory_order_relaxed) && (b = next.fetch_add(chunk)) < n;) {
      try {
        f(b, std::min(n, b + chunk), w);
      } catch (...) {
        keep(std::current_exception());
      }
    }
  };
  std::vector<std::thread> pool;
  try {
    pool.reserve(threads);
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  } catch (...) {
    keep(std::current_exception());  // the started ones still run; join them below
  }
  work(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

// f(i, worker) for each i in [0, n).
template <class F>
void parallel_for(std::size_t n, unsigned threads, std::size_t chunk, F&& f) {
  parallel_chunks(n, threads, chunk, [&](std::size_t b, std::size_t e, unsigned w) {
    for (std::size_t i = b; i < e; ++i) f(i, w);
  });
}

}  // namespace dtlab
