#include "kernel/exit_guard.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <new>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace dtlab {
namespace {

// One record per datagram (SOCK_SEQPACKET keeps them whole, and a send from several
// threads or a forked child never interleaves): '+' or '-', 'G' or 'P', the payload.
std::mutex g_lock;
std::atomic<int> g_socket{-1};
pid_t g_watchdog = -1;
std::atomic<bool> g_interrupted{false};
int g_signal_pipe[2] = {-1, -1};
// This process's nonce in the DTLAB_GUARD tags of its children (16 hex digits), set
// before the watchdog's fork so that the watchdog knows it.
char g_nonce[17] = {};
constexpr int kPidDigits = 10;  // a tag's pid, zero-padded
constexpr char kGuardVar[] = "DTLAB_GUARD=";

// The pids in /proc now, sorted (a directory listing: no file read).
std::vector<int> running_pids() {
  std::vector<int> pids;
  if (DIR* proc = opendir("/proc")) {
    while (const dirent* e = readdir(proc)) {
      char* end = nullptr;
      const long pid = std::strtol(e->d_name, &end, 10);
      if (pid > 1 && *end == '\0') pids.push_back(static_cast<int>(pid));
    }
    closedir(proc);
  }
  std::sort(pids.begin(), pids.end());
  return pids;
}

// Kills (SIGKILL) every other process whose DTLAB_GUARD value holds a space-separated
// word equal to `tag` (or, with `prefix`, starting with it), except those in `before`
// (sorted: processes that ran before the child started cannot descend from it, so only
// the environments of newer ones are read). Repeated while it finds some (a process may
// fork while the scan runs), at most 5 rounds. Processes of other users, or gone, are
// skipped (their environ cannot be read).
void kill_carrying(const std::string& tag, bool prefix, const std::vector<int>& before = {}) {
  const pid_t self = getpid();
  for (int round = 0; round < 5; ++round) {
    int found = 0;
    for (const int pid : running_pids()) {
      if (pid == self || std::binary_search(before.begin(), before.end(), pid)) continue;
      std::ifstream in("/proc/" + std::to_string(pid) + "/environ", std::ios::binary);
      // The environment: NUL-terminated NAME=VALUE entries; the tags are VALUE's words.
      bool carries = false;
      for (std::string entry; !carries && std::getline(in, entry, '\0');) {
        if (entry.rfind(kGuardVar, 0) != 0) continue;
        std::istringstream words(entry.substr(sizeof kGuardVar - 1));
        for (std::string word; !carries && words >> word;)
          carries = prefix ? word.rfind(tag, 0) == 0 : word == tag;
      }
      if (carries) {
        kill(static_cast<pid_t>(pid), SIGKILL);
        ++found;
      }
    }
    if (found == 0) return;
  }
}

// Per running child: the pids that ran when it was started (GuardedEnvironment).
std::mutex g_before_lock;
std::map<int, std::vector<int>> g_before;

std::string child_tag(int pid) {
  char digits[kPidDigits + 1];
  std::snprintf(digits, sizeof digits, "%0*d", kPidDigits, pid);
  return std::string(g_nonce) + "." + digits;
}

// Set around our own forks that exec (a child program) or run the watchdog: the fork
// handler below leaves those children's state alone.
thread_local bool t_own_fork = false;

// The watchdog's list and what it does with it once dtlab is gone.
struct Guarded {
  std::set<int> groups;
  std::set<std::string> paths;

  void apply(const char* rec, std::size_t n) {
    if (n < 3) return;
    const std::string payload(rec + 2, n - 2);
    const bool add = rec[0] == '+';
    if (rec[1] == 'G') {
      const int g = std::atoi(payload.c_str());
      if (g <= 1) return;
      if (add) groups.insert(g);
      else groups.erase(g);
    } else if (rec[1] == 'P') {
      if (add) paths.insert(payload);
      else paths.erase(payload);
    }
  }
  void end_all() const {
    for (int g : groups) kill(-g, SIGKILL);
    for (const auto& p : paths) {
      std::error_code ec;
      std::filesystem::remove_all(p, ec);
    }
  }
};

// Only descriptor 3 (the socket) stays open, so that the watchdog holds no pipe of
// its caller's open (a caller reading dtlab's stdout sees EOF when dtlab ends).
void isolate_watchdog(int sock) {
  setpgid(0, 0);  // Ctrl-C to dtlab's group does not reach it
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT}) signal(s, SIG_IGN);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  prctl(PR_SET_NAME, "dtlab-watchdog");
  if (sock < 3) sock = fcntl(sock, F_DUPFD, 3);
  if (sock != 3) dup2(sock, 3);
  const int null = open("/dev/null", O_RDWR);
  for (int fd = 0; fd < 3; ++fd) dup2(null, fd);
  close_range(4, ~0U, 0);
}

