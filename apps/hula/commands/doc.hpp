// SPDX-License-Identifier: MIT
// `hula doc`: the curve document from the command line (doc.cpp).
#pragma once

#include "commands/common.hpp"

namespace hula::cli {

/// `hula doc`: new, add, list, show, set, remove, undo, redo, history, export, import, run, check.
[[nodiscard]] Command add_doc(CLI::App& app);

}  // namespace hula::cli
