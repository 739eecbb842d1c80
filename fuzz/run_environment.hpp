#pragma once
// Where and with what a run happened, for results a paper can cite: the build
// (dtlab version, git commit, compiler, CGAL / GMP / TetGen versions), the machine
// (CPU, threads, memory, OS kernel), the command line and the UTC date.
#include <string>

#include <nlohmann/json.hpp>

namespace dtlab::fuzz {

nlohmann::json build_description();    // from dtlab/build_info.hpp
nlohmann::json machine_description();  // /proc/cpuinfo, /proc/meminfo, uname
std::string command_line();            // this process's argv, shell-quoted where needed
std::string utc_now();                 // "2026-11-30T08:41:00Z"

// {"build", "machine", "command", "date_utc"}; the caller adds what the run was (seeds ...).
nlohmann::json run_environment();

}  // namespace dtlab::fuzz
