// SPDX-License-Identifier: MIT
// The workbench's static files (web/dist, installed to share/hulahoops/web),
// served for every path outside /api/: "/" is index.html; a path with a
// '..' or hidden segment, or one that resolves outside the directory
// through a symbolic link, is 404 like a missing file.
#pragma once

#include <filesystem>
#include <string_view>

#include "hula/server/http.hpp"

namespace hula::server {

/// The file at URL path `path` under `root`, with its content type.
/// @throws HttpError(404, "NotFound") when there is no such file (or no root)
[[nodiscard]] Response static_file(const std::filesystem::path& root, std::string_view path);

}  // namespace hula::server
