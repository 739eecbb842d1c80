// dtlab mesh check MESH / dtlab mesh repair MESH --out FILE: the one mesh diagnosis
// (sampling/mesh_report) and the repair that `fracture --repair` runs (fracture/mesh_repair).
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "fracture/mesh_repair.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_io.hpp"
#include "sampling/mesh_report_json.hpp"

namespace dtlab::cli {

namespace {
struct MeshArgs {
  std::string mesh, out;
  std::size_t locations = 3;
  bool json = false;
};

TriangleMesh load(const std::string& path) { return path == "builtin" ? make_bumpy_torus() : read_mesh(path); }

void print_report(const std::string& name, const MeshReport& r) {
  std::printf("mesh %s: %s\n", name.c_str(), r.summary().c_str());
  for (const auto& p : r.problems()) std::printf("  %s\n", p.c_str());
  std::printf("  %s\n", r.solid() ? "solid: fracture and booleans accept it"
                                  : "not solid: `dtlab mesh repair` or `fracture --repair` may fix it");
}

int run_check(const MeshArgs& a) {
  const MeshReport r = analyze_mesh(load(a.mesh), a.locations);
  if (a.json) {
    nlohmann::json j = mesh_report_json(r);
    j["file"] = a.mesh;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    print_report(a.mesh, r);
  }
  return r.solid() ? kOk : kDefect;
}

int run_repair(const MeshArgs& a) {
  const RepairResult r = repair_mesh(load(a.mesh));
  // Not repairable: the one error style, its JSON object inside the report.
  const CliError error{"mesh repair", a.mesh, 0, "cannot be repaired into a solid: " + r.after.why_not_solid()};
  if (r.solid() && !a.out.empty()) write_off(a.out, r.mesh);
  if (a.json) {
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& s : r.steps) steps.push_back({{"step", s.what}, {"count", s.count}, {"detail", s.detail}});
    nlohmann::json j = {{"file", a.mesh},
                        {"before", mesh_report_json(r.before)},
                        {"repairs", steps},
                        {"after", mesh_report_json(r.after)},
                        {"solid", r.solid()},
                        {"out", r.solid() ? a.out : ""}};
    if (!r.solid()) j.update(error_json(error));
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    print_report(a.mesh, r.before);
    for (const auto& s : r.steps)
      std::printf("repair: %s: %zu%s%s\n", s.what.c_str(), s.count, s.detail.empty() ? "" : ", ", s.detail.c_str());
    if (r.steps.empty()) std::printf("repair: nothing changed\n");
    std::printf("after: %s\n", r.after.summary().c_str());
    if (r.solid() && !a.out.empty()) std::printf("wrote %s\n", a.out.c_str());
  }
  if (!r.solid()) return report_error(error, false);
  return kOk;
}
}  // namespace

void add_mesh_command(CLI::App& app, int& rc) {
  CLI::App* mesh = app.add_subcommand("mesh", "diagnose or repair a triangle mesh (check | repair)");
  mesh->require_subcommand(1);

  auto c = std::make_shared<MeshArgs>();
  CLI::App* check = mesh->add_subcommand(
      "check", "closed, manifold, oriented, self-intersections, holes, duplicates, degenerate triangles, volume "
               "(exit 0 solid, 1 not)");
  check->add_option("MESH", c->mesh, "mesh (.off .obj .ply .stl) or 'builtin'")->required();
  check->add_option("--locations", c->locations, "locations listed per problem")->transform(count_in(0, 1e9))->capture_default_str();
  check->add_flag("--json", c->json, "the report as JSON on stdout");
  check->callback([c, &rc] { rc = run_check(*c); });

  auto r = std::make_shared<MeshArgs>();
  CLI::App* repair = mesh->add_subcommand(
      "repair", "repair into a solid and write it (exit 2, naming what remains, when it cannot become one)");
  repair->add_option("MESH", r->mesh, "mesh (.off .obj .ply .stl) or 'builtin'")->required();
  repair->add_option("--out", r->out, "repaired mesh (.off)")->type_name("FILE");
  repair->add_flag("--json", r->json, "before, repairs and after as JSON on stdout");
  repair->callback([r, &rc] { rc = run_repair(*r); });
}

}  // namespace dtlab::cli
