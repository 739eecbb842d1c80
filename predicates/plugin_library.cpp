#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "predicates/plugin_predicates.hpp"

namespace dtlab {

const PluginLibrary& load_plugin(const std::string& path) {
  static std::mutex lock;
  static std::map<std::string, std::unique_ptr<PluginLibrary>> loaded;
  std::lock_guard<std::mutex> g(lock);
  if (auto it = loaded.find(path); it != loaded.end()) return *it->second;
  if (path.empty()) throw std::invalid_argument("plugin: needs a path (plugin:PATH.so)");
  // dlopen searches the library path for a name without '/': a plug-in is a file.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw std::invalid_argument("plugin " + path + ": cannot load: " + (why ? why : "unknown error"));
  }
  auto lib = std::make_unique<PluginLibrary>();
  lib->path = path;
  lib->orient3d = reinterpret_cast<dtlab_orient3d_fn>(dlsym(handle, "dtlab_orient3d"));
  lib->insphere = reinterpret_cast<dtlab_insphere_fn>(dlsym(handle, "dtlab_insphere"));
  if (!lib->orient3d || !lib->insphere) {
    dlclose(handle);
    throw std::invalid_argument("plugin " + path + ": no symbol " +
                                (lib->orient3d ? "dtlab_insphere" : "dtlab_orient3d") +
                                " (predicates/plugin_abi.h lists what a plug-in exports)");
  }
  const auto name_fn = reinterpret_cast<dtlab_backend_name_fn>(dlsym(handle, "dtlab_backend_name"));
  const char* name = name_fn ? name_fn() : nullptr;
  lib->name = name && *name ? name : std::filesystem::path(path).stem().string();
  return *loaded.emplace(path, std::move(lib)).first->second;
}

}  // namespace dtlab
