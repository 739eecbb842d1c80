#include "oracle/peers/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "kernel/exit_guard.hpp"
#include "oracle/peers/program_reaper.hpp"

namespace dtlab {
namespace {

std::atomic<bool (*)()> g_interrupt_check{nullptr};

// Everything the child does between fork and exec must be async-signal-safe: the
// argument vector and the paths are prepared before the fork. Every descriptor of
// the parent is close-on-exec (pipe2, socketpair with SOCK_CLOEXEC); dup2 clears the
// flag on the copies the program gets.
[[noreturn]] void exec_child(char* const* argv, GuardedEnvironment& env, const char* log, std::uint64_t memory,
                             int stdin_fd, int reply_fd, int error_fd) {
  setpgid(0, 0);
  guard_own_group_in_child();
  env.stamp_child_pid();
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  const int fd = open(log ? log : "/dev/null", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd >= 0) {
    dup2(fd, 1);
    dup2(fd, 2);
  }
  if (stdin_fd >= 0) {
    dup2(stdin_fd, 0);
  } else {
    const int in = open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (in >= 0) dup2(in, 0);
  }
  if (reply_fd == 3)
    fcntl(3, F_SETFD, 0);
  else if (reply_fd >= 0)
    dup2(reply_fd, 3);
  if (memory) {
    rlimit r{static_cast<rlim_t>(memory), static_cast<rlim_t>(memory)};
    setrlimit(RLIMIT_AS, &r);
  }
  rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  execvpe(argv[0], argv, env.envp());
  const int err = errno;
  [[maybe_unused]] ssize_t w = write(error_fd, &err, sizeof err);
  _exit(127);
}

// After the last wait for a child: an interrupt of dtlab (its handler is ending the
// process) made that child die, so its end is no answer to report.
void hold_if_interrupted() {
  if (interrupt_received()) wait_for_interrupt_exit();
}

}  // namespace

void set_interrupt_check(bool (*check)()) { g_interrupt_check = check; }

bool interrupt_requested() {
  bool (*check)() = g_interrupt_check.load();
  return check && check();
}

std::uint64_t vm_hwm_bytes(int pid) {
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%d/status", static_cast<int>(pid));
  std::FILE* f = std::fopen(path, "r");
  if (!f) return 0;
  char line[256];
  std::uint64_t kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "VmHWM:", 6) == 0) {
      kb = std::strtoull(line + 6, nullptr, 10);
      break;
    }
  std::fclose(f);
  return kb * 1024;
}

namespace {

// read(2) of `n` bytes, retried on EINTR; what read returned.
ssize_t read_retrying(int fd, void* into, std::size_t n) {
  ssize_t got = 0;
  while ((got = read(fd, into, n)) < 0 && errno == EINTR) {
  }
  return got;
}

// The reaper's side, once the program is forked: its pid to the parent, then the reaping.
[[noreturn]] void report_and_reap(int pid_fd, pid_t program) {
  [[maybe_unused]] const ssize_t w = write(pid_fd, &program, sizeof program);
  if (program < 0) _exit(127);
  reap_program(program);
}

// The parent's side: the program's pid as its reaper reported it, or -1 (the reaper is
// then reaped here).
pid_t program_pid_from(int pid_fd, pid_t reaper) {
  pid_t program = -1;
  const ssize_t got = read_retrying(pid_fd, &program, sizeof program);
  close(pid_fd);
  if (got == static_cast<ssize_t>(sizeof program) && program > 0) return program;
  waitpid(reaper, nullptr, 0);
  return -1;
}

}  // namespace

