#pragma once
// A triangle mesh as numpy arrays, (n, 3) float64 vertices and (m, 3) uint32 faces,
// in both directions (sampling and fracture take either a file or arrays).
#include <pybind11/pybind11.h>

#include "sampling/triangle_mesh.hpp"

namespace dtlab::python {

// Copies and validates: finite vertices, face indices in range, at least one face.
TriangleMesh mesh_from_arrays(pybind11::handle vertices, pybind11::handle faces);
// (vertices, faces), moved into numpy without a copy.
pybind11::tuple mesh_to_arrays(TriangleMesh&& mesh);

}  // namespace dtlab::python
