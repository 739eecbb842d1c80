#pragma once
// A predicate backend loaded from a shared library with the C ABI of
// predicates/plugin_abi.h: `plugin:PATH` wherever a backend name is taken. One call
// through a function pointer per predicate; the kernel's fused filters (adaptive's
// insphere_sides) are not used, so the plug-in decides every sign.
#include <string>
#include <string_view>

#include "predicates/backend.hpp"
#include "predicates/plugin_abi.h"

namespace dtlab {

inline constexpr std::string_view kPluginPrefix = "plugin:";

struct PluginLibrary {
  std::string path;
  std::string name;  // dtlab_backend_name(), else the file's stem
  dtlab_orient3d_fn orient3d = nullptr;
  dtlab_insphere_fn insphere = nullptr;
};

// Loads PATH once per process (later calls return the same library; it is never
// unloaded). Throws std::invalid_argument with a one-line reason: the file cannot be
// loaded (dlerror's words), or dtlab_orient3d / dtlab_insphere is missing.
const PluginLibrary& load_plugin(const std::string& path);

struct PluginPredicates {
  const PluginLibrary* library = nullptr;

  std::string_view name() const { return library->name; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return sign_of(library->orient3d(&a.x, &b.x, &c.x, &d.x));
  }
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const {
    return sign_of(library->insphere(&a.x, &b.x, &c.x, &d.x, &e.x));
  }

 private:
  static constexpr int sign_of(int v) { return (v > 0) - (v < 0); }
};

static_assert(PredicateBackend<PluginPredicates>);
static_assert(sizeof(Point3) == 3 * sizeof(double), "the ABI passes a Point3 as three doubles");

}  // namespace dtlab
