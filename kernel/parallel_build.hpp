#pragma once
// The parallel insertion loop of build_delaunay (kernel/README.md, "The parallel build").
// Each BRIO round, already sorted along a Hilbert curve, is cut into one contiguous range
// per thread; every thread runs the one inserter (kernel/inserter.hpp) on its own view of
// the shared records (kernel/claimed_mesh.hpp), which claims each tet before touching it.
// An insertion that meets another thread's tet is rolled back and the point deferred; the
// deferred points of a pass form the next pass, which runs on one thread when it is small
// or when the last pass resolved less than half of its points. A full storage stops the
// pass; it grows while no thread runs and the pass resumes where each thread stopped. A
// named failure stops every thread at its next point.
#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "kernel/claimed_mesh.hpp"
#include "kernel/inserter.hpp"
#include "kernel/insertion_log.hpp"
#include "kernel/parallel_for.hpp"
#include "kernel/shared_tets.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/perturbed.hpp"

namespace dtlab {

namespace detail {

// The adaptive backend's stage counter, if B has one (each thread gets its own).
template <class B>
AdaptiveStats** stage_counter(B& b) {
  if constexpr (std::is_same_v<B, AdaptivePredicates>)
    return &b.stats;
  else if constexpr (std::is_same_v<B, Perturbed<AdaptivePredicates>>)
    return &b.base.stats;
  else
    return nullptr;
}

inline void add_stages(AdaptiveStats& to, const AdaptiveStats& from) {
  for (std::size_t s = 0; s < to.orient3d.size(); ++s) {
    to.orient3d[s] += from.orient3d[s];
    to.insphere[s] += from.insphere[s];
  }
}

}  // namespace detail

// The owner byte names a thread: ids 1..254.
inline constexpr unsigned kMaxBuildThreads = 254;

template <PredicateBackend B>
class ParallelInsertion {
 public:
  using Worker = Inserter<B, ClaimedMesh>;
  using Outcome = typename Worker::Outcome;

  // pts: the points by vertex id (insertion rank), with the infinite vertex or the bigtet
  // corners after the n input points.
  ParallelInsertion(const Point3* pts, std::uint32_t n, std::uint32_t inf, const B& pred, const BuildOptions& opt,
                    unsigned threads)
      : store_(initial_slots(n, opt, threads)), grain_(std::max<std::size_t>(opt.parallel_grain, 1)), stages_(threads) {
    B mine = pred;
    AdaptiveStats** counter = detail::stage_counter(mine);
    caller_stages_ = counter ? *counter : nullptr;
    for (unsigned w = 0; w < threads; ++w) {
      if (counter && caller_stages_) *counter = &stages_[w];
      workers_.push_back(std::make_unique<Worker>(pts, mine, inf, opt.seed + w,
                                                  ClaimedMesh(store_, static_cast<std::uint8_t>(w + 1))));
      workers_.back()->reserve(n);
    }
  }

  SharedTets& store() { return store_; }

  // The storage's first capacity: opt.parallel_slots_per_point per point and room for
  // the first tets and two blocks per thread.
  static std::size_t initial_slots(std::uint32_t n, const BuildOptions& opt, unsigned threads) {
    const double per_point = std::isfinite(opt.parallel_slots_per_point) && opt.parallel_slots_per_point > 0
                                 ? std::min(opt.parallel_slots_per_point, 1e3)
                                 : 7.0;
    return static_cast<std::size_t>(per_point * n) + 64 + 2 * std::size_t(ClaimedMesh::kBlock) * threads;
  }
  // How many times the storage grew.
  std::size_t growths() const { return growths_; }

  // The first tet (and its infinite neighbours) on thread 0's view; every thread's
  // geometry learns it (it defines the symbolic inner point O).
  void start(const std::uint32_t first[4], std::uint32_t vertices) {
    workers_[0]->start(first[0], first[1], first[2], first[3]);
    for (std::size_t w = 1; w < workers_.size(); ++w)
      workers_[w]->geometry().set_first_tet(first[0], first[1], first[2], first[3]);
    vertices_ = vertices;
  }