[[noreturn]] void run_watchdog(int sock) {
  isolate_watchdog(sock);
  Guarded guarded;
  std::vector<char> buf(1 << 16);
  for (;;) {
    const ssize_t n = recv(3, buf.data(), buf.size(), 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // every copy of the other end is closed: dtlab has ended
    guarded.apply(buf.data(), static_cast<std::size_t>(n));
  }
  guarded.end_all();
  if (g_nonce[0]) kill_carrying(std::string(g_nonce) + ".", true);  // those that left their groups
  _exit(0);
}

// A plain fork of a guarded process (bench's measuring child) that goes on running
// dtlab code: it drops its parent's list (its children are listed with a watchdog of its
// own, started on first use), ends with its parent (PR_SET_PDEATHSIG), and takes the
// signals' default actions (it has no signal thread).
void after_plain_fork(pid_t parent) {
  if (t_own_fork) return;
  const int sock = g_socket.exchange(-1);
  if (sock >= 0) close(sock);
  g_watchdog = -1;
  new (&g_lock) std::mutex;  // another thread may have held it at the fork
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler != SIG_IGN) signal(sig, SIG_DFL);
  }
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(1);
}

pid_t g_parent_at_fork = 0;

void register_fork_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    pthread_atfork([] { g_parent_at_fork = getpid(); }, nullptr, [] { after_plain_fork(g_parent_at_fork); });
  });
}

void start_watchdog_locked() {
  if (g_socket.load() >= 0) return;
  register_fork_handler();
  const std::uint64_t nonce =
      (std::uint64_t{std::random_device{}()} << 32) ^ std::random_device{}() ^ static_cast<std::uint64_t>(getpid());
  std::snprintf(g_nonce, sizeof g_nonce, "%016llx", static_cast<unsigned long long>(nonce));
  int sv[2];
  if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sv) != 0)
    throw std::runtime_error("cannot start the exit watchdog: socketpair failed");
  t_own_fork = true;
  const pid_t pid = fork();
  t_own_fork = false;
  if (pid < 0) {
    close(sv[0]);
    close(sv[1]);
    throw std::runtime_error("cannot start the exit watchdog: fork failed");
  }
  if (pid == 0) {
    close(sv[0]);
    run_watchdog(sv[1]);
  }
  close(sv[1]);
  g_watchdog = pid;
  g_socket = sv[0];
}

void send_record(char op, char kind, const std::string& payload) {
  std::lock_guard<std::mutex> hold(g_lock);
  start_watchdog_locked();
  std::string rec{op, kind};
  rec += payload;
  while (send(g_socket.load(), rec.data(), rec.size(), MSG_NOSIGNAL) < 0 && errno == EINTR) {
  }
}

[[noreturn]] void die_of(int sig) {
  signal(sig, SIG_DFL);
  sigset_t s;
  sigemptyset(&s);
  sigaddset(&s, sig);
  pthread_sigmask(SIG_UNBLOCK, &s, nullptr);
  raise(sig);
  _exit(128 + sig);
}

void on_signal(int sig) {
  const unsigned char s = static_cast<unsigned char>(sig);
  [[maybe_unused]] const ssize_t w = write(g_signal_pipe[1], &s, 1);
}

}  // namespace

void mark_exec_fork(bool on) { t_own_fork = on; }

void prepare_exit_guard() {
  std::lock_guard<std::mutex> hold(g_lock);
  start_watchdog_locked();
}

void guard_path(const std::string& path) { send_record('+', 'P', path); }
void release_path(const std::string& path) { send_record('-', 'P', path); }
void release_group(int pgid) { send_record('-', 'G', std::to_string(pgid)); }

