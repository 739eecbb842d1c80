// _core.read_mesh, _core.builtin_mesh and _core.sample: the sampling module's mesh
// readers and samplers on numpy arrays.
#include "python/src/bindings.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/triangle_mesh_arrays.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_io.hpp"
#include "sampling/mesh_sampler.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

py::tuple read_mesh_file(const std::string& path) {
  TriangleMesh mesh;
  {
    py::gil_scoped_release nogil;
    mesh = read_mesh(path);  // InputError -> ValueError("file:line: reason")
  }
  return mesh_to_arrays(std::move(mesh));
}

py::tuple builtin_mesh() { return mesh_to_arrays(make_bumpy_torus()); }

// {"points": (k, 3) array, "candidates": points tried}; k < count when the budget ran out.
py::dict sample(py::handle vertices, py::handle faces, std::size_t count, const std::string& method,
                std::uint64_t seed, bool blue_noise, double blue_noise_ratio) {
  const auto m = parse_sample_method(method);
  if (!m) throw py::value_error("method: expected surface, rays, sdf or winding, got '" + method + "'");
  if (count < 1 || count > (1ul << 30))
    throw py::value_error("n: " + std::to_string(count) + " not in [1 - 1073741824]");
  if (!(blue_noise_ratio >= 1 && blue_noise_ratio <= 100)) throw py::value_error("blue_noise_ratio: not in [1 - 100]");
  const TriangleMesh mesh = mesh_from_arrays(vertices, faces);
  SampleRequest req;
  req.method = *m;
  req.count = count;
  req.seed = seed;
  req.blue_noise = blue_noise;
  req.blue_noise_ratio = blue_noise_ratio;
  SampleOutput out;
  {
    py::gil_scoped_release nogil;
    out = MeshSampler(mesh).sample(req);
  }
  py::dict d;
  d["candidates"] = out.candidates;
  d["points"] = points_to_numpy(std::move(out.points));
  return d;
}

}  // namespace

void bind_sampling(py::module_& m) {
  m.def("read_mesh", &read_mesh_file, py::arg("path"), "(vertices, faces) of an OFF, OBJ, PLY or STL file.");
  m.def("builtin_mesh", &builtin_mesh, "(vertices, faces) of the built-in bumpy torus.");
  m.def("sample", &sample, py::arg("vertices"), py::arg("faces"), py::arg("count"), py::arg("method"),
        py::arg("seed"), py::arg("blue_noise"), py::arg("blue_noise_ratio"),
        "Points on or inside a triangle mesh (see dtlab.sample).");
}

}  // namespace dtlab::python
