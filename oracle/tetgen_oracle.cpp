#include "oracle/tetgen_oracle.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <cstring>
#include <fcntl.h>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <vector>

#include "kernel/input_error.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"

extern char** environ;

namespace dtlab {
namespace {

namespace fs = std::filesystem;

// A temporary directory removed with everything in it when this goes away.
class TempDir {
 public:
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/dtlab-tetgen-XXXXXX";
    std::vector<char> buf(tmpl.begin(), tmpl.end());
    buf.push_back('\0');
    if (mkdtemp(buf.data()) == nullptr) throw std::runtime_error("tetgen oracle: cannot create a temporary directory");
    path_ = buf.data();
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string describe_status(int status) {
  if (WIFEXITED(status)) return "tetgen exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "tetgen killed by signal " + std::to_string(WTERMSIG(status));
  return "tetgen ended abnormally";
}

}  // namespace

OracleRun tetgen_delaunay(std::span<const Point3> points, const TetgenOptions& options) {
  if (!(options.timeout_s > 0 && std::isfinite(options.timeout_s)))
    throw std::invalid_argument("tetgen: the time-out must be finite and positive");
  OracleRun run;
  run.name = "tetgen";
  TempDir dir;
  const std::string node = (dir.path() / "in.node").string();
  write_node(node, std::vector<Point3>(points.begin(), points.end()));
  const std::string log = (dir.path() / "tetgen.log").string();

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  std::string flags = "-QzJNF";
  std::vector<char*> argv = {const_cast<char*>(options.binary.c_str()), flags.data(),
                             const_cast<char*>(node.c_str()), nullptr};
  // The child leads its own process group, so a time-out kills whatever it started too.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = 0;
  const auto start = std::chrono::steady_clock::now();
  const int err = posix_spawnp(&pid, options.binary.c_str(), &fa, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (err != 0) {
    run.note = "cannot start '" + options.binary + "': " + std::strerror(err);
    return run;
  }
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r == pid) break;
    if (r < 0) {
      run.note = "waitpid failed";
      return run;
    }
    if (run.seconds > options.timeout_s) {
      kill(-pid, SIGKILL);  // the whole group
      waitpid(pid, &status, 0);
      run.note = "tetgen timed out after " + std::to_string(options.timeout_s) + " s";
      return run;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(run.seconds < 1 ? 1 : 20));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    run.note = describe_status(status);
    return run;
  }
  const std::string ele = (dir.path() / "in.1.ele").string();
  Tetrahedralization t;
  t.points.assign(points.begin(), points.end());
  if (!fs::exists(ele)) {
    // TetGen writes no .ele when the input spans no volume.
    run.note = "tetgen wrote no .ele";
    run.mesh = std::move(t);
    return run;
  }
  try {
    t.tets = read_ele(ele, 0, points.size());
  } catch (const InputError& e) {
    run.note = std::string("unreadable tetgen output: ") + e.what();
    return run;
  }
  std::vector<char> used(points.size(), 0);
  for (const Tet& k : t.tets)
    for (auto v : k) used[v] = 1;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!used[i]) run.duplicates.push_back(static_cast<std::uint32_t>(i));
  run.mesh = std::move(t);
  return run;
}

}  // namespace dtlab
