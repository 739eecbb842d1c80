// `dtlab check PREFIX [--json]`: the exact invariant checker on PREFIX.node and
// PREFIX.ele, as written by dtlab, TetGen or any tool using TetGen's formats.
// Exit 0 when valid (every stage proven, the single cover included), 1 listing each
// defect (`unproven` when a stage could not decide), 2 on unreadable input.
#include <cstdio>
#include <string>

#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "kernel/tet_io.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/report_json.hpp"

namespace dtlab::cli {

void add_check_command(CLI::App& app, int& rc) {
  CLI::App* sub = app.add_subcommand("check", "exact invariant check of a .node/.ele pair");
  struct Args {
    std::string prefix;
    bool json = false;
    std::size_t witnesses = 16;
    bool volume_identity = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("PREFIX", args->prefix, "reads PREFIX.node and PREFIX.ele")->required();
  sub->add_flag("--json", args->json, "print a JSON summary on stdout");
  sub->add_option("--witnesses", args->witnesses, "defects listed per kind (all are counted)")->transform(count_in(0, 1e9))->capture_default_str();
  sub->add_flag("--volume-identity", args->volume_identity,
                "also compare the exact sum of tet volumes with the hull's (a slow cross-check)");
  sub->callback([args, &rc] {
    CheckOptions opt;
    opt.witnesses_per_kind = args->witnesses;
    opt.volume_identity = args->volume_identity;
    const CheckReport r = check_tetrahedralization(read_tetgen(args->prefix), opt);
    if (args->json) {
      nlohmann::json j = to_json(r);
      j["prefix"] = args->prefix;
      std::printf("%s\n", j.dump(2).c_str());
    } else {
      std::printf("%s: %s\n", args->prefix.c_str(), check_headline(r).c_str());
      std::printf("  %s\n", format_stats(r.stats).c_str());
      for (int k = 0; k < kDefectKinds; ++k)
        if (r.counts[k])
          std::printf("  %llu x %s\n", static_cast<unsigned long long>(r.counts[k]),
                      defect_name(static_cast<DefectKind>(k)));
      for (const Defect& d : r.defects) std::printf("  %s\n", format_defect(d).c_str());
    }
    rc = r.ok() ? kOk : kDefect;
  });
}

}  // namespace dtlab::cli
