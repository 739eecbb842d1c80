#pragma once
// One error style for every command: on stderr
//   dtlab <command>: <file>:<line>: <reason>     (an input file at fault; line 0: the whole file)
//   dtlab <command>: <reason>                    (bad usage; no file)
// and exit 2; with --json the error is also a JSON object on stdout:
//   {"error": {"command", "file", "line", "reason"}, "exit": 2}
// (file and line null when no file is at fault). main() reports every exception this way, so
// a command throws InputError (kernel/input_error.hpp) for a bad file, UsageError
// for bad usage found after parsing, and never prints its own error line.
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"

namespace dtlab::cli {

// Bad usage found by a command after parsing (a missing output, a malformed --shard).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CliError {
  std::string command;  // the subcommand path: "tetra", "mesh check"; "" before one
  std::string file;     // "" when no file is at fault
  long line = 0;        // 0: the file as a whole (cannot open, is a directory, ...)
  std::string reason;
  int exit = kBadInput;
};

// "dtlab tetra: a.node:5: not a number: 'one'".
std::string error_line(const CliError& e);
nlohmann::json error_json(const CliError& e);
// Prints the line on stderr (and the JSON object on stdout when `json`); returns e.exit.
int report_error(const CliError& e, bool json);
// The exception being handled (call inside a catch block) as an error of `command`.
CliError current_error(const std::string& command);
// The subcommand path named by the arguments (argv without the program name).
std::string command_path(const CLI::App& app, const std::vector<std::string>& args);
// Whether the arguments ask for JSON output.
bool wants_json(const std::vector<std::string>& args);

}  // namespace dtlab::cli
