#include "cli/progress.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace dtlab::cli {

namespace {

double interval_from_environment() {
  const char* s = std::getenv("DTLAB_PROGRESS_SECONDS");
  if (!s || !*s) return 5;
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  return *end == '\0' && std::isfinite(v) && v >= 0 ? v : 5;
}

std::string duration_text(double s) {
  char buf[48];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}

}  // namespace

Progress::Progress(std::string command, bool quiet)
    : command_(std::move(command)), quiet_(quiet), interval_s_(interval_from_environment()),
      stage_start_(Clock::now()), last_line_(stage_start_) {}

void Progress::print(const std::string& text) {
  std::fprintf(stderr, "dtlab %s: %s\n", command_.c_str(), text.c_str());
  std::fflush(stderr);
  last_line_ = Clock::now();
  printed_ = true;
}

void Progress::say(const std::string& text) {
  if (quiet_) return;
  std::lock_guard<std::mutex> g(lock_);
  print(text);
}

void Progress::update(const std::string& stage, std::size_t done, std::size_t total, const std::string& note) {
  if (quiet_) return;
  std::lock_guard<std::mutex> g(lock_);
  const auto now = Clock::now();
  if (stage != stage_) stage_ = stage, stage_start_ = now;
  const double since_line = std::chrono::duration<double>(now - last_line_).count();
  const bool last = done >= total;
  if (since_line < interval_s_ && !(last && printed_) && interval_s_ > 0) return;
  const double elapsed = std::chrono::duration<double>(now - stage_start_).count();
  char head[96];
  std::snprintf(head, sizeof head, "%zu/%zu (%.0f%%)", done, total, total ? 100.0 * double(done) / double(total) : 100.0);
  std::string text = stage + " " + head;
  if (!note.empty()) text += ", " + note;
  text += "; " + duration_text(elapsed) + " so far";
  if (!last && done > 0) text += ", ETA " + duration_text(elapsed * double(total - done) / double(done));
  if (last) text += ", done";
  print(text);
}

}  // namespace dtlab::cli
