#include "oracle/peers/served_child.hpp"

#include "kernel/exit_guard.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>
#include <utility>

namespace dtlab {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Resets the child's VmHWM to its current resident size (Linux's clear_refs "5"), so
// that the peak read after a request is that request's.
void reset_peak(int pid) { std::ofstream("/proc/" + std::to_string(pid) + "/clear_refs") << "5"; }

bool send_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = send(fd, text.data() + done, text.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

ServedChild::ServedChild(std::vector<std::string> argv, ChildLimits limits)
    : argv_(std::move(argv)), limits_(std::move(limits)) {}

ServedChild::~ServedChild() { stop(); }

bool ServedChild::start(ChildResult& r) {
  int request[2], reply[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, request) != 0) {
    r.message = "socketpair failed";
    return false;
  }
  if (pipe2(reply, O_CLOEXEC) != 0) {
    close(request[0]);
    close(request[1]);
    r.message = "pipe failed";
    return false;
  }
  child_ = spawn_child(argv_, limits_, request[1], reply[1], r.message);
  close(request[1]);
  close(reply[1]);
  if (child_.reaper < 0) {
    close(request[0]);
    close(reply[0]);
    r.status = ChildStatus::not_started;
    return false;
  }
  to_ = request[0];
  from_ = reply[0];
  buffer_.clear();
  return true;
}

bool ServedChild::stop(int* status) {
  if (child_.reaper < 0) return false;
  if (to_ >= 0) close(to_);  // EOF: a server that is still well ends by itself
  if (from_ >= 0) close(from_);
  to_ = from_ = -1;
  int s = 0;
  bool killed = false;
  const auto t0 = Clock::now();
  while (waitpid(child_.reaper, &s, WNOHANG) == 0) {
    if (since(t0) > 0.5) {
      kill(-child_.program, SIGKILL);
      waitpid(child_.reaper, &s, 0);
      killed = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  end_tagged(child_.program);  // descendants that left the group kept its tag (the reaper ended the rest)
  release_group(child_.program);
  child_ = {};
  if (status) *status = s;
  return killed;
}

ChildResult ServedChild::ask(const std::string& request, double timeout_s, std::string& reply) {
  ChildResult r;
  reply.clear();
  if (child_.reaper < 0 && !start(r)) return r;
  const auto t0 = Clock::now();
  reset_peak(child_.program);
  bool alive = send_all(to_, request + "\n");
  std::size_t end = std::string::npos;
  while (alive && (end = buffer_.find('\n')) == std::string::npos) {
    const double left = timeout_s - since(t0);
    if (left <= 0) {
      kill(-child_.program, SIGKILL);
      stop();
      r.status = ChildStatus::timed_out;
      r.seconds = since(t0);
      return r;
    }
    if (interrupt_requested()) {
      kill(-child_.program, SIGKILL);
      stop();
      throw ChildInterrupted();
    }
    pollfd p{from_, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min(left * 1000, 100.0)) + 1);
    if (ready < 0 && errno != EINTR) alive = false;
    if (ready <= 0) continue;
    char chunk[4096];
    const ssize_t n = read(from_, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      alive = false;  // EOF: it ended
    else
      buffer_.append(chunk, static_cast<std::size_t>(n));
  }
  r.seconds = since(t0);
  if (!alive) {
    int status = 0;
    const bool killed = stop(&status);
    if (interrupt_received()) wait_for_interrupt_exit();
    classify_child_end(status, limits_.log_path, r);
    if (killed) r.out_of_memory = false;  // our SIGKILL: it lingered after closing its reply channel
    if (r.status == ChildStatus::exited && r.exit_code == 0) r.exit_code = 3;  // ended without answering: no answer
    return r;
  }
  r.peak_rss_bytes = vm_hwm_bytes(child_.program);
  const std::string line = buffer_.substr(0, end);
  buffer_.erase(0, end + 1);
  char* rest = nullptr;
  r.status = ChildStatus::exited;
  r.exit_code = static_cast<int>(std::strtol(line.c_str(), &rest, 10));
  if (rest == line.c_str()) {  // not a reply line: the protocol is broken, start afresh
    stop();
    r.exit_code = 3;
    reply = "bad reply from the helper: " + line;
    return r;
  }
  reply = *rest == ' ' ? std::string(rest + 1) : std::string(rest);
  r.out_of_memory = r.exit_code != 0 && mentions_allocation_failure(reply);
  return r;
}

ServedChild& ServedChildren::get(const std::string& key, const std::vector<std::string>& argv, ChildLimits limits) {
  auto& slot = children_[key];
  if (!slot) {
    limits.log_path = logs_.file("log-" + std::to_string(children_.size()) + ".txt");
    slot = std::make_unique<ServedChild>(argv, std::move(limits));
  }
  return *slot;
}

}  // namespace dtlab
