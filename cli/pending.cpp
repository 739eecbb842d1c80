#include <cstdio>

#include "cli/command.hpp"

namespace dtlab::cli {

void add_pending_command(CLI::App& app, int& rc, const char* name, const char* what,
                         const char* issue) {
  CLI::App* sub = app.add_subcommand(name, std::string(what) + " (not implemented yet)");
  sub->allow_extras();
  static bool json = false;
  sub->add_flag("--json", json, "print a JSON summary on stdout");
  sub->callback([&rc, name, issue] {
    std::fprintf(stderr, "dtlab %s: not implemented yet (issue %s)\n", name, issue);
    rc = kBadInput;
  });
}

}  // namespace dtlab::cli
