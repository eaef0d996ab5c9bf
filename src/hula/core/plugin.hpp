// SPDX-License-Identifier: MIT
// Parts of HulaHoops that link a large library (pagmo2, Open CASCADE) are built as plugins,
// shared objects loaded with dlopen the first time they are used, so that a command that never
// uses them does not pay for loading, relocating and initialising those libraries at start-up
// (pagmo's static initialisers alone copy megabytes of benchmark-problem tables).
//
// A plugin `name` is the file libhula_<name>.so, looked for, in order, in:
//   1. $HULA_PLUGIN_DIR, when set;
//   2. the plugin directory of an installation, relative to the binary or shared object holding
//      this code (bin/../lib/hulahoops for the installed `hula`), then, for a shared object, its own
//      directory (the Python package of a wheel ships its plugins beside the module);
//   3. the plugin directory of the configured installation prefix;
//   4. the plugin directory of the build tree (tests and uninstalled binaries).
// A plugin is loaded at most once per process and never unloaded.
#pragma once

#include <string_view>

namespace hula {

/// The address of `symbol` (an extern "C" entry point) in plugin `plugin`, loading it if needed.
/// @param plugin the plugin's name, e.g. "pagmo" for libhula_pagmo.so
/// @param symbol the entry point's unmangled name
/// @returns a non-null address; callers cast it to the entry point's function type
/// @throws hula::Error(Errc::IoError) with where.field = "plugin" if no directory holds a loadable
///   plugin of that name (naming the files tried and the loader's reason) or the plugin lacks the symbol
[[nodiscard]] void* plugin_symbol(std::string_view plugin, std::string_view symbol);

}  // namespace hula
