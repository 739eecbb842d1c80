#include "oracle/peers/peer_child.hpp"

#include <unistd.h>

#include <cstring>

namespace dtlab {

std::uint64_t default_peer_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 2;
}

ChildLimits peer_limits(const PeerOptions& options, const std::string& log, bool may_be_instrumented) {
  ChildLimits limits =
      ChildLimits::of(options.timeout_s, log, options.memory_bytes ? options.memory_bytes : default_peer_memory());
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  if (may_be_instrumented) limits.memory_bytes = 0;
#else
  (void)may_be_instrumented;
#endif
  return limits;
}

namespace {

std::string signal_text(int signal) {
  const char* s = strsignal(signal);
  return std::string("signal ") + std::to_string(signal) + " (" + (s ? s : "?") + ")";
}

// "HEAD: LAST" or whichever of the two is there.
std::string joined(const std::string& head, const std::string& last) {
  return head.empty() ? last : last.empty() ? head : head + ": " + last;
}

}  // namespace

std::optional<Verdict> child_failure(const ChildResult& c, const std::string& log, PeerRun& run,
                                     bool exit4_not_installed) {
  run.wall_seconds = c.seconds;
  run.seconds = c.seconds;
  run.peak_rss_bytes = c.peak_rss_bytes;
  switch (c.status) {
    case ChildStatus::not_started: run.message = c.message; return Verdict::not_installed;
    case ChildStatus::timed_out:
      run.message = "killed after " + std::to_string(c.seconds).substr(0, 6) + " s";
      return Verdict::hung;
    case ChildStatus::output_limit: run.message = c.message; return Verdict::refused;
    case ChildStatus::signaled:
    case ChildStatus::exited: break;
  }
  const std::string last = last_line_of(log);
  if (c.out_of_memory) {
    run.message =
        joined(c.status == ChildStatus::signaled ? signal_text(c.signal) : "", last.empty() ? c.message : last);
    return Verdict::out_of_memory;
  }
  if (c.status == ChildStatus::signaled) {
    run.message = joined(signal_text(c.signal), last);
    return Verdict::crashed;
  }
  if (c.exit_code == 0) {
    run.message = last;
    return std::nullopt;
  }
  if (c.exit_code == 4 && exit4_not_installed) {
    run.message = last.empty() ? "not installed" : last;
    return Verdict::not_installed;
  }
  run.message = last.empty() ? "exit status " + std::to_string(c.exit_code) : last;
  return Verdict::refused;
}

}  // namespace dtlab
