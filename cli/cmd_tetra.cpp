// dtlab tetra INPUT: the Delaunay tetrahedralization of a point file.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/build_options.hpp"
#include "cli/command.hpp"
#include "cli/input_points.hpp"
#include "cli/tetra_report.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"

namespace dtlab::cli {

namespace {
struct TetraArgs {
  std::string input;
  std::string out;
  bool vtu = false;
  bool json = false;
  KernelArgs kernel;
};

int run_tetra(const TetraArgs& a) {
  const BuildOptions options = a.kernel.build_options();
  PointFile in = read_input_points(a.input);
  BuildResult r = build_delaunay(in.points, a.kernel.predicate_spec(), options);
  if (!a.out.empty()) {
    write_tetgen(a.out, r.mesh);
    if (a.vtu) write_vtu(a.out + ".vtu", r.mesh);
  }
  nlohmann::json j = tetra_summary(r, a.kernel);
  j["input"] = a.input;
  if (!a.out.empty()) j["output"] = a.out;
  if (a.json) {
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    print_tetra_summary(stdout, r, a.input);
    if (!a.out.empty()) std::printf("wrote %s.node, %s.ele%s\n", a.out.c_str(), a.out.c_str(), a.vtu ? ", .vtu" : "");
  }
  if (r.failure && r.failure->kind == FailureKind::lower_dimensional) {
    std::fprintf(stderr, "dtlab tetra: %s: %s\n", a.input.c_str(), r.failure->detail.c_str());
    return kBadInput;
  }
  return r.failure ? kDefect : kOk;
}
}  // namespace

void add_tetra_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<TetraArgs>();
  CLI::App* sub = app.add_subcommand("tetra", "Delaunay tetrahedralization of a point file (.node or .xyz)");
  sub->add_option("INPUT", args->input, "points: .node, .xyz, or the vertices of a mesh (.off .obj .ply .stl)")->required();
  sub->add_option("--out", args->out, "write PREFIX.node and PREFIX.ele (TetGen format)");
  sub->add_flag("--vtu", args->vtu, "also write PREFIX.vtu for ParaView");
  sub->add_flag("--json", args->json, "print a JSON summary on stdout");
  args->kernel.add_to(*sub);
  sub->callback([args, &rc] { rc = run_tetra(*args); });
}

}  // namespace dtlab::cli
