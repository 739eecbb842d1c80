// `dtlab oracle INPUT [--against cgal,tetgen] [--predicates NAME] [--perturb sos|none]
// [--json]`: builds our DT, runs the oracles, checks every answer exactly and
// compares them canonically (oracle/compare.hpp).
// Exit 0 when ours is valid and agrees with every valid oracle answer, 1 otherwise,
// 2 on bad input. An oracle that crashes or times out is "no answer", not a failure.
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/input_points.hpp"
#include "kernel/build.hpp"
#include "kernel/point_io.hpp"
#include "oracle/cgal_oracle.hpp"
#include "oracle/check.hpp"
#include "oracle/compare.hpp"
#include "oracle/report_json.hpp"
#include "oracle/tetgen_oracle.hpp"

namespace dtlab::cli {
namespace {

struct Args {
  std::string input;
  std::vector<std::string> against = {"cgal", "tetgen"};
  std::string predicates = "adaptive";
  std::string perturb = "sos";
  std::string tetgen = "tetgen";
  double timeout = 600;
  bool json = false;
};

struct Checked {
  OracleRun run;
  std::optional<CheckReport> report;  // absent when the oracle gave no answer
};

std::string cell_text(const std::vector<std::uint32_t>& c) {
  std::string s = "{";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(c[i]);
  }
  return s + "}";
}

std::string verdict(const Comparison& c) {
  std::ostringstream o;
  if (c.agree()) {
    if (c.general_position) o << "agree (general position: identical tets)";
    else if (c.tets_equal) o << "agree (identical tets; " << c.cells_a << " Delaunay cells)";
    else o << "agree (same Delaunay complex, " << c.cells_a << " cells; tets differ inside cospherical cells)";
  } else {
    o << "DIFFER: " << c.only_a_count << " cells only in the first, " << c.only_b_count << " only in the second";
    if (!c.only_a.empty()) o << "; e.g. first only " << cell_text(c.only_a[0]);
    if (!c.only_b.empty()) o << "; e.g. second only " << cell_text(c.only_b[0]);
  }
  return o.str();
}

void run_oracle(const Args& a, int& rc) {
  const PointFile pf = read_input_points(a.input);
  const auto& pts = pf.points;
  std::vector<Checked> runs;

  PredicateSpec spec;
  spec.backend = a.predicates;
  spec.perturb = a.perturb == "sos";
  const BuildResult built = build_delaunay(pts, spec, BuildOptions{});
  if (built.failure && built.failure->kind == FailureKind::lower_dimensional) {
    // No 3D triangulation to compare (fewer than 4 points, coplanar...): bad input, as for tetra.
    std::fprintf(stderr, "dtlab oracle: %s: %s\n", a.input.c_str(), built.failure->detail.c_str());
    rc = kBadInput;
    return;
  }
  OracleRun ours;
  ours.name = "dtlab";
  ours.mesh = built.mesh;
  ours.duplicates = built.duplicates;
  ours.seconds = built.stats.seconds;
  if (built.failure)
    ours.note = std::string("build failed: ") + failure_name(built.failure->kind) + " " + built.failure->detail;
  runs.push_back({std::move(ours), std::nullopt});
  for (const std::string& name : a.against) {
    if (name == "cgal") runs.push_back({cgal_delaunay(pts), std::nullopt});
    else if (name == "tetgen")
      runs.push_back({tetgen_delaunay(pts, {.binary = a.tetgen, .timeout_s = a.timeout}), std::nullopt});
    else throw CLI::ValidationError("--against", "unknown oracle '" + name + "' (cgal, tetgen)");
  }
  for (Checked& c : runs)
    if (c.run.mesh) c.report = check_tetrahedralization(*c.run.mesh, {.duplicates = c.run.duplicates});

  struct Pair {
    std::size_t i, j;
    Comparison c;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < runs.size(); ++i)
    for (std::size_t j = i + 1; j < runs.size(); ++j)
      if (runs[i].report && runs[j].report)
        pairs.push_back({i, j, compare_canonical(*runs[i].run.mesh, *runs[i].report, *runs[j].run.mesh,
                                                 *runs[j].report)});

  // Ours must be valid and agree with every valid answer; with sos, which is
  // CGAL's perturbation, its tets must equal CGAL's exactly.
  bool ok = runs[0].report && runs[0].report->ok() && !built.failure;
  std::vector<std::string> problems;
  for (const Pair& p : pairs) {
    if (p.i != 0 || !runs[p.j].report->ok()) continue;
    if (!p.c.agree()) ok = false, problems.push_back("differs from " + runs[p.j].run.name);
    if (spec.perturb && runs[p.j].run.name == "cgal" && !p.c.tets_equal)
      ok = false, problems.push_back("tets differ from CGAL's although both use the sos perturbation");
  }
  rc = ok ? kOk : kDefect;

  if (a.json) {
    nlohmann::json j;
    j["input"] = a.input;
    j["points"] = pts.size();
    j["predicates"] = a.predicates;
    j["perturb"] = a.perturb;
    j["ok"] = ok;
    j["problems"] = problems;
    for (const Checked& c : runs) {
      nlohmann::json r;
      r["answered"] = c.run.mesh.has_value();
      r["note"] = c.run.note;
      r["seconds"] = c.run.seconds;
      r["duplicates"] = c.run.duplicates.size();
      if (c.run.mesh) r["tets"] = c.run.mesh->tets.size();
      if (c.report) r["check"] = to_json(*c.report);
      j["runs"][c.run.name] = r;
    }
    for (const Pair& p : pairs) j["comparisons"][runs[p.i].run.name + " vs " + runs[p.j].run.name] = to_json(p.c);
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("%s: %zu points, predicates %s, perturbation %s\n", a.input.c_str(), pts.size(),
              a.predicates.c_str(), a.perturb.c_str());
  for (const Checked& c : runs) {
    std::printf("  %-7s", c.run.name.c_str());
    if (!c.run.mesh) {
      std::printf("no answer (%s)\n", c.run.note.c_str());
      continue;
    }
    std::printf("%10zu tets  %8.3f s  check %.3f s  %s%s%s\n", c.run.mesh->tets.size(), c.run.seconds,
                c.report->stats.seconds, c.report->ok() ? "valid" : "DEFECTS",
                c.run.note.empty() ? "" : "  ", c.run.note.c_str());
    for (const Defect& d : c.report->defects) std::printf("           %s\n", format_defect(d).c_str());
  }
  for (const Pair& p : pairs)
    std::printf("  %s vs %s: %s\n", runs[p.i].run.name.c_str(), runs[p.j].run.name.c_str(), verdict(p.c).c_str());
  for (const auto& s : problems) std::printf("  PROBLEM: dtlab %s\n", s.c_str());
  std::printf("%s\n", ok ? "OK" : "FAILED");
}

}  // namespace

void add_oracle_command(CLI::App& app, int& rc) {
  CLI::App* sub = app.add_subcommand("oracle", "compare against CGAL and TetGen, all checked exactly");
  auto a = std::make_shared<Args>();
  sub->add_option("INPUT", a->input, "point file (.node or .xyz)")->required();
  sub->add_option("--against", a->against, "oracles to run: cgal, tetgen")->delimiter(',');
  sub->add_option("--predicates", a->predicates, "our backend: naive|epsilon|adaptive|exact");
  sub->add_option("--perturb", a->perturb, "symbolic perturbation: sos|none")
      ->check(CLI::IsMember({"sos", "none"}));
  sub->add_option("--tetgen", a->tetgen, "the tetgen binary");
  sub->add_option("--timeout", a->timeout, "seconds before TetGen counts as no answer")->check(number_in(0.001, 1e6));
  sub->add_flag("--json", a->json, "print a JSON summary on stdout");
  sub->callback([a, &rc] { run_oracle(*a, rc); });
}

}  // namespace dtlab::cli
