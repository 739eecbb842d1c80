#pragma once
// The parts of the _core extension module, one per dtlab module; module.cpp calls them.
#include <pybind11/pybind11.h>

namespace dtlab::python {

void bind_tetrahedralize(pybind11::module_& m);
void bind_check(pybind11::module_& m);
void bind_oracle(pybind11::module_& m);
void bind_voronoi(pybind11::module_& m);
void bind_voronoi_check(pybind11::module_& m);
void bind_sampling(pybind11::module_& m);
void bind_fracture(pybind11::module_& m);
void bind_fuzz(pybind11::module_& m);
void bind_spatial(pybind11::module_& m);

}  // namespace dtlab::python
