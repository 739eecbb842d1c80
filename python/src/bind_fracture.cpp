// _core.fracture: Voronoi fracture of a closed mesh given as arrays.
#include <pybind11/stl.h>

#include <cmath>
#include <optional>

#include "fracture/fracture.hpp"
#include "fracture/piece_io.hpp"
#include "fracture/piece_tets.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/progress_callback.hpp"
#include "python/src/triangle_mesh_arrays.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

py::tuple point_tuple(const Point3& p) { return py::make_tuple(p.x, p.y, p.z); }

// The CLI's --sites / --impact / --site-noise (sites=, impact=, site_noise=): site_source "sampler", "mesh-vertices"
// or "points" (then `sites`, an (n, 3) array).
SiteOptions site_options(const std::string& source, py::handle sites, std::optional<std::array<double, 3>> impact,
                         double impact_radius, double site_noise) {
  SiteOptions s;
  if (source == "mesh-vertices") {
    s.source = SiteSource::mesh_vertices;
  } else if (source == "points") {
    s.source = SiteSource::points;
    const DoubleArray a = point_array(sites, "sites");
    const auto pts = points_of(a);
    s.points.assign(pts.begin(), pts.end());
    if (s.points.empty()) throw py::value_error("sites: no points");
  } else if (source != "sampler") {
    throw py::value_error("sites: an (n, 3) array or 'mesh-vertices'");
  }
  if (impact) {
    for (double c : *impact)
      if (!std::isfinite(c)) throw py::value_error("impact: coordinates must be finite");
    if (!(impact_radius > 0 && impact_radius <= 1e300)) throw py::value_error("impact needs impact_radius > 0");
    if (s.source == SiteSource::points)
      throw py::value_error("impact chooses sampled sites or sites='mesh-vertices', not an array of sites");
    s.impact = Point3{(*impact)[0], (*impact)[1], (*impact)[2]};
  }
  s.impact_radius = impact_radius;
  if (!(site_noise >= 0 && site_noise <= 10)) throw py::value_error("site_noise: not in [0 - 10]");
  s.noise = site_noise;
  return s;
}

// The CLI's --tets: every piece through TetGen (without the GIL), the tets into the
// manifest; a TetGen failure or tets off their surface's exact volume raise RuntimeError.
std::vector<PieceTets> piece_tets(const FractureResult& r, const std::string& tetgen, nlohmann::json& manifest) {
  std::vector<PieceTets> tets;
  {
    py::gil_scoped_release nogil;
    TetgenRunOptions to;
    to.binary = tetgen;
    tets = tetrahedralize_pieces(r, to);  // std::runtime_error naming the piece
  }
  add_tets_to_manifest(manifest, tets);
  if (const std::size_t exact = manifest["tets"]["pieces_exact"].get<std::size_t>(); exact != tets.size())
    throw std::runtime_error("tets: the tets of " + std::to_string(tets.size() - exact) +
                             " pieces do not have their surface's exact volume");
  return tets;
}

