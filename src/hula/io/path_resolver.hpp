// SPDX-License-Identifier: MIT
// Which files a study (or any document) may name, decided by the caller
// (DESIGN.md io: "a path resolver that decides which files a study may
// read"). The readers never open a path a file names directly: they ask the
// resolver passed in, so the command line can resolve relative names against
// the study file's folder while a server confines them to its workspace.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace hula::io {

/// Turns a file name written in a document into the path to open, or throws hula::Error.
/// @param name the name as written (e.g. the "csv" member of a profile)
/// @param field the JSON path of the member, for messages (e.g. "target.csv")
/// @returns the path to open
using PathResolver = std::function<std::filesystem::path(const std::string& name, std::string_view field)>;

/// The command line's rule: relative names against `base` (the folder of the file that names them),
/// absolute names as written.
/// @throws hula::Error(Errc::InvalidArgument) naming the field for an empty name
[[nodiscard]] PathResolver relative_to(std::filesystem::path base);

/// A server's rule: only relative names that stay inside `workspace` after resolving "." and ".."
/// lexically and every symbolic link of the existing part of the path.
/// @throws hula::Error(Errc::InvalidArgument) naming the field (never the workspace) for an empty
///   or absolute name, or one that leaves the workspace
[[nodiscard]] PathResolver confined_to(std::filesystem::path workspace);

}  // namespace hula::io
