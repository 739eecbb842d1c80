#pragma once
// Each `dtlab` subcommand registers itself on the CLI11 app. Its callback stores
// the process exit code: 0 ok, 1 a check found a defect, 2 bad usage or input.
#include <CLI/CLI.hpp>

namespace dtlab::cli {

enum ExitCode : int { kOk = 0, kDefect = 1, kBadInput = 2 };

}  // namespace dtlab::cli