void guard_own_group_in_child() {
  const int sock = g_socket.load();
  if (sock < 0) return;
  char rec[32] = {'+', 'G'};
  char digits[16];
  int n = 0;
  for (int pid = getpid(); pid > 0 && n < 16; pid /= 10) digits[n++] = static_cast<char>('0' + pid % 10);
  for (int i = 0; i < n; ++i) rec[2 + i] = digits[n - 1 - i];
  send(sock, rec, static_cast<std::size_t>(2 + n), MSG_NOSIGNAL);
}

GuardedEnvironment::GuardedEnvironment() {
  prepare_exit_guard();  // the nonce
  for (char** e = environ; e && *e; ++e)
    if (std::strncmp(*e, kGuardVar, sizeof kGuardVar - 1) != 0) entries_.emplace_back(*e);
  std::string guard = kGuardVar + guard_tag_prefix() + std::string(kPidDigits, '0');  // the outer tags stay
  digits_ = guard.size() - kPidDigits;
  guard_ = entries_.size();
  entries_.push_back(std::move(guard));
  for (auto& e : entries_) pointers_.push_back(e.data());
  pointers_.push_back(nullptr);
  before_ = running_pids();
}

void GuardedEnvironment::started(int child_pid) {
  std::lock_guard<std::mutex> hold(g_before_lock);
  g_before[child_pid] = std::move(before_);
}

void GuardedEnvironment::stamp_child_pid() {
  char* d = pointers_[guard_] + digits_;
  for (int pid = getpid(), k = kPidDigits - 1; k >= 0; --k, pid /= 10) d[k] = static_cast<char>('0' + pid % 10);
}

void end_tagged(int child_pid) {
  if (!g_nonce[0]) return;
  std::vector<int> before;
  {
    std::lock_guard<std::mutex> hold(g_before_lock);
    if (auto it = g_before.find(child_pid); it != g_before.end()) {
      before = std::move(it->second);
      g_before.erase(it);
    }
  }
  kill_carrying(child_tag(child_pid), false, before);
}

std::string guard_tag_prefix() {
  prepare_exit_guard();
  const char* outer = std::getenv("DTLAB_GUARD");  // kGuardVar's name: dtlab under dtlab
  std::string prefix = outer && *outer ? std::string(outer) + " " : "";
  return prefix + g_nonce + ".";
}

int guard_pid_digits() { return kPidDigits; }

void end_guarded_now() {
  g_lock.lock();  // never released: the process ends after this
  const int sock = g_socket.exchange(-1);
  if (sock < 0) return;
  close(sock);
  // A child between fork and exec still holds a copy; it closes at its exec.
  const auto t0 = std::chrono::steady_clock::now();
  while (waitpid(g_watchdog, nullptr, WNOHANG) == 0 &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  // Reaps the killed children, so that none is left a zombie under an init that does not reap.
  const auto t1 = std::chrono::steady_clock::now();
  while (waitpid(-1, nullptr, WNOHANG) >= 0 && std::chrono::steady_clock::now() - t1 < std::chrono::seconds(1))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void install_interrupt_cleanup() {
  // A mask inherited across exec may block them (a caller's pthread_sigmask): then
  // `timeout`'s SIGTERM or Ctrl-C would wait for ever. Threads started later inherit this.
  sigset_t ours;
  sigemptyset(&ours);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&ours, sig);
  pthread_sigmask(SIG_UNBLOCK, &ours, nullptr);
  prepare_exit_guard();
  if (pipe2(g_signal_pipe, O_CLOEXEC) != 0) return;
  std::thread([] {
    unsigned char s = 0;
    while (read(g_signal_pipe[0], &s, 1) != 1) {
    }
    g_interrupted = true;
    end_guarded_now();
    die_of(s);
  }).detach();
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // nohup, a background job: keep ignoring it
    struct sigaction a {};
    a.sa_handler = on_signal;
    sigemptyset(&a.sa_mask);
    a.sa_flags = SA_RESTART;
    sigaction(sig, &a, nullptr);
  }
}

bool interrupt_received() { return g_interrupted.load(); }

void wait_for_interrupt_exit() {
  for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
}

}  // namespace dtlab
