// _core: the compiled half of the `dtlab` Python package. The public API, with its
// result classes and docstrings, is dtlab/__init__.py; this module does the work.
#include "kernel/input_error.hpp"
#include "options/option_error.hpp"
#include "python/src/bindings.hpp"
#include "python/src/parameter_name.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  m.doc() = "dtlab's C++ core (use the `dtlab` package, not this module).";
  // Bad input is a ValueError: a file's "file:line: reason" as the CLI prints it, a bad
  // option value as "name: reason" with the Python parameter's name (the CLI's
  // "--eps-mode" is eps_mode=).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const dtlab::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const dtlab::OptionError& e) {
      const std::string message = dtlab::python::parameter_name(e.option()) + ": " + e.reason();
      PyErr_SetString(PyExc_ValueError, message.c_str());
    }
  });
  m.attr("__version__") = "0.1.0";
  dtlab::python::bind_tetrahedralize(m);
  dtlab::python::bind_check(m);
  dtlab::python::bind_oracle(m);
  dtlab::python::bind_voronoi(m);
  dtlab::python::bind_voronoi_check(m);
  dtlab::python::bind_sampling(m);
  dtlab::python::bind_fracture(m);
  dtlab::python::bind_fuzz(m);
  dtlab::python::bind_spatial(m);
}
