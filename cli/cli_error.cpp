#include "cli/cli_error.hpp"

#include <new>

#include <algorithm>
#include <cstdio>

#include "kernel/input_error.hpp"

namespace dtlab::cli {

std::string error_line(const CliError& e) {
  std::string s = e.command.empty() ? "dtlab: " : "dtlab " + e.command + ": ";
  if (!e.file.empty()) s += e.file + ":" + std::to_string(e.line) + ": ";
  return s + e.reason;
}

nlohmann::json error_json(const CliError& e) {
  const nlohmann::json file = e.file.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.file);
  const nlohmann::json line = e.file.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.line);
  return {{"error", {{"command", e.command}, {"file", file}, {"line", line}, {"reason", e.reason}}},
          {"exit", e.exit}};
}

int report_error(const CliError& e, bool json) {
  std::fflush(stdout);
  std::fprintf(stderr, "%s\n", error_line(e).c_str());
  if (json) std::printf("%s\n", error_json(e).dump(2).c_str());
  std::fflush(stdout);
  return e.exit;
}

CliError current_error(const std::string& command) {
  CliError e;
  e.command = command;
  try {
    throw;
  } catch (const InputError& x) {
    e.file = x.file();
    e.line = x.line();
    e.reason = x.reason();
  } catch (const CLI::ParseError& x) {
    e.reason = x.what();
    if (e.reason.empty()) e.reason = x.get_name();
  } catch (const std::bad_alloc&) {
    // Not the input's fault: a named failure of this run (exit 1), not bad input.
    e.reason = "out of memory (the input may be fine: give the run more memory or a smaller input)";
    e.exit = kDefect;
  } catch (const std::exception& x) {
    e.reason = x.what();
  } catch (...) {
    e.reason = "unknown error";
  }
  return e;
}

std::string command_path(const CLI::App& app, const std::vector<std::string>& args) {
  std::string path;
  const CLI::App* at = &app;
  for (const auto& a : args) {
    if (!a.empty() && a[0] == '-') continue;
    const CLI::App* sub = nullptr;
    for (const CLI::App* s : at->get_subcommands([](const CLI::App*) { return true; }))
      if (s->check_name(a)) sub = s;
    if (!sub) break;
    path += (path.empty() ? "" : " ") + sub->get_name();
    at = sub;
  }
  return path;
}

bool wants_json(const std::vector<std::string>& args) {
  return std::find(args.begin(), args.end(), "--json") != args.end();
}

}  // namespace dtlab::cli
