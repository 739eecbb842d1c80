#include "oracle/peers/program_reaper.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <initializer_list>

namespace dtlab {
namespace {

constexpr long kSweepLimitNs = 2'000'000'000;  // the sweep gives up after 2 s (a process stuck in the kernel)

long now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1'000'000'000L + t.tv_nsec;
}

void nap_1ms() {
  timespec t{0, 1'000'000};
  nanosleep(&t, nullptr);
}

// Parses a decimal number at `s` (no sign); `s` moves past it.
long parse_number(const char*& s, const char* end) {
  long v = 0;
  while (s < end && *s >= '0' && *s <= '9') v = v * 10 + (*s++ - '0');
  return v;
}

// The parent and process group of `pid` from /proc/PID/stat ("pid (comm) state ppid
// pgrp ..."; comm may hold spaces and parentheses, so fields are read after the last
// ')'). False when it is gone.
bool read_parent_and_group(const char* pid_digits, long& ppid, long& pgrp) {
  char path[48] = "/proc/";
  int n = 6;
  for (const char* d = pid_digits; *d && n < 40; ++d) path[n++] = *d;
  for (const char* tail = "/stat"; *tail; ++tail) path[n++] = *tail;
  path[n] = '\0';
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char buf[512];
  const ssize_t got = read(fd, buf, sizeof buf);
  close(fd);
  if (got <= 0) return false;
  const char* end = buf + got;
  const char* s = end;
  while (s > buf && s[-1] != ')') --s;
  if (s == buf || end - s < 4) return false;
  s += 3;  // ") S "
  ppid = parse_number(s, end);
  ++s;
  pgrp = parse_number(s, end);
  return true;
}

// Kills (SIGKILL) every child of this process, and the group of each that leads one.
// Reads /proc with getdents64: no allocation.
void kill_children() {
  const long self = getpid();
  const int dir = open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;
  alignas(8) char buf[8192];
  for (;;) {
    const long n = syscall(SYS_getdents64, dir, buf, sizeof buf);
    if (n <= 0) break;
    for (long at = 0; at < n;) {
      // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name
      unsigned short reclen = 0;
      __builtin_memcpy(&reclen, buf + at + 16, sizeof reclen);
      const char* name = buf + at + 19;
      at += reclen;
      if (*name < '1' || *name > '9') continue;
      long ppid = 0, pgrp = 0;
      if (!read_parent_and_group(name, ppid, pgrp) || ppid != self) continue;
      const char* s = name;
      const long pid = parse_number(s, s + 16);
      kill(static_cast<pid_t>(pid), SIGKILL);
      if (pgrp == pid) kill(static_cast<pid_t>(-pid), SIGKILL);
    }
  }
  close(dir);
}

// Ends as `status` (a wait status) says the program ended.
[[noreturn]] void exit_as(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    struct sigaction a {};
    a.sa_handler = SIG_DFL;
    sigemptyset(&a.sa_mask);
    sigaction(sig, &a, nullptr);
    sigset_t only;
    sigemptyset(&only);
    sigaddset(&only, sig);
    sigprocmask(SIG_UNBLOCK, &only, nullptr);
    kill(getpid(), sig);
  }
  _exit(WIFEXITED(status) ? WEXITSTATUS(status) : 127);
}

volatile sig_atomic_t g_parent_died = 0;

void on_parent_death(int) { g_parent_died = 1; }

}  // namespace

void become_reaper(bool end_with_parent, int parent) {
  sigset_t block;
  sigemptyset(&block);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) sigaddset(&block, sig);
  sigprocmask(SIG_BLOCK, &block, nullptr);
  struct sigaction a {};  // a host's SIG_IGN would reap the program before our wait could read its end
  a.sa_handler = SIG_DFL;
  sigemptyset(&a.sa_mask);
  sigaction(SIGCHLD, &a, nullptr);
  setpgid(0, 0);
  prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
  if (end_with_parent) {
    struct sigaction d {};  // no SA_RESTART: the wait below returns EINTR
    d.sa_handler = on_parent_death;
    sigemptyset(&d.sa_mask);
    sigaction(SIGUSR1, &d, nullptr);
    prctl(PR_SET_PDEATHSIG, SIGUSR1, 0, 0, 0);
    if (getppid() != parent) g_parent_died = 1;  // it died before the prctl
  }
}

void reap_program(int program) {
  const int null = open("/dev/null", O_RDWR);
  for (int fd = 0; fd < 3; ++fd) dup2(null, fd);
  syscall(SYS_close_range, 3U, ~0U, 0U);

  int status = 0;
  for (;;) {  // the program's end; adopted orphans that end meanwhile are reaped
    int s = 0;
    const pid_t w = waitpid(-1, &s, 0);
    if (w == program) {
      status = s;
      break;
    }
    if (w < 0 && errno != EINTR) _exit(127);  // no child at all: cannot happen
    if (g_parent_died) kill(-program, SIGKILL);
  }

  // What the program left: its group, then every orphan adopted here (those that left
  // the group, and those the group kill orphans), until none is left.
  kill(-program, SIGKILL);
  const long start = now_ns();
  while (now_ns() - start < kSweepLimitNs) {
    const pid_t w = waitpid(-1, nullptr, WNOHANG);
    if (w > 0) continue;
    if (w < 0) break;  // no child left
    kill_children();
    nap_1ms();
  }
  exit_as(status);
}

}  // namespace dtlab