SpawnedChild spawn_child(const std::vector<std::string>& args, const ChildLimits& limits, int stdin_fd, int reply_fd,
                         std::string& message) {
  if (args.empty()) throw std::invalid_argument("run_child: no program");
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  int exec_pipe[2], pid_pipe[2];  // the exec's errno (EOF when it succeeded); the program's pid
  if (pipe2(exec_pipe, O_CLOEXEC) != 0) throw std::runtime_error("run_child: pipe failed");
  if (pipe2(pid_pipe, O_CLOEXEC) != 0) {
    close(exec_pipe[0]);
    close(exec_pipe[1]);
    throw std::runtime_error("run_child: pipe failed");
  }
  GuardedEnvironment env;  // starts the exit guard; DTLAB_GUARD: found again if it leaves its group (end_tagged)
  mark_exec_fork(true);
  const pid_t reaper = fork();
  if (reaper == 0) {  // the reaper (oracle/peers/program_reaper.hpp), then the program
    become_reaper();
    // vfork: the reaper waits until the program has exec'd (or failed to) and no second
    // copy of dtlab's page tables is made. The program's side calls only exec_child.
    const pid_t program = vfork();
    if (program == 0) {
      close(pid_pipe[1]);
      exec_child(argv.data(), env, limits.log_path.empty() ? nullptr : limits.log_path.c_str(), limits.memory_bytes,
                 stdin_fd, reply_fd, exec_pipe[1]);
    }
    // The program set its own group before its exec, and vfork returns only after that:
    // a group kill as soon as dtlab knows the pid reaches it.
    report_and_reap(pid_pipe[1], program);
  }
  mark_exec_fork(false);
  close(exec_pipe[1]);
  close(pid_pipe[1]);
  if (reaper < 0) {
    close(exec_pipe[0]);
    close(pid_pipe[0]);
    message = std::string("fork failed: ") + std::strerror(errno);
    return {};
  }
  const pid_t program = program_pid_from(pid_pipe[0], reaper);
  if (program < 0) {
    close(exec_pipe[0]);
    message = "fork failed";
    return {};
  }
  env.started(program);
  int exec_errno = 0;
  const ssize_t got = read_retrying(exec_pipe[0], &exec_errno, sizeof exec_errno);  // EOF when exec succeeded
  close(exec_pipe[0]);
  if (got == static_cast<ssize_t>(sizeof exec_errno)) {
    waitpid(reaper, nullptr, 0);
    end_tagged(program);  // drops its record of the pids at the start
    release_group(program);
    message = "cannot run '" + args[0] + "': " + std::strerror(exec_errno);
    return {};
  }
  return {reaper, program};
}

