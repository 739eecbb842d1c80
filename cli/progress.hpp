#pragma once
// Progress of a long run: a line on stderr every few seconds, also when stderr is not
// a terminal (a log file, CI), naming the stage, how far it got and the ETA:
//   dtlab fuzz: cases 120/600 (20%), 3 failing; 14 s so far, ETA 56 s
// Silent with --quiet. The interval is 5 s; DTLAB_PROGRESS_SECONDS sets another
// (0: a line at every step, as the tests use). Thread-safe.
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace dtlab::cli {

class Progress {
 public:
  Progress(std::string command, bool quiet);
  // Reports `done` of `total` steps of `stage` when the interval has passed since the
  // last line (and a closing line at done == total once any line was printed).
  void update(const std::string& stage, std::size_t done, std::size_t total, const std::string& note = "");
  // One line now, whatever the interval (a stage that cannot count its steps).
  void say(const std::string& text);
  bool quiet() const { return quiet_; }

 private:
  using Clock = std::chrono::steady_clock;
  void print(const std::string& text);

  std::string command_;
  bool quiet_;
  double interval_s_;
  std::string stage_;
  Clock::time_point stage_start_, last_line_;
  bool printed_ = false;
  std::mutex lock_;
};

}  // namespace dtlab::cli
