#pragma once
// Runs body(i) for every i in [0, n) on `jobs` threads (the caller's included), items
// taken in order from a shared counter. The first exception stops the queue and is
// rethrown on the calling thread once every worker has returned.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace dtlab::fuzz {

template <class F>
void run_work_queue(std::size_t n, unsigned jobs, F&& body) {
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::exception_ptr error;
  const auto worker = [&] {
    for (;;) {
      const std::size_t w = next.fetch_add(1);
      if (w >= n) return;
      try {
        body(w);
      } catch (...) {
        std::lock_guard<std::mutex> g(lock);
        if (!error) error = std::current_exception();
        next = n;
        return;
      }
    }
  };
  const unsigned workers = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(std::max<std::size_t>(n, 1))));
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < workers; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace dtlab::fuzz
