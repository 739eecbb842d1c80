// dtlab sample: points on or inside a triangle mesh (chapter 3 of the thesis, plus
// the robust winding-number sampler), with a mesh report and an inside/outside check.
#include <cctype>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "kernel/point_io.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_io.hpp"
#include "sampling/mesh_report.hpp"
#include "sampling/mesh_report_json.hpp"
#include "sampling/mesh_sampler.hpp"
#include "sampling/sample_quality.hpp"

namespace dtlab::cli {

namespace {

struct SampleArgs {
  std::string mesh = "builtin";
  std::string method = "winding";
  std::size_t count = 10000;
  std::uint64_t seed = 1;
  bool blue_noise = false;
  double ratio = 5;
  std::string out;
  bool json = false;
  bool no_check = false;
};

int run_sample(const SampleArgs& a) {
  // Points are written as .node, or as x y z text (.xyz, .txt, .pwn): never text under a mesh extension.
  std::string ext = a.out.substr(std::min(a.out.size(), a.out.find_last_of('.')));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".node" && ext != ".xyz" && ext != ".txt" && ext != ".pwn")
    throw CLI::ValidationError("--out", "'" + a.out + "': sample writes points as .xyz or .node");
  const auto method = parse_sample_method(a.method);
  if (!method) throw CLI::ValidationError("--method", "expected surface, rays, sdf or winding");
  const auto t0 = std::chrono::steady_clock::now();
  const TriangleMesh mesh = a.mesh == "builtin" ? make_bumpy_torus() : read_mesh(a.mesh);
  if (mesh.triangles.empty()) throw InputError(a.mesh, 0, "mesh has no triangles");
  const MeshReport report = analyze_mesh(mesh);
  if (const std::string why = magnitude_problem(report.magnitude, *method == SampleMethod::surface); !why.empty())
    throw InputError(a.mesh, 0, why);
  const auto t1 = std::chrono::steady_clock::now();
  const MeshSampler sampler(mesh);
  SampleRequest req;
  req.method = *method;
  req.count = a.count;
  req.seed = a.seed;
  req.blue_noise = a.blue_noise;
  req.blue_noise_ratio = a.ratio;
  const SampleOutput out = sampler.sample(req);
  const auto t2 = std::chrono::steady_clock::now();
  if (ext == ".node") write_node(a.out, out.points);
  else write_xyz(a.out, out.points);
  const bool volume = *method != SampleMethod::surface;
  OutsideStats outside;
  if (volume && !a.no_check) outside = count_outside(sampler.bvh(), out.points);
  const double sample_s = std::chrono::duration<double>(t2 - t1).count();
  const double load_s = std::chrono::duration<double>(t1 - t0).count();

  if (a.json) {
    nlohmann::json j;
    j["mesh"] = mesh_report_json(report);
    j["mesh"]["file"] = a.mesh;
    j["method"] = a.method;
    j["blue_noise"] = a.blue_noise;
    j["seed"] = a.seed;
    j["requested"] = a.count;
    j["points"] = out.points.size();
    j["candidates"] = out.candidates;
    j["out"] = a.out;
    j["seconds"] = {{"load_and_report", load_s}, {"sample", sample_s}};
    j["samples_per_second"] = sample_s > 0 ? out.points.size() / sample_s : 0.0;
    if (volume && !a.no_check)
      j["outside"] = {{"checked", outside.checked}, {"count", outside.outside}, {"fraction", outside.fraction()}};
    else
      j["outside"] = nullptr;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("mesh %s: %s\n", a.mesh.c_str(), report.summary().c_str());
    for (const auto& p : report.problems()) std::printf("  %s\n", p.c_str());
    std::printf("%s%s: %zu points in %.3f s (%.0f samples/s) -> %s\n", a.method.c_str(),
                a.blue_noise ? " + blue noise" : "", out.points.size(), sample_s,
                sample_s > 0 ? out.points.size() / sample_s : 0.0, a.out.c_str());
    if (volume && !a.no_check)
      std::printf("outside the mesh (winding number): %zu of %zu (%.4f%%)\n", outside.outside, outside.checked,
                  100 * outside.fraction());
  }
  if (out.points.size() < a.count) {
    std::fprintf(stderr, "dtlab sample: only %zu of %zu points after %zu candidates (mesh encloses little volume?)\n",
                 out.points.size(), a.count, out.candidates);
    return kDefect;
  }
  return kOk;
}

}  // namespace

void add_sample_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<SampleArgs>();
  CLI::App* sub = app.add_subcommand("sample", "sample points on and inside a triangle mesh");
  sub->add_option("MESH", args->mesh, "mesh file (.off .obj .ply .stl) or 'builtin' (bumpy torus)")
      ->capture_default_str();
  sub->add_option("--method", args->method, "surface | rays | sdf | winding")
      ->check(CLI::IsMember({"surface", "rays", "sdf", "winding"}))
      ->capture_default_str();
  sub->add_option("--count", args->count, "number of points")->transform(count_in(1, 1 << 30))->capture_default_str();
  sub->add_option("--seed", args->seed, "random seed")->check(seed_value())->capture_default_str();
  sub->add_flag("--blue-noise", args->blue_noise, "weighted sample elimination (Yuksel 2015) over the method");
  sub->add_option("--blue-noise-ratio", args->ratio, "candidates per kept point for --blue-noise")
      ->check(number_in(1, 100))
      ->capture_default_str();
  sub->add_option("--out", args->out, "output points (.xyz or .node)")->type_name("FILE")->required();
  sub->add_flag("--no-check", args->no_check, "skip the winding-number check of the volume samples");
  sub->add_flag("--json", args->json, "print a JSON summary on stdout");
  sub->callback([args, &rc] { rc = run_sample(*args); });
}

}  // namespace dtlab::cli
