// dtlab voronoi INPUT: Voronoi cells of a point file, clipped to a box. A failed
// Delaunay build exits 1 with its named failure (e.g. walk-cycle).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli/build_options.hpp"
#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/input_points.hpp"
#include "cli/number_options.hpp"
#include "cli/old_outputs.hpp"
#include "cli/peer_definitions.hpp"
#include "cli/voronoi_against.hpp"
#include "fracture/render_png.hpp"
#include "kernel/build.hpp"
#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi/voronoi_io.hpp"
#include "voronoi/voronoi_range.hpp"

namespace dtlab::cli {

namespace {
struct VoronoiArgs {
  std::string input, out;
  KernelArgs kernel;
  std::vector<double> box;
  double margin = 0.1;
  unsigned threads = 0;
  const CLI::Option* threads_option = nullptr;
  const CLI::Option* vtu_format_option = nullptr;
  bool no_obj = false, vtu = false, tets = false, json = false, check = false;
  std::string vtu_format = "binary", png;
  double png_shrink = 0.8;
  std::string against = "none";
  double timeout = 600;
  bool quiet = false;
  PeerDefinitionArgs defined;  // --voronoi-peer, --peers
};

// The ranges of voronoi/voronoi_range.hpp, with or without --check (out of range it
// could only report broken cells): sites are bad input, a box out of range bad usage.
void check_voronoi_range(const std::string& input, const std::vector<Point3>& points,
                         const std::optional<vor::Box>& box, double margin) {
  const auto refusal = voronoi_refusal(points, box, margin);
  if (!refusal) return;
  if (refusal->range == VoronoiRefusal::Range::sites) throw InputError(input, 0, refusal->reason);
  throw UsageError(refusal->reason);
}

// --check: each cell's shape and the volumes' sum, into m["check"]; the number of defects.
std::size_t check_cells(const VoronoiDiagram& vd, nlohmann::json& m) {
  std::size_t defects = 0;
  // The exact Voronoi checker's rule: relative tolerances (of the cells' scale,
  // cell_scale) with an ulp floor where the cells are a few ulps of the box's
  // coordinates wide (voronoi/rounding_bound.hpp).
  const double tol = 1e-9 * vd.scale;
  const double vertex_error = cells_rounding_floor(vd, false).vertex_error;
  nlohmann::json bad = nlohmann::json::array();
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    if (vd.cells[i].duplicate_of >= 0) continue;
    if (vd.cells[i].face_count() == 0 && vd.may_be_empty(i)) continue;
    const std::string why = check_cell(vd.cells[i], tol, vertex_error);
    if (!why.empty()) bad.push_back({{"cell", i}, {"defect", why}}), ++defects;
  }
  const double rel = std::abs(m["cell_volume_sum"].get<double>() - vd.box.volume()) / vd.box.volume();
  // The volume floor holds for closed cells only (with a defective cell, 1e-12 alone); it
  // is summed over the cells only when 1e-12 is not met.
  const bool floor_needed = defects == 0 && !(rel <= 1e-12);
  const double volume_tol = floor_needed ? std::max(1e-12, cells_rounding_floor(vd).volume / vd.box.volume()) : 1e-12;
  if (!(rel <= volume_tol)) ++defects;  // a NaN error (overflowing volumes) is a defect too
  m["check"] = {{"defects", bad},
                {"relative_volume_error", rel},
                {"relative_volume_tolerance", volume_tol},
                {"volume_rule", volume_tol > 1e-12 ? "ulps" : "relative"},
                {"vertex_error_floor", vertex_error}};
  return defects;
}

// The set of PREFIX: .obj (unless --no-obj), .json, .vtu, .tets.vtu (cli/old_outputs.hpp).
OutputSet voronoi_output_set(const VoronoiArgs& a) {
  OutputSet set{{a.out + ".json"}, {}, {a.input}};
  for (auto [on, suffix] : {std::pair{!a.no_obj, ".obj"}, std::pair{a.vtu, ".vtu"}, std::pair{a.tets, ".tets.vtu"}})
    (on ? set.written : set.others).push_back(a.out + suffix);
  return set;
}

// Every file the run writes: the set and --png.
std::vector<std::string> voronoi_outputs(const VoronoiArgs& a) {
  std::vector<std::string> files = a.out.empty() ? std::vector<std::string>{} : voronoi_output_set(a).written;
  if (!a.png.empty()) files.push_back(a.png);
  return files;
}

int run_voronoi(const VoronoiArgs& a) {
  const bool obj = !a.no_obj;
  if (a.vtu_format_option->count() > 0 && !a.vtu && !a.tets) throw UsageError("--vtu-format needs --vtu or --tets");
  a.defined.register_all();  // before the cells: a bad definition ends the run at once
  if (!a.out.empty()) check_out_prefix(a.out);
  refuse_overwriting_inputs(voronoi_outputs(a), {a.input});  // before the cells
  PointFile in = read_input_points(a.input);
  if (in.points.empty()) throw InputError(a.input, 0, "no points");
  VoronoiOptions o;
  o.margin = a.margin;
  o.predicates = a.kernel.predicate_spec();
  o.build = a.kernel.build_options();
  o.threads = a.threads;
  // The Delaunay build too, when --threads is given (as in tetra: kernel/README.md).
  const bool threads_given = a.threads_option && a.threads_option->count() > 0;
  o.build.threads = threads_given ? a.threads : 1;
  o.build.canonical_order = threads_given;  // the same tets' order at any N, 1 included
  o.keep_dt = a.against != "none";  // the checker reads the relation from our DT (exact backends only)
  if (!a.box.empty()) {
    if (a.box.size() != 6 || !(a.box[0] < a.box[3] && a.box[1] < a.box[4] && a.box[2] < a.box[5]))
      throw UsageError("--box needs xmin ymin zmin xmax ymax zmax with min < max");
    o.box = vor::Box{{a.box[0], a.box[1], a.box[2]}, {a.box[3], a.box[4], a.box[5]}};
  }
  check_voronoi_range(a.input, in.points, o.box, o.margin);
  std::optional<VoronoiDiagram> built;
  try {
    built = compute_voronoi(in.points, o);
  } catch (const UnrepresentableCell& e) {
    throw InputError(a.input, 0, e.what());
  } catch (const std::runtime_error&) {
    // compute_voronoi reports a failed Delaunay build as an error without its kind;
    // the same build (deterministic, the same options, as compute_voronoi runs it)
    // names it, and a failed build is a defect (exit 1), as in `dtlab tetra`.
    const BuildResult r = build_delaunay(in.points, o.predicates, o.build);
    if (!r.failure || r.failure->kind == FailureKind::lower_dimensional) throw;
    std::fprintf(stderr, "dtlab voronoi: %s: Delaunay build failed: %s while inserting point %lld: %s\n",
                 a.input.c_str(), failure_name(r.failure->kind), static_cast<long long>(r.failure->point),
                 r.failure->detail.c_str());
    return kDefect;
  }
  const VoronoiDiagram& vd = *built;
  // Without --check (which reports them as defects, exit 1) lost cells are never written.
  if (const std::string why = a.check ? "" : lost_cells_problem(vd); !why.empty()) throw InputError(a.input, 0, why);
  nlohmann::json m = cells_manifest(vd);
  m["input"] = a.input;
  m["timing"] = {{"seconds_delaunay", vd.seconds_dt},
                 {"seconds_cells", vd.seconds_cells},
                 {"clipped_cells", vd.clipped},
                 {"exact_clipped_cells", vd.exact_clipped},
                 {"box_clipped_cells", vd.box_clipped}};
  const std::size_t defects = a.check ? check_cells(vd, m) : 0;
  int peers_rc = kOk;
  if (const auto peers = parse_voronoi_peers(a.against); !peers.empty() || a.against != "none") {
    try {
      peers_rc = judge_voronoi_peers(in.points, vd, {peers, a.timeout, a.quiet}, a.json, m);
    } catch (const std::invalid_argument& e) {
      throw InputError(a.input, 0, e.what());  // no 3D Delaunay complex to judge against
    }
  }
  if (!a.out.empty()) {
    SetBeingWritten set(voronoi_output_set(a), a.quiet);  // the old set first, never the input
    if (obj) write_cells_obj(a.out + ".obj", vd);
    set.placed();
    if (a.vtu) write_cells_vtu(a.out + ".vtu", vd, parse_vtu_format(a.vtu_format));
    set.placed();
    if (a.tets) write_cells_tets_vtu(a.out + ".tets.vtu", vd, parse_vtu_format(a.vtu_format));
    set.placed();
    write_text_file(a.out + ".json", m.dump(1) + "\n");
    set.done();
  }
  if (!a.png.empty()) write_cells_png(a.png, vd, a.png_shrink);
  if (a.json) {
    std::printf("%s\n", m.dump(2).c_str());
  } else {
    std::printf("%s: %zu cells, box volume %.17g, cell volume sum %.17g\n", a.input.c_str(), vd.cells.size(),
                vd.box.volume(), m["cell_volume_sum"].get<double>());
    if (a.check) {
      std::printf("check: %zu defect(s)\n", defects);
      const auto& bad = m["check"]["defects"];
      for (std::size_t k = 0; k < bad.size() && k < 20; ++k)
        std::printf("  cell %zu: %s\n", bad[k]["cell"].get<std::size_t>(), bad[k]["defect"].get<std::string>().c_str());
      if (bad.size() > 20) std::printf("  ... %zu more in the --json manifest\n", bad.size() - 20);
      const double rel = m["check"]["relative_volume_error"].get<double>();
      const double volume_tol = m["check"]["relative_volume_tolerance"].get<double>();
      if (!(rel <= volume_tol))
        std::printf("  cell volumes sum to the box volume within %.3g (relative), more than %.3g\n", rel, volume_tol);
      else if (volume_tol > 1e-12)
        std::printf("  cell volumes within %.3g of the box volume (relative): the ulp floor (%.3g) applies\n", rel,
                    volume_tol);
    }
    if (!a.out.empty())
      std::printf("wrote %s.json%s%s%s\n", a.out.c_str(), obj ? ", .obj" : "", a.vtu ? ", .vtu" : "",
                  a.tets ? ", .tets.vtu" : "");
    if (!a.png.empty()) std::printf("wrote %s\n", a.png.c_str());
  }
  return defects ? kDefect : peers_rc;
}
}  // namespace

