#include "fuzz/run_environment.hpp"

#include <sys/utsname.h>

#include <ctime>
#include <fstream>
#include <iterator>
#include <thread>

#include "dtlab/build_info.hpp"
#include "kernel/trim.hpp"

namespace dtlab::fuzz {

namespace {

std::string proc_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return trim(line.substr(colon + 1));
    }
  return "";
}

std::string shell_quote(const std::string& arg) {
  if (!arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                            "-_=+,./:@%") == std::string::npos)
    return arg;
  std::string q = "'";
  for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

nlohmann::json build_description() {
  return {{"dtlab", build_version()},        {"git_commit", build_commit()},
          {"compiler", build_compiler()},    {"build_type", build_type()},
          {"cgal", build_cgal_version()},    {"gmp", build_gmp_version()},
          {"gmp_runtime", runtime_gmp_version()}, {"tetgen", build_tetgen_version()}};
}

nlohmann::json machine_description() {
  nlohmann::json m;
  m["cpu"] = proc_field("/proc/cpuinfo", "model name");
  m["hardware_threads"] = std::thread::hardware_concurrency();
  m["memory"] = proc_field("/proc/meminfo", "MemTotal");
  utsname u{};
  m["kernel"] = uname(&u) == 0 ? std::string(u.sysname) + " " + u.release + " " + u.machine : std::string();
  return m;
}

std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string out, arg;
  for (char c : raw) {
    if (c != '\0') {
      arg += c;
      continue;
    }
    if (!out.empty()) out += ' ';
    out += shell_quote(arg);
    arg.clear();
  }
  return out;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

nlohmann::json run_environment() {
  return {{"build", build_description()}, {"machine", machine_description()}, {"command", command_line()},
          {"date_utc", utc_now()}};
}

}  // namespace dtlab::fuzz
