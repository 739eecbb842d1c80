// dtlab fracture MESH: Voronoi fracture of a closed mesh into closed pieces.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <unordered_set>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/input_points.hpp"
#include "cli/number_options.hpp"
#include "cli/old_outputs.hpp"
#include "cli/progress.hpp"
#include "fracture/piece_gltf.hpp"
#include "fracture/piece_io.hpp"
#include "fracture/render_png.hpp"
#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "oracle/peers/child_process.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_io.hpp"

namespace dtlab::cli {

namespace {
struct FractureArgs {
  std::string mesh = "builtin", out, sampler = "winding", png;
  std::size_t pieces = 20, recurse_pieces = 4;
  std::uint64_t seed = 1;
  double gap = 0, explode = 0.6;
  unsigned threads = 0;
  std::vector<std::size_t> recurse;
  bool blue_noise = false, json = false, repair = false, split = false, quiet = false, vtu = false;
  std::string vtu_format = "binary";
  const CLI::Option* vtu_format_option = nullptr;
  double boolean_seconds = 30;
  std::string sites;                       // FILE | mesh-vertices (default: the sampler)
  std::vector<double> impact, cell_scale;  // X,Y,Z / SX,SY,SZ
  double impact_radius = 0, site_noise = 0, density = 1;
  bool no_island_split = false, surfaces = false, gltf = false, tets = false, exact_tiling = false;
  std::string tetgen = "tetgen";
};

Point3 triple(const std::vector<double>& v, const char* option) {
  if (v.size() != 3) throw UsageError(std::string(option) + " takes three comma-separated numbers");
  return {v[0], v[1], v[2]};
}

// --sites, --impact, --site-noise as the library's SiteOptions.
SiteOptions site_options(const FractureArgs& a) {
  SiteOptions s;
  if (a.sites == "mesh-vertices") {
    s.source = SiteSource::mesh_vertices;
  } else if (!a.sites.empty()) {
    s.source = SiteSource::points;
    s.points = read_input_points(a.sites).points;  // InputError: file:line: reason
    if (s.points.empty()) throw InputError(a.sites, 0, "no sites in the file");
  }
  if (!a.impact.empty()) {
    s.impact = triple(a.impact, "--impact");
    if (!(a.impact_radius > 0)) throw UsageError("--impact needs --impact-radius R > 0");
    if (s.source == SiteSource::points)
      throw UsageError("--impact chooses sampled sites or mesh-vertices, not --sites FILE");
  }
  s.impact_radius = a.impact_radius;
  s.noise = a.site_noise;
  return s;
}

// --tets: every piece through TetGen, into the manifest; false after a one-line message
// when TetGen fails on a piece (a named failure).
bool tetrahedralize(const FractureArgs& a, const FractureResult& r, nlohmann::json& m, std::vector<PieceTets>& tets,
                    Progress& progress) {
  progress.say("tetrahedralizing " + std::to_string(r.pieces.size()) + " pieces (" + a.tetgen + " -pY)");
  try {
    TetgenRunOptions to;
    to.binary = a.tetgen;
    tets = tetrahedralize_pieces(r, to);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "dtlab fracture: %s: --tets: %s\n", a.mesh.c_str(), e.what());
    return false;
  }
  add_tets_to_manifest(m, tets);
  return true;
}

// The library's options from the command line's (fracture_mesh checks --gap against the mesh).
FractureOptions fracture_options(const FractureArgs& a, SampleMethod method) {
  FractureOptions o;
  o.pieces = a.pieces;
  o.sampler = method;
  o.blue_noise = a.blue_noise;
  o.seed = a.seed;
  o.margin = a.gap;
  o.threads = a.threads;
  o.recurse = a.recurse;
  o.recurse_pieces = a.recurse_pieces;
  o.repair = a.repair;
  o.boolean_seconds = a.boolean_seconds;
  o.sites = site_options(a);
  o.island_split = !a.no_island_split;
  o.exact_tiling = a.exact_tiling;
  if (!a.cell_scale.empty()) o.cell_scale = triple(a.cell_scale, "--cell-scale");
  return o;
}

// The manifest's record of the command line, so a run can be repeated from its folder.
nlohmann::json options_json(const FractureArgs& a) {
  nlohmann::json o = {{"pieces", a.pieces},
                      {"sampler", a.sampler},
                      {"seed", a.seed},
                      {"gap", a.gap},
                      {"margin", a.gap},
                      {"blue_noise", a.blue_noise},
                      {"explode", a.explode},
                      {"recurse", a.recurse},
                      {"recurse_pieces", a.recurse_pieces},
                      {"repair", a.repair},
                      {"split", a.split},
                      {"vtu", a.vtu},
                      {"boolean_seconds", a.boolean_seconds},
                      {"sites", a.sites.empty() ? "sampler" : a.sites},
                      {"impact", a.impact},
                      {"impact_radius", a.impact_radius},
                      {"site_noise", a.site_noise},
                      {"island_split", !a.no_island_split},
                      {"cell_scale", a.cell_scale},
                      {"density", a.density}};
  o["exact_tiling"] = a.exact_tiling;
  o["tets"] = a.tets;
  return o;
}

// The files of DIR a fracture run writes, and those of the other options (an earlier
// run's): all removed before the first new one, so that DIR never holds a manifest of one
// run beside pieces of another (cli/old_outputs.hpp). The input mesh is never removed.
// The input files: the mesh and a --sites FILE.
std::vector<std::string> fracture_inputs(const FractureArgs& a) {
  std::vector<std::string> in;
  if (a.mesh != "builtin") in.push_back(a.mesh);
  if (!a.sites.empty() && a.sites != "mesh-vertices") in.push_back(a.sites);
  return in;
}

OutputSet fracture_output_set(const FractureArgs& a, std::size_t pieces) {
  OutputSet set;
  set.inputs = fracture_inputs(a);  // DIR/pieces.obj, a split piece may be the mesh or the sites
  set.written = {a.out + "/pieces.obj", a.out + "/exploded.obj", a.out + "/pieces.mtl", a.out + "/manifest.json",
                 a.out + "/adjacency.txt"};
  for (auto [on, name] :
       {std::pair{a.repair, "/repaired.off"}, std::pair{a.vtu, "/pieces.vtu"}, std::pair{a.surfaces, "/surfaces.vtu"},
        std::pair{a.gltf, "/pieces.gltf"}, std::pair{a.tets, "/tets.vtu"}})
    (on ? set.written : set.others).push_back(a.out + name);
  // Every piece file this run writes, those new to DIR too: each is guarded once placed.
  std::unordered_set<std::string> split;
  if (a.split)
    for (std::size_t i = 0; i < pieces; ++i) {
      set.written.push_back(a.out + "/pieces/" + piece_file_name(i));
      split.insert(set.written.back());
    }
  for (std::string& p : piece_files_in(a.out + "/pieces"))
    if (!split.contains(p)) set.others.push_back(std::move(p));
  return set;
}

// Every file of --out: the pieces (OBJ, and VTU, glTF, split files when asked), the
// manifest and the adjacency list, one line per piece "i: j k l" (for breakable constraints).
void write_fracture_outputs(const FractureArgs& a, const FractureResult& r, nlohmann::json& m,
                            const std::vector<PieceTets>& tets) {
  std::filesystem::create_directories(a.out);
  SetBeingWritten set(fracture_output_set(a, r.pieces.size()), a.quiet);
  write_pieces_obj(a.out + "/pieces.obj", r);
  set.placed();
  write_pieces_obj(a.out + "/exploded.obj", r, a.explode);
  set.placed();
  write_pieces_mtl(a.out + "/pieces.mtl");
  set.placed();
  if (a.repair) write_off(a.out + "/repaired.off", r.input);
  set.placed();
  if (a.vtu) write_pieces_vtu(a.out + "/pieces.vtu", r, parse_vtu_format(a.vtu_format));
  set.placed();
  if (a.surfaces) write_piece_surfaces_vtu(a.out + "/surfaces.vtu", r, parse_vtu_format(a.vtu_format));
  set.placed();
  if (a.gltf) write_pieces_gltf(a.out + "/pieces.gltf", r);
  set.placed();
  if (a.tets) write_piece_tets_vtu(a.out + "/tets.vtu", r, tets, parse_vtu_format(a.vtu_format));
  set.placed();
  if (a.split) {
    std::filesystem::create_directories(a.out + "/pieces");
    m["split_files"] = write_piece_files(a.out + "/pieces", r, [&](const std::string& p) { set.placed(p); });
  }
  write_text_file(a.out + "/manifest.json", m.dump(1) + "\n");
  set.placed();
  OutputFile adjacency(a.out + "/adjacency.txt");
  std::FILE* f = adjacency.get();
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    std::fprintf(f, "%zu:", i);
    for (auto j : r.pieces[i].neighbors) std::fprintf(f, " %u", j);
    std::fputc('\n', f);
  }
  adjacency.close();
  set.done();
}