// {"pieces": [per piece: vertices, faces, cut, cut_tag, volume, centroid, site,
// interior_area, neighbors, parent (with tets: tet_points, tets)], "manifest": `dtlab
// fracture --json`'s manifest}.
py::dict fracture(py::handle vertices, py::handle faces, std::size_t pieces, std::uint64_t seed, double margin,
                  const std::string& sampler, bool blue_noise, unsigned threads,
                  const std::vector<std::size_t>& recurse, std::size_t recurse_pieces, const std::string& site_source,
                  py::handle sites, std::optional<std::array<double, 3>> impact, double impact_radius,
                  double site_noise, bool island_split, std::array<double, 3> cell_scale, double density,
                  bool exact_tiling, bool tets, const std::string& tetgen, const py::object& progress) {
  const auto method = parse_sample_method(sampler);
  if (!method || *method == SampleMethod::surface)
    throw py::value_error("sampler must be rays, sdf or winding (a volume sampler)");
  if (pieces < 1 || pieces > 100000)
    throw py::value_error("pieces: " + std::to_string(pieces) + " not in [1 - 100000]");
  if (recurse_pieces < 1 || recurse_pieces > 10000)
    throw py::value_error("recurse_pieces: " + std::to_string(recurse_pieces) + " not in [1 - 10000]");
  if (!(margin >= 0)) throw py::value_error("margin: must be a non-negative number");
  const TriangleMesh mesh = mesh_from_arrays(vertices, faces);
  FractureOptions o;
  o.pieces = pieces;
  o.sampler = *method;
  o.blue_noise = blue_noise;
  o.seed = seed;
  o.margin = margin;
  o.margin_name = "margin";  // fracture_mesh's refusal of a gap as wide as the mesh
  o.threads = threads;
  o.recurse = recurse;
  o.recurse_pieces = recurse_pieces;
  o.sites = site_options(site_source, sites, impact, impact_radius, site_noise);
  o.island_split = island_split;
  for (double c : cell_scale)
    if (!(c >= 1e-6 && c <= 1e6)) throw py::value_error("cell_scale: every factor must be in [1e-06 - 1e+06]");
  o.cell_scale = {cell_scale[0], cell_scale[1], cell_scale[2]};
  if (!(density > 0 && density <= 1e300)) throw py::value_error("density: must be a positive number");
  o.exact_tiling = exact_tiling;
  if (!progress.is_none()) {
    // Called from the boolean workers, one at a time (fracture/cell_boolean.cpp).
    o.progress = [call = python_callback(progress)](std::size_t done, std::size_t total) {
      call(ProgressEvent{"fracture:booleans", done, total});
    };
  }
  FractureResult r;
  {
    py::gil_scoped_release nogil;
    r = fracture_mesh(mesh, o);  // std::invalid_argument (not closed, ...) -> ValueError
  }
  nlohmann::json manifest = fracture_manifest(r, density);
  std::vector<PieceTets> tet_sets;
  if (tets) tet_sets = piece_tets(r, tetgen, manifest);
  py::dict out;
  out["manifest"] = json_to_python(manifest);
  py::list list;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    Piece& p = r.pieces[i];
    py::dict d;
    if (tets) {
      d["tet_points"] = points_to_numpy(std::move(tet_sets[i].points));
      d["tets"] = to_numpy<std::uint32_t, 4>(std::move(tet_sets[i].tets));
    }
    const std::vector<char>& cut = p.geometry.cut;
    py::array_t<bool> mask(static_cast<py::ssize_t>(cut.size()));
    bool* m = mask.mutable_data();
    for (std::size_t i = 0; i < cut.size(); ++i) m[i] = cut[i] != 0;
    d["cut"] = mask;
    d["cut_tag"] = to_numpy<std::int32_t, 1>(std::move(p.geometry.cut_tag));
    d["vertices"] = points_to_numpy(std::move(p.geometry.mesh.vertices));
    d["faces"] = to_numpy<std::uint32_t, 3>(std::move(p.geometry.mesh.triangles));
    d["volume"] = p.volume;
    d["centroid"] = point_tuple(p.centroid);
    d["site"] = point_tuple(p.site);
    d["interior_area"] = p.interior_area;
    d["neighbors"] = to_numpy<std::uint32_t, 1>(std::move(p.neighbors));
    d["parent"] = p.parent;
    d["site_index"] = p.site_index;
    d["island"] = p.island;
    list.append(d);
  }
  out["pieces"] = list;
  return out;
}

}  // namespace

void bind_fracture(py::module_& m) {
  m.def("fracture", &fracture, py::arg("vertices"), py::arg("faces"), py::arg("pieces"), py::arg("seed"),
        py::arg("margin"), py::arg("sampler"), py::arg("blue_noise"), py::arg("threads"), py::arg("recurse"),
        py::arg("recurse_pieces"), py::arg("site_source") = "sampler", py::arg("sites") = py::none(),
        py::arg("impact") = py::none(), py::arg("impact_radius") = 0.0, py::arg("site_noise") = 0.0,
        py::arg("island_split") = true, py::arg("cell_scale") = std::array<double, 3>{1, 1, 1},
        py::arg("density") = 1.0, py::arg("exact_tiling") = false, py::arg("tets") = false,
        py::arg("tetgen") = "tetgen", py::arg("progress") = py::none(),
        "Voronoi fracture of a closed mesh (see dtlab.fracture).");
}

}  // namespace dtlab::python