SpawnedChild fork_under_reaper(const ForkHooks& hooks) {
  int pid_pipe[2];
  if (pipe2(pid_pipe, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  prepare_exit_guard();
  const pid_t parent = getpid();
  if (hooks.before) hooks.before();
  mark_exec_fork(true);  // the reaper is ours: the exit guard's plain-fork handler leaves it alone
  const pid_t reaper = fork();
  if (reaper == 0) {
    become_reaper(true, parent);
    mark_exec_fork(false);  // the program is a plain fork (after_plain_fork, kernel/exit_guard.cpp)
    const pid_t program = fork();
    if (program == 0) {
      close(pid_pipe[0]);
      close(pid_pipe[1]);
      setpgid(0, 0);
      signal(SIGUSR1, SIG_DFL);  // the reaper's parent-death signal
      sigset_t none;             // the reaper's blocked signals are not the program's
      sigemptyset(&none);
      sigprocmask(SIG_SETMASK, &none, nullptr);
      if (hooks.after_child) hooks.after_child();
      return {0, 0};
    }
    if (program > 0) setpgid(program, program);  // both sides: a kill as soon as dtlab knows the pid reaches it
    report_and_reap(pid_pipe[1], program);
  }
  const int fork_errno = errno;
  mark_exec_fork(false);
  if (hooks.after_parent) hooks.after_parent();
  close(pid_pipe[1]);
  if (reaper < 0) {
    close(pid_pipe[0]);
    throw std::system_error(fork_errno, std::generic_category(), "fork");
  }
  const pid_t program = program_pid_from(pid_pipe[0], reaper);
  if (program < 0) throw std::system_error(EAGAIN, std::generic_category(), "fork");
  return {reaper, program};
}

namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t file_size_of(const std::string& path) {
  struct stat st {};
  return !path.empty() && stat(path.c_str(), &st) == 0 ? static_cast<std::uint64_t>(st.st_size) : 0;
}

// The last `bytes` of a file ("" when missing).
std::string tail_of(const std::string& path, std::streamoff bytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  const std::streamoff from = size > bytes ? size - bytes : 0;
  in.seekg(from);
  std::string text(static_cast<std::size_t>(size - from), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  return text;
}

bool tells_allocation_failure(const std::string& log_path) {
  return !log_path.empty() && mentions_allocation_failure(tail_of(log_path, 4096));
}

enum class WaitEnd { ended, timed_out, output_limit, wait_failed };

// Waits for `child` under `limits`: samples the program's peak memory and, through
// `output_bytes`, the size of what it wrote; kills the program's group at the time
// limit, at the output cap or on an interrupt request (then throws ChildInterrupted).
WaitEnd wait_limited(const SpawnedChild& child, const ChildLimits& limits, Clock::time_point start, ChildResult& r,
                     int& status, const std::function<std::uint64_t()>& output_bytes) {
  // Readable once the waited process has ended: each poll's pause ends at its end, so
  // its time is not rounded up to the poll interval. Without it (old kernels), a sleep.
  struct ExitDescriptor {
    int fd;
    ~ExitDescriptor() {
      if (fd >= 0) close(fd);
    }
  } ended{static_cast<int>(syscall(SYS_pidfd_open, child.reaper, 0))};
  const auto pause_ms = [&](int ms) {
    pollfd p{ended.fd, POLLIN, 0};
    if (ended.fd < 0 || poll(&p, 1, ms) < 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
  };
  rusage usage{};
  WaitEnd end = WaitEnd::ended;
  for (;;) {
    // Sampled before each wait: the last sample is at most one poll interval old.
    r.peak_rss_bytes = std::max(r.peak_rss_bytes, vm_hwm_bytes(child.program));
    const pid_t w = wait4(child.reaper, &status, WNOHANG, &usage);
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (w == child.reaper) break;
    if (w < 0 && errno != EINTR) {
      kill(-child.program, SIGKILL);
      return WaitEnd::wait_failed;
    }
    if (interrupt_requested()) {
      kill(-child.program, SIGKILL);
      end_tagged(child.program);
      wait4(child.reaper, &status, 0, &usage);
      release_group(child.program);
      throw ChildInterrupted();
    }
    if (r.seconds > limits.timeout_s)
      end = WaitEnd::timed_out;
    else if (limits.log_cap_bytes && output_bytes() > limits.log_cap_bytes)
      end = WaitEnd::output_limit;
    if (end != WaitEnd::ended) {
      kill(-child.program, SIGKILL);
      wait4(child.reaper, &status, 0, &usage);
      break;
    }
    pause_ms(r.seconds < 0.2 ? 1 : r.seconds < 2 ? 5 : 20);
  }
  r.maxrss_bytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
  return end;
}

// The end of a child waited for by wait_limited: its group released, its status set.
ChildResult& finish_child(const SpawnedChild& child, WaitEnd end, int status, const ChildLimits& limits,
                          ChildResult& r) {
  // The group may hold grandchildren that outlived their parent (a forked body has no
  // reaper to end them), and descendants that left the group carry its tag.
  kill(-child.program, SIGKILL);
  end_tagged(child.program);
  release_group(child.program);
  if (end == WaitEnd::wait_failed) {
    r.status = ChildStatus::not_started;
    r.message = "wait failed";
    return r;
  }
  hold_if_interrupted();
  if (end == WaitEnd::timed_out)
    r.status = ChildStatus::timed_out;
  else if (end == WaitEnd::output_limit) {
    r.status = ChildStatus::output_limit;
    r.message = "killed: wrote more than " + std::to_string(limits.log_cap_bytes >> 20) + " MiB of output";
  } else
    classify_child_end(status, limits.log_path, r);
  return r;
}

}  // namespace

bool mentions_allocation_failure(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* marker : {"bad_alloc", "memoryerror", "out of memory", "cannot allocate", "memory exhausted"})
    if (text.find(marker) != std::string::npos) return true;
  return false;
}

void classify_child_end(int status, const std::string& log_path, ChildResult& r) {
  if (WIFSIGNALED(status)) {
    r.status = ChildStatus::signaled;
    r.signal = WTERMSIG(status);
  } else {
    r.status = ChildStatus::exited;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  if (r.status == ChildStatus::signaled && r.signal == SIGKILL) {
    // Our own kills (time limit, output cap, interrupt) never come here.
    r.out_of_memory = true;
    r.message = "killed by SIGKILL, not at the time limit (the out-of-memory killer or a memory limit)";
  } else if ((r.status == ChildStatus::signaled || r.exit_code != 0) && tells_allocation_failure(log_path)) {
    r.out_of_memory = true;
    r.message = "an allocation failed";
  }
}

bool program_found(const std::string& program) {
  const auto executable = [](const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(path.c_str(), X_OK) == 0;
  };
  if (program.empty()) return false;
  if (program.find('/') != std::string::npos) return executable(program);
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t at = 0;;) {
    const std::size_t end = dirs.find(':', at);
    const std::string dir = dirs.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (executable((dir.empty() ? std::string(".") : dir) + "/" + program)) return true;
    if (end == std::string::npos) return false;
    at = end + 1;
  }
}

ChildResult run_child(const std::vector<std::string>& args, const ChildLimits& limits) {
  if (!std::isfinite(limits.timeout_s) || limits.timeout_s <= 0)
    throw std::invalid_argument("run_child: the timeout must be a positive number of seconds");
  ChildResult r;
  const auto start = Clock::now();
  const SpawnedChild child = spawn_child(args, limits, -1, -1, r.message);
  if (child.reaper < 0) return r;  // not_started
  int status = 0;
  const WaitEnd end = wait_limited(child, limits, start, r, status, [&] { return file_size_of(limits.log_path); });
  return finish_child(child, end, status, limits, r);
}

ChildResult run_forked(const std::function<void(int reply_fd)>& body, const ChildLimits& limits, std::string& reply) {
  if (!std::isfinite(limits.timeout_s) || limits.timeout_s <= 0)
    throw std::invalid_argument("run_forked: the timeout must be a positive number of seconds");
  ChildResult r;
  reply.clear();
  int fd[2];
  if (pipe2(fd, O_CLOEXEC) != 0) {
    r.message = "pipe failed";
    return r;
  }
  prepare_exit_guard();  // its fork handler gives the child its own guard and the parent-death signal
  std::fflush(nullptr);
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fd[0]);
    close(fd[1]);
    r.message = std::string("fork failed: ") + std::strerror(errno);
    return r;
  }
  if (pid == 0) {
    close(fd[0]);
    setpgid(0, 0);
    if (!limits.log_path.empty()) {
      const int log = open(limits.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
      if (log >= 0) dup2(log, 1), dup2(log, 2);
    }
    if (limits.memory_bytes) {
      rlimit m{static_cast<rlim_t>(limits.memory_bytes), static_cast<rlim_t>(limits.memory_bytes)};
      setrlimit(RLIMIT_AS, &m);
    }
    int code = 0;
    try {
      body(fd[1]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      code = 70;
    }
    std::fflush(nullptr);
    _exit(code);
  }
  setpgid(pid, pid);  // both sides, so a kill right after the fork reaches the group
  close(fd[1]);
  fcntl(fd[0], F_SETFL, O_NONBLOCK);
  std::uint64_t replied = 0;  // bytes read from the reply pipe, kept or not
  const auto drain = [&] {
    char chunk[4096];
    ssize_t n;
    while ((n = read(fd[0], chunk, sizeof chunk)) > 0) {
      replied += static_cast<std::uint64_t>(n);
      const std::uint64_t kept = reply.size(), cap = limits.log_cap_bytes ? limits.log_cap_bytes : UINT64_MAX;
      reply.append(chunk, static_cast<std::size_t>(std::min<std::uint64_t>(n, cap - std::min(kept, cap))));
    }
    return std::max<std::uint64_t>(replied, file_size_of(limits.log_path));
  };

  int status = 0;
  WaitEnd end = WaitEnd::wait_failed;
  try {
    end = wait_limited({pid, pid}, limits, start, r, status, drain);
  } catch (...) {
    close(fd[0]);
    throw;
  }
  drain();
  close(fd[0]);
  return finish_child({pid, pid}, end, status, limits, r);
}

std::string last_line_of(const std::string& path) {
  const std::string text = tail_of(path, 4096);
  std::size_t end = text.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return "";
  const std::size_t begin = text.rfind('\n', end);
  return text.substr(begin == std::string::npos ? 0 : begin + 1,
                     end - (begin == std::string::npos ? 0 : begin + 1) + 1);
}

}  // namespace dtlab