void print_fracture_summary(const FractureArgs& a, const FractureResult& r, double rel) {
  std::printf("mesh %s: %s\n", a.mesh.c_str(), r.report.summary().c_str());
  for (const auto& p : r.report.problems()) std::printf("  %s\n", p.c_str());
  for (const auto& s : r.repairs)
    std::printf("  repair: %s: %zu%s%s\n", s.what.c_str(), s.count, s.detail.empty() ? "" : ", ", s.detail.c_str());
  std::printf("%s: %zu pieces (%zu booleans, %zu skipped), mesh volume %.12g, relative volume error %.3g\n",
              a.mesh.c_str(), r.pieces.size(), r.booleans, r.skipped, r.mesh_volume, rel);
  if (r.duplicate_sites > 0 || r.sites_without_piece > 0)
    std::printf(
        "  sites: %zu, of which %zu repeat an earlier site (no piece of their own) and %zu have cells that "
        "miss the mesh\n",
        r.sites, r.duplicate_sites, r.sites_without_piece);
  if (!a.out.empty())
    std::printf("wrote %s/{pieces.obj, exploded.obj, pieces.mtl, manifest.json, adjacency.txt%s%s%s%s%s}\n",
                a.out.c_str(), a.split ? ", pieces/piece_NNNN.obj" : "", a.vtu ? ", pieces.vtu" : "",
                a.surfaces ? ", surfaces.vtu" : "", a.gltf ? ", pieces.gltf" : "", a.tets ? ", tets.vtu" : "");
}