void add_voronoi_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<VoronoiArgs>();
  CLI::App* sub = app.add_subcommand("voronoi", "Voronoi cells of a point file, clipped to a box");
  sub->add_option("INPUT", args->input, kInputPointsHelp)->required();
  CLI::Option* out = sub->add_option("--out", args->out, "write PREFIX.obj (a group per cell), PREFIX.json (manifest)")
                         ->type_name("PREFIX")
                         ->check(non_empty_path);
  sub->add_option("--box", args->box,
                  "clip box: xmin ymin zmin xmax ymax zmax (default: bounding box grown by --margin)")
      ->expected(6)
      ->check(number_in(-1e101, 1e101));
  sub->add_option("--margin", args->margin, "default box growth per side, relative to the extent")->check(number_in(0, 1e6))->capture_default_str();
  args->threads_option = sub->add_option("--threads", args->threads,
                                         "threads for the cells, and for the Delaunay build when given (0: all)")
                             ->transform(count_in(0, 1024))
                             ->capture_default_str();
  sub->add_flag("--vtu", args->vtu, "also write PREFIX.vtu (polyhedron cells) for ParaView")->needs(out);
  sub->add_flag("--tets", args->tets,
                "also write PREFIX.tets.vtu: every cell as tetrahedra (cell data site, cell_volume), which VTK "
                "integrates exactly")
      ->needs(out);
  args->vtu_format_option =
      sub->add_option("--vtu-format", args->vtu_format, "encoding of the .vtu (--vtu, --tets): binary (base64) | ascii")
          ->check(CLI::IsMember({"binary", "ascii"}))
          ->capture_default_str()
          ->needs(out);
  CLI::Option* png = sub->add_option("--png", args->png,
                                     "draw the cells (each shrunk about its centroid, own colour) to this PNG file")
                         ->type_name("FILE");
  sub->add_option("--png-shrink", args->png_shrink, "--png: scale of each cell about its centroid")
      ->check(number_in(0.05, 1))
      ->capture_default_str()
      ->needs(png);
  sub->add_flag("--no-obj", args->no_obj, "do not write PREFIX.obj");
  sub->add_flag("--check", args->check, "check every cell (closed, convex, Euler 2) and the volume sum; exit 1 on a defect");
  sub->add_option(
         "--against", args->against,
         "Voronoi peers to judge with the exact checker, clipped to the same box: none, all, or a comma list of "
         "voro++, scipy-voronoi, qvoronoi, cgal-dual, dtlab:naive|epsilon|adaptive|exact, or a --voronoi-peer")
      ->capture_default_str();
  args->defined.add_to(*sub, "--peers", PeerKinds::voronoi);
  sub->add_option("--timeout", args->timeout, "seconds before a peer counts as hung")->check(number_in(0.001, 1e6))->capture_default_str();
  sub->add_flag("--quiet", args->quiet, "no progress lines");
  sub->add_flag("--json", args->json, "print the manifest on stdout (with --against: also exact_check and peers)");
  // How the Delaunay build runs, as in tetra (the cells need the infinite boundary).
  args->kernel.add_to(*sub, kAllKernelOptions & ~kBoundaryOption);
  sub->callback([args, &rc] { rc = run_voronoi(*args); });
}

}  // namespace dtlab::cli
