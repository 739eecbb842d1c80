// dtlab tetra INPUT: the Delaunay tetrahedralization of a point file. With --check the
// result is verified by the exact checker (exit 1 on a defect); without it, a build
// with a non-robust backend (naive, epsilon) says that it is unverified.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli/build_options.hpp"
#include "cli/command.hpp"
#include "cli/input_points.hpp"
#include "cli/old_outputs.hpp"
#include "cli/tetra_report.hpp"
#include "fuzz/outcome.hpp"
#include "kernel/input_error.hpp"
#include "kernel/input_file.hpp"
#include "kernel/node_reuse.hpp"
#include "kernel/npy_writer.hpp"
#include "kernel/output_file.hpp"
#include "kernel/parallel_for.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/report_json.hpp"

namespace dtlab::cli {

namespace {
struct TetraArgs {
  std::string input;
  std::string out;
  bool vtu = false;
  std::string vtu_format = "binary";
  std::string format = "node";
  bool json = false;
  bool check = false;
  KernelArgs kernel;
};

bool robust_backend(const std::string& predicates) { return predicates == "adaptive" || predicates == "exact"; }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The set of PREFIX: .node/.ele or the .npy pair, and .vtu (cli/old_outputs.hpp).
OutputSet tetra_output_set(const TetraArgs& a) {
  const std::vector<std::string> text{a.out + ".node", a.out + ".ele"}, npy{a.out + ".points.npy", a.out + ".tets.npy"};
  OutputSet set{a.format == "npy" ? npy : text, a.format == "npy" ? text : npy, {a.input}};
  (a.vtu ? set.written : set.others).push_back(a.out + ".vtu");
  return set;
}

// A 0-based input .node already is the output's .node (kernel/node_reuse.hpp): kept when
// it is PREFIX.node, else copied byte for byte.
bool input_node_reusable(const TetraArgs& a, int first_index) {
  // A regular file only: a FIFO's content is gone once read (reopening it blocked for ever).
  return a.format != "npy" && a.input.ends_with(".node") && first_index == 0 && input_file_size(a.input);
}

// Before the build: no output replaces the input, except a reusable input .node.
void refuse_output_over_input(const TetraArgs& a, int first_index) {
  if (a.out.empty()) return;
  const bool node_reused = input_node_reusable(a, first_index);
  std::vector<std::string> outputs;
  for (const std::string& p : tetra_output_set(a).written)
    if (!(node_reused && p == a.out + ".node")) outputs.push_back(p);
  refuse_overwriting_inputs(outputs, {a.input});
}

// The output files; returns what became of PREFIX.node (written, copied, kept).
std::string write_outputs(const TetraArgs& a, const Tetrahedralization& mesh, int first_index) {
  const unsigned threads = a.kernel.threads;
  std::string node = "written";
  SetBeingWritten set(tetra_output_set(a), false);  // the old set first; the input stays
  if (a.format == "npy") {
    write_npy_points(a.out + ".points.npy", mesh.points);
    set.placed();
    write_npy_tets(a.out + ".tets.npy", mesh.tets);
    set.placed();
    node = "none";
  } else {
    const NodeReuse reuse =
        input_node_reusable(a, first_index) ? reuse_node_file(a.input, a.out + ".node") : NodeReuse::none;
    if (reuse == NodeReuse::none) write_node(a.out + ".node", mesh.points, threads);
    set.placed();
    node = reuse == NodeReuse::same_file ? "kept" : reuse == NodeReuse::copied ? "copied" : "written";
    write_ele(a.out + ".ele", mesh.tets, threads);
    set.placed();
  }
  if (a.vtu) write_vtu(a.out + ".vtu", mesh, parse_vtu_format(a.vtu_format));
  set.done();
  return node;
}

int run_tetra(const TetraArgs& a) {
  BuildOptions options = a.kernel.build_options();
  // With --threads, the threaded build's order on any count: `--threads 1` writes what
  // `--threads 2` writes (kernel/build.hpp, canonical_order).
  options.canonical_order = a.kernel.threads_given();
  const auto start = std::chrono::steady_clock::now();
  if (!a.out.empty()) check_out_prefix(a.out);
  PointFile in = read_input_points(a.input);
  refuse_output_over_input(a, in.first_index);
  const double read_seconds = seconds_since(start);
  const auto build_start = std::chrono::steady_clock::now();
  BuildResult r = build_delaunay(std::move(in.points), a.kernel.predicate_spec(), options);
  const double build_seconds = seconds_since(build_start);  // the whole call: order, build, compaction
  // No 3D triangulation (fewer than 4 points, all coplanar): bad input, exit 2.
  // With a non-robust backend that verdict may be the backend's error: bad input only
  // when exact predicates agree (fuzz/outcome.hpp), else a named failure (exit 1).
  if (r.failure && r.failure->kind == FailureKind::lower_dimensional) {
    if (robust_backend(a.kernel.predicates) || fuzz::is_lower_dimensional(r.mesh.points))
      throw InputError(a.input, 0, r.failure->detail);
    r.failure->detail +=
        " by the " + a.kernel.predicates + " predicates, but exact predicates find four affinely independent points";
  }
  const auto write_start = std::chrono::steady_clock::now();
  const std::string node = a.out.empty() ? "" : write_outputs(a, r.mesh, in.first_index);
  const double write_seconds = seconds_since(write_start);
  nlohmann::json j = tetra_summary(r, a.kernel);
  j["read_seconds"] = read_seconds;
  j["build_call_seconds"] = build_seconds;
  j["write_seconds"] = write_seconds;
  j["threads"] = thread_count(a.kernel.threads);
  if (!a.json) print_tetra_summary(stdout, r, a.input);
  // The exact check of a finished build (a failed one is already reported as such).
  // It takes the mesh over (renumbered for speed): nothing below reads r.mesh.
  std::optional<CheckReport> check;
  if (a.check && !r.failure) {
    CheckOptions co;
    co.duplicates = r.duplicates;
    co.witnesses_per_kind = 3;
    co.threads = a.kernel.threads;
    check = check_tetrahedralization(std::move(r.mesh), co);
  }
  j["input"] = a.input;
  if (!a.out.empty()) j["output"] = a.out, j["node_file"] = node;
  j["total_seconds"] = seconds_since(start);
  j["check"] = check ? to_json(*check) : nlohmann::json(nullptr);
  const bool unverified = !r.failure && !check && !robust_backend(a.kernel.predicates);
  j["verified"] = check ? nlohmann::json(check->ok()) : nlohmann::json(nullptr);
  if (a.json) {
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    if (check) print_tetra_check(stdout, *check);
    if (!a.out.empty() && a.format == "npy")
      std::printf("wrote %s.points.npy, %s.tets.npy%s\n", a.out.c_str(), a.out.c_str(), a.vtu ? ", .vtu" : "");
    else if (!a.out.empty())
      std::printf("wrote %s.node%s, %s.ele%s\n", a.out.c_str(),
                  node == "kept" ? " (the input, kept)" : node == "copied" ? " (copied from the input)" : "",
                  a.out.c_str(), a.vtu ? ", .vtu" : "");
  }
  if (unverified)
    std::fprintf(stderr,
                 "dtlab tetra: UNVERIFIED: the %s predicates can give a wrong tetrahedralization; "
                 "verify with --check (or `dtlab check PREFIX` on the --out files)\n",
                 a.kernel.predicates.c_str());
  if (r.failure || (check && !check->ok())) return kDefect;
  return kOk;
}
}  // namespace

void add_tetra_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<TetraArgs>();
  CLI::App* sub = app.add_subcommand("tetra", "Delaunay tetrahedralization of a point file (.node .xyz) or of a mesh file's vertices (.off .obj .ply .stl)");
  sub->add_option("INPUT", args->input, kInputPointsHelp)->required();
  CLI::Option* out = sub->add_option("--out", args->out, "write PREFIX.node and PREFIX.ele (TetGen format)")
                         ->type_name("PREFIX")
                         ->check(non_empty_path);
  sub->add_option("--format", args->format,
                  "node: PREFIX.node/.ele (a 0-based input .node is copied, not rewritten); npy: PREFIX.points.npy "
                  "and PREFIX.tets.npy (NumPy, dtlab's orientation)")
      ->check(CLI::IsMember({"node", "npy"}))
      ->capture_default_str()
      ->needs(out);
  CLI::Option* vtu = sub->add_flag("--vtu", args->vtu, "also write PREFIX.vtu for ParaView")->needs(out);
  sub->add_option("--vtu-format", args->vtu_format, "encoding of the .vtu: binary (base64) | ascii")
      ->check(CLI::IsMember({"binary", "ascii"}))
      ->capture_default_str()
      ->needs(vtu);
  sub->add_flag("--json", args->json, "print a JSON summary on stdout");
  sub->add_flag("--check", args->check,
                "verify the result with the exact checker (as `dtlab check`); exit 1 on a defect");
  args->kernel.add_to(*sub, kAllKernelOptions | kThreadsOption);
  sub->callback([args, &rc] { rc = run_tetra(*args); });
}

}  // namespace dtlab::cli
