#pragma once
// nlohmann::json -> Python objects (dict, list, int, float, str, bool, None), so the
// Python API returns the same summaries as the CLI's --json.
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace dtlab::python {

pybind11::object json_to_python(const nlohmann::json& j);

}  // namespace dtlab::python
