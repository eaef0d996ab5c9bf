// SPDX-License-Identifier: MIT
#include "hula/core/plugin.hpp"

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "hula/core/error.hpp"

// The directories compiled in by CMake (src/hula/core/CMakeLists.txt).
#ifndef HULA_PLUGIN_RELATIVE_DIR
#define HULA_PLUGIN_RELATIVE_DIR "../lib/hulahoops"
#endif
#ifndef HULA_PLUGIN_INSTALL_DIR
#define HULA_PLUGIN_INSTALL_DIR ""
#endif
#ifndef HULA_PLUGIN_BUILD_DIR
#define HULA_PLUGIN_BUILD_DIR ""
#endif

namespace hula {
namespace {

// The directories to look in, in the order of plugin.hpp.
std::vector<std::filesystem::path> plugin_dirs() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("HULA_PLUGIN_DIR"); env != nullptr && *env != '\0') dirs.emplace_back(env);
  // The file holding this code: the executable (its link map has no name) or a shared object (the
  // Python module). The executable's own path comes from /proc, not from argv[0].
  Dl_info self{};
  link_map* map = nullptr;
  if (::dladdr1(reinterpret_cast<void*>(&plugin_symbol), &self, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) != 0) {
    const bool executable = map == nullptr || map->l_name == nullptr || *map->l_name == '\0';
    std::error_code ec;
    const std::filesystem::path object =
        std::filesystem::canonical(executable ? std::filesystem::path("/proc/self/exe") : map->l_name, ec);
    if (!ec) {
      dirs.push_back(object.parent_path() / HULA_PLUGIN_RELATIVE_DIR);
      if (!executable) dirs.push_back(object.parent_path());  // a wheel's plugins lie beside its module
    }
  }
  if (*HULA_PLUGIN_INSTALL_DIR != '\0') dirs.emplace_back(HULA_PLUGIN_INSTALL_DIR);
  if (*HULA_PLUGIN_BUILD_DIR != '\0') dirs.emplace_back(HULA_PLUGIN_BUILD_DIR);
  return dirs;
}

// dlopen and dlerror are not required to be thread-safe together: one load at a time.
std::mutex& load_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

void* plugin_symbol(std::string_view plugin, std::string_view symbol) {
  const std::string file = "libhula_" + std::string(plugin) + ".so";
  const std::lock_guard lock(load_mutex());
  std::string tried;
  for (const auto& dir : plugin_dirs()) {
    const std::filesystem::path path = dir / file;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      continue;
    }
    // RTLD_LOCAL: the plugin's libraries stay out of the global namespace; loaded once, never closed.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = ::dlerror();
      throw Error(Errc::IoError,
                  "plugin " + path.string() + " cannot be loaded: " + (why != nullptr ? why : "unknown reason"),
                  {.field = "plugin"});
    }
    ::dlerror();
    void* address = ::dlsym(handle, std::string(symbol).c_str());
    if (address == nullptr)
      throw Error(Errc::IoError, "plugin " + path.string() + " has no entry point " + std::string(symbol),
                  {.field = "plugin"});
    return address;
  }
  throw Error(Errc::IoError,
              "the " + std::string(plugin) + " plugin " + file + " is not installed (looked for " + tried +
                  "; HULA_PLUGIN_DIR names another directory)",
              {.field = "plugin"});
}

}  // namespace hula