// Stages: read the mesh, fracture it, tetrahedralize the pieces (--tets), write, report.
int run_fracture(const FractureArgs& a) {
  if (a.out.empty() && !a.json && a.png.empty())  // never compute without writing
    throw UsageError("nothing to write: give --out DIR (or --json, --png FILE)");
  if (a.vtu_format_option->count() > 0 && !a.vtu && !a.surfaces && !a.tets)
    throw UsageError("--vtu-format needs --vtu, --surfaces or --tets");
  const auto method = parse_sample_method(a.sampler);
  if (!method || *method == SampleMethod::surface)
    throw UsageError("--sampler must be rays, sdf or winding (a volume sampler)");
  // Before the booleans: DIR usable, no output over an input (the pieces' count is not
  // known yet: with --split every existing piece file counts as an output).
  std::vector<std::string> outputs;
  if (!a.out.empty()) {
    check_out_folder(a.out);
    OutputSet set = fracture_output_set(a, 0);  // lists DIR/pieces/ once: its piece files are `others`
    outputs = std::move(set.written);
    const std::string piece_dir = a.out + "/pieces/";
    if (a.split)
      for (std::string& p : set.others)
        if (p.starts_with(piece_dir)) outputs.push_back(std::move(p));
  }
  if (!a.png.empty()) outputs.push_back(a.png);
  refuse_overwriting_inputs(outputs, fracture_inputs(a));
  if (a.tets && !program_found(a.tetgen))  // before the work, not after it
    throw UsageError("--tets: no TetGen program " + a.tetgen + " (give --tetgen FILE)");
  Progress progress("fracture", a.quiet);
  const TriangleMesh mesh = a.mesh == "builtin" ? make_bumpy_torus() : read_mesh(a.mesh);
  FractureOptions o = fracture_options(a, *method);
  o.progress = [&progress](std::size_t done, std::size_t total) { progress.update("booleans", done, total); };
  FractureResult r;
  const std::string source = a.sites.empty()              ? std::to_string(a.pieces) + " " + a.sampler + " sites"
                             : a.sites == "mesh-vertices" ? std::to_string(a.pieces) + " mesh-vertex sites"
                                                          : "the sites of " + a.sites;
  progress.say("fracturing " + a.mesh + " at " + source + " (one boolean per cell, then its islands)");
  try {
    r = fracture_mesh(mesh, o);
  } catch (const std::invalid_argument& e) {
    throw InputError(a.mesh, 0, e.what());
  } catch (const std::runtime_error& e) {  // a named failure of a boolean (time budget)
    std::fprintf(stderr, "dtlab fracture: %s: %s\n", a.mesh.c_str(), e.what());
    return kDefect;
  }
  if (r.pieces.empty()) {  // e.g. a gap wider than every cell: nothing of the mesh is left
    std::fprintf(stderr, "dtlab fracture: %s: no piece is left (--gap %g removes every cell's part of the mesh)\n",
                 a.mesh.c_str(), a.gap);
    return kDefect;
  }
  nlohmann::json m = fracture_manifest(r, a.density);
  std::vector<PieceTets> tets;
  if (a.tets && !tetrahedralize(a, r, m, tets, progress)) return kDefect;
  m["input"] = a.mesh;
  m["options"] = options_json(a);
  if (!a.out.empty()) {
    progress.say("writing " + std::to_string(r.pieces.size()) + " pieces to " + a.out);
    write_fracture_outputs(a, r, m, tets);
  }
  if (!a.png.empty()) write_exploded_png(a.png, r, a.explode);
  const double rel = m["relative_volume_error"].get<double>();
  if (a.json)
    std::printf("%s\n", m.dump(2).c_str());
  else
    print_fracture_summary(a, r, rel);
  if (a.tets && m["tets"]["pieces_exact"].get<std::size_t>() != tets.size()) {
    std::fprintf(stderr,
                 "dtlab fracture: %s: --tets: the tets of %zu pieces do not have their surface's exact volume\n",
                 a.mesh.c_str(), tets.size() - m["tets"]["pieces_exact"].get<std::size_t>());
    return kDefect;
  }
  // With a gap the pieces are meant to lose volume; without one they must tile the mesh.
  return a.gap == 0 && rel > 1e-9 ? kDefect : kOk;
}
}  // namespace

