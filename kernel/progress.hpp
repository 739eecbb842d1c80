#pragma once
// Progress of a long library call: a callback with (stage, done, total), made from the
// calling thread about every `every` items of a stage and at its end. The caller sets
// the listener for the duration of a call with a ProgressScope; the library's loops
// (the build's insertion loop, the checker's steps) read it once, on the thread that
// made the call (workers see none), so no options struct carries it. No listener: one
// branch per item. The callback may throw (a Python KeyboardInterrupt, a user's
// exception): the loop stops at once and the exception propagates out of the call.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <string_view>
#include <utility>

namespace dtlab {

struct ProgressEvent {
  std::string_view stage;  // "insert", "check:orientation", "fuzz:cases", "fracture:pieces", ...
  std::size_t done = 0;
  std::size_t total = 0;
};

class Progress {
 public:
  // every == 0: about 1000 calls per stage (total / 1000, at least 1).
  explicit Progress(std::function<void(const ProgressEvent&)> callback, std::size_t every = 0)
      : callback_(std::move(callback)), every_(every) {}

  // Starts a stage of `total` items: one call with done = 0.
  void begin(std::string_view stage, std::size_t total) {
    stage_ = stage;
    total_ = total;
    step_ = every_ ? every_ : std::max<std::size_t>(1, total / 1000);
    next_ = 0;
    ended_ = false;
    advance(0);
  }
  // `done` items of the stage are finished; calls back when a step was crossed or at the end.
  void advance(std::size_t done) {
    if (done < total_ ? done < next_ : ended_) return;
    ended_ = done >= total_;
    next_ = done + step_;
    callback_(ProgressEvent{stage_, done, total_});
  }
  void finish() { advance(total_); }

 private:
  std::function<void(const ProgressEvent&)> callback_;
  std::size_t every_;
  std::string_view stage_;
  std::size_t total_ = 0, step_ = 1, next_ = 0;
  bool ended_ = false;
};

// The listener of this thread's library calls, or null.
inline Progress*& thread_progress() {
  static thread_local Progress* listener = nullptr;
  return listener;
}

// Sets this thread's listener until the end of the scope (the previous one comes back).
class ProgressScope {
 public:
  explicit ProgressScope(Progress* listener) : previous_(thread_progress()) { thread_progress() = listener; }
  ~ProgressScope() { thread_progress() = previous_; }
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

 private:
  Progress* previous_;
};

// A stage that may have no listener (the form the library's loops use).
inline void progress_begin(Progress* p, std::string_view stage, std::size_t total) {
  if (p) p->begin(stage, total);
}
inline void progress_advance(Progress* p, std::size_t done) {
  if (p) p->advance(done);
}

}  // namespace dtlab