  // Inserts `list` (ranks, in order). Returns false after a named failure (log.failure
  // set, the points not inserted appended to log.skipped).
  bool insert(std::vector<std::uint32_t> list, InsertionLog& log) {
    bool progressed = true;
    while (!list.empty()) {
      const auto threads = static_cast<unsigned>(std::min<std::size_t>(workers_.size(), list.size() / grain_));
      if (threads < 2 || !progressed) return insert_serially(list, 0, log);
      // A mesh with few vertices is too small to share: threads would meet at once.
      const std::size_t want = grain_ * threads;
      if (vertices_ < want) {
        const std::size_t count = std::min(list.size(), want - vertices_);
        std::vector<std::uint32_t> head(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(count));
        if (!insert_serially(head, 0, log)) {
          log.skipped.insert(log.skipped.end(), list.begin() + static_cast<std::ptrdiff_t>(count), list.end());
          return false;
        }
        list.erase(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(count));
        continue;
      }
      std::vector<std::uint32_t> deferred;
      if (!parallel_pass(list, threads, deferred, log)) return false;
      progressed = deferred.size() <= list.size() / 2;
      list = std::move(deferred);
    }
    return true;
  }

  // The end of the build: unused fresh slots become dead records; the statistics summed.
  BuildStats finish() {
    BuildStats s;
    for (auto& w : workers_) {
      w->mesh().finish();
      const BuildStats& t = w->stats();
      s.inserted += t.inserted;
      s.flips14 += t.flips14, s.flips23 += t.flips23, s.flips32 += t.flips32, s.flips44 += t.flips44;
      s.walk_steps += t.walk_steps;
      s.orient3d_calls += w->geometry().orient_calls;
      s.insphere_calls += w->geometry().insphere_calls;
    }
    s.conflicts = conflicts_;
    s.storage_growths = growths_;
    s.threads = static_cast<unsigned>(workers_.size());
    s.parallel_passes = passes_;
    s.parallel_seconds = pass_seconds_;
    s.idle_seconds = idle_seconds_;
    s.serial_points = serial_points_;
    s.serial_seconds = serial_seconds_;
    if (caller_stages_)
      for (const AdaptiveStats& st : stages_) detail::add_stages(*caller_stages_, st);
    return s;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  // Adds the wall seconds of its scope to `to`.
  struct Timed {
    double& to;
    Clock::time_point start = Clock::now();
    ~Timed() { to += seconds(Clock::now() - start); }
  };

  struct Range {
    std::size_t cursor, end;
    std::vector<std::uint32_t> deferred;
  };

  // list[from..] on thread 0's view while no other thread runs: no claim can fail but
  // for a tet that only a broken adjacency reaches (a freed slot of another thread).
  bool insert_serially(const std::vector<std::uint32_t>& list, std::size_t from, InsertionLog& log) {
    const Timed timed{serial_seconds_};
    serial_points_ += list.size() - from;
    Worker& w = *workers_[0];
    w.mesh().attach();
    for (std::size_t i = from; i < list.size();) {
      const std::uint32_t k = list[i];
      switch (w.insert(k)) {
        case Outcome::inserted: ++vertices_; break;
        case Outcome::duplicate: log.duplicates.push_back({k, w.found()}); break;
        case Outcome::no_room: grow(); continue;  // the same point again
        case Outcome::conflict:
          log.failure =
              InsertionLog::Failure{k, FailureKind::inconsistent_adjacency, "the adjacency leads to a freed tet"};
          log.skipped.insert(log.skipped.end(), list.begin() + static_cast<std::ptrdiff_t>(i), list.end());
          return false;
        case Outcome::failed:
          log.failure = InsertionLog::Failure{k, w.failure(), w.failure_detail()};
          log.skipped.insert(log.skipped.end(), list.begin() + static_cast<std::ptrdiff_t>(i), list.end());
          return false;
      }
      ++i;
    }
    audit();
    return true;
  }

  bool parallel_pass(const std::vector<std::uint32_t>& list, unsigned threads, std::vector<std::uint32_t>& deferred,
                     InsertionLog& log) {
    std::vector<Range> ranges(threads);
    for (unsigned r = 0; r < threads; ++r)
      ranges[r] = Range{list.size() * r / threads, list.size() * (r + 1) / threads, {}};
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> duplicates(threads);
    std::vector<std::size_t> inserted(threads, 0), conflicts(threads, 0);
    std::optional<InsertionLog::Failure> failure;
    std::mutex failure_mutex;
    ++passes_;
    for (;;) {
      for (auto& w : workers_) w->mesh().attach();
      std::atomic<bool> stop{false}, full{false};
      // Each worker's first and last moment in the pass (thread start, the barrier's wait).
      std::vector<Clock::time_point> began(threads), ended(threads);
      const Clock::time_point pass_start = Clock::now();
      parallel_chunks(threads, threads, 1, [&](std::size_t begin, std::size_t end, unsigned w) {
        Worker& ins = *workers_[w];
        if (began[w] == Clock::time_point{}) began[w] = Clock::now();
        const struct Ended {
          Clock::time_point& at;
          ~Ended() { at = Clock::now(); }
        } mark{ended[w]};
        for (std::size_t r = begin; r < end; ++r) {
          Range& range = ranges[r];
          try {
            for (; range.cursor < range.end; ++range.cursor) {
              if (stop.load(std::memory_order_relaxed)) return;
              const std::uint32_t k = list[range.cursor];
              const Outcome o = ins.insert(k);
              if (o == Outcome::inserted) {
                ++inserted[w];
              } else if (o == Outcome::duplicate) {
                duplicates[w].push_back({k, ins.found()});
              } else if (o == Outcome::conflict) {
                ++conflicts[w];
                range.deferred.push_back(k);
              } else if (o == Outcome::no_room) {  // k again after the growth
                full.store(true, std::memory_order_relaxed);
                stop.store(true, std::memory_order_relaxed);
                return;
              } else {  // failed: k stays at the cursor, among the points not inserted
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = InsertionLog::Failure{k, ins.failure(), ins.failure_detail()};
                stop.store(true, std::memory_order_relaxed);
                return;
              }
            }
          } catch (...) {
            stop.store(true, std::memory_order_relaxed);
            throw;
          }
        }
      });
      const Clock::time_point pass_end = Clock::now();
      pass_seconds_ += seconds(pass_end - pass_start);
      for (unsigned w = 0; w < threads; ++w)
        if (began[w] != Clock::time_point{})
          idle_seconds_ += seconds(began[w] - pass_start) + seconds(pass_end - ended[w]);
        else
          idle_seconds_ += seconds(pass_end - pass_start);
      if (failure || !full.load()) break;
      grow();
    }
    for (unsigned w = 0; w < threads; ++w) {
      log.duplicates.insert(log.duplicates.end(), duplicates[w].begin(), duplicates[w].end());
      vertices_ += inserted[w];
      conflicts_ += conflicts[w];
    }
    for (Range& range : ranges) deferred.insert(deferred.end(), range.deferred.begin(), range.deferred.end());
    if (!failure) {
      audit();
      return true;
    }
    log.failure = std::move(failure);
    for (Range& range : ranges)
      log.skipped.insert(log.skipped.end(), list.begin() + static_cast<std::ptrdiff_t>(range.cursor),
                         list.begin() + static_cast<std::ptrdiff_t>(range.end));
    log.skipped.insert(log.skipped.end(), deferred.begin(), deferred.end());
    return false;
  }

  // Debug builds: the claim protocol's state after every pass that ended without a
  // failure (kernel/claimed_mesh.hpp, ownership_defect).
  void audit() const {
#ifndef NDEBUG
    std::vector<const ClaimedMesh*> views;
    for (const auto& w : workers_) views.push_back(&w->mesh());
    const std::string defect = ownership_defect(store_, views);
    assert(defect.empty() && "the claim protocol's state after a pass");
#endif
  }

  // The storage grows by half; every view, not only the ones of the next pass, learns
  // the new addresses: a view left on the old ones would write its block's unused
  // slots there at finish() (the defect of 2026-12-02: those slots, never marked dead,
  // came out of the compaction as tets (0, 0, 0, 0)).
  void grow() {
    store_.grow(store_.capacity() + store_.capacity() / 2 + ClaimedMesh::kBlock * workers_.size());
    for (auto& w : workers_) w->mesh().attach();
    ++growths_;
  }

  SharedTets store_;
  std::size_t grain_;
  std::vector<AdaptiveStats> stages_;
  AdaptiveStats* caller_stages_ = nullptr;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::size_t vertices_ = 0;  // in the mesh (the infinite vertex counted)
  std::uint64_t conflicts_ = 0;
  std::size_t growths_ = 0;
  std::uint64_t passes_ = 0, serial_points_ = 0;
  double pass_seconds_ = 0, serial_seconds_ = 0, idle_seconds_ = 0;
};

}  // namespace dtlab