void add_fracture_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<FractureArgs>();
  CLI::App* sub = app.add_subcommand("fracture", "Voronoi fracture of a closed mesh into closed pieces");
  sub->add_option("MESH", args->mesh, "closed mesh (.off .obj .ply .stl) or 'builtin' (bumpy torus)")
      ->capture_default_str();
  sub->add_option("--pieces", args->pieces, "number of Voronoi sites")
      ->transform(count_in(1, 100000))
      ->capture_default_str();
  sub->add_option("--sampler", args->sampler, "site sampler: rays | sdf | winding")->capture_default_str();
  sub->add_flag("--blue-noise", args->blue_noise, "blue-noise sites (weighted sample elimination)");
  sub->add_option("--seed", args->seed, "random seed")->check(seed_value())->capture_default_str();
  sub->add_option("--gap,--margin", args->gap,
                  "gap between neighbouring pieces (mesh units); --margin is the old spelling")
      ->check(number_in(0, 1e300))
      ->capture_default_str();
  sub->add_option("--explode", args->explode, "exploded.obj: move pieces by this times their centroid offset")
      ->check(number_in(0, 1000))
      ->capture_default_str();
  sub->add_option("--recurse", args->recurse, "pieces to fracture again (ids of the first level)")
      ->delimiter(',')
      ->transform(count_in(0, 1e9));
  sub->add_option("--recurse-pieces", args->recurse_pieces, "pieces each --recurse piece is split into")
      ->transform(count_in(1, 10000))
      ->capture_default_str();
  sub->add_option("--threads", args->threads, "threads for the booleans (0: all)")
      ->transform(count_in(0, 1024))
      ->capture_default_str();
  sub->add_flag(
      "--repair", args->repair,
      "repair the mesh first (merge, drop degenerate, orient, stitch, fill holes, resolve self-intersections)");
  sub->add_flag("--split", args->split, "also write one OBJ per piece to OUT/pieces/");
  sub->add_option("--boolean-seconds", args->boolean_seconds,
                  "time budget of one corefinement; past it a named failure, exit 1 (0: none)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub->add_flag("--vtu", args->vtu, "also write OUT/pieces.vtu (a polyhedron cell per piece) for ParaView");
  args->vtu_format_option =
      sub->add_option("--vtu-format", args->vtu_format,
                      "encoding of the .vtu files (--vtu, --surfaces, --tets): binary (base64) | ascii")
          ->check(CLI::IsMember({"binary", "ascii"}))
          ->capture_default_str();
  sub->add_option("--sites", args->sites,
                  "sites from a file (.xyz .node, or a mesh file's vertices) or 'mesh-vertices' (a seeded subset of "
                  "--pieces of them); default: --sampler")
      ->type_name("FILE|mesh-vertices");
  sub->add_option("--impact", args->impact, "cluster the sites around this point (density falls off with distance)")
      ->delimiter(',')
      ->check(number_in(-1e300, 1e300))
      ->type_name("X,Y,Z");
  sub->add_option("--impact-radius", args->impact_radius, "--impact: standard deviation of the fall-off (mesh units)")
      ->check(number_in(0, 1e300))
      ->capture_default_str();
  sub->add_option("--site-noise", args->site_noise, "jitter every site by up to this times the mesh's box diagonal")
      ->check(number_in(0, 10))
      ->capture_default_str();
  sub->add_flag("--no-island-split", args->no_island_split,
                "keep the disconnected chunks of one cell together as one piece (default: one piece per island)");
  sub->add_option("--cell-scale", args->cell_scale, "anisotropic cells: stretch them by these factors (e.g. 1,1,4)")
      ->delimiter(',')
      ->check(number_in(1e-6, 1e6))
      ->type_name("SX,SY,SZ");
  sub->add_flag(
      "--surfaces", args->surfaces,
      "also write OUT/surfaces.vtu: every piece as closed triangles with a 'piece' array (VTK integrates it)");
  sub->add_flag("--gltf", args->gltf,
                "also write OUT/pieces.gltf (glTF 2.0: a node per piece, cut faces a 2nd material)");
  sub->add_flag(
      "--exact-tiling", args->exact_tiling,
      "prove sum(piece volumes) = mesh volume exactly on the unrounded pieces (exact arithmetic; costs time)");
  sub->add_flag("--tets", args->tets,
                "also write OUT/tets.vtu: every piece tetrahedralized (TetGen -pY, surface kept) with a 'piece' array");
  sub->add_option("--tetgen", args->tetgen, "--tets: the TetGen program")->type_name("FILE")->capture_default_str();
  sub->add_option("--density", args->density, "mass density for the manifest's mass and mass_inertia")
      ->check(number_in(1e-300, 1e300))
      ->capture_default_str();
  sub->add_option("--png", args->png, "draw the exploded view (--explode) to this PNG file")->type_name("FILE");
  sub->add_option("--out", args->out, "output folder (pieces.obj, exploded.obj, manifest.json, adjacency.txt)")
      ->type_name("DIR")
      ->check(non_empty_path);
  sub->add_flag("--json", args->json, "print the manifest on stdout");
  sub->add_flag("--quiet", args->quiet, "no progress lines on stderr");
  sub->callback([args, &rc] { rc = run_fracture(*args); });
}

}  // namespace dtlab::cli
