// SPDX-License-Identifier: MIT
#include "hula/io/path_resolver.hpp"

#include <system_error>
#include <utility>

#include "hula/core/error.hpp"

namespace hula::io {

namespace {
[[noreturn]] void refuse(std::string_view field, const std::string& why) {
  throw Error(Errc::InvalidArgument, std::string(field) + ": " + why, {.field = std::string(field)});
}
}  // namespace

PathResolver relative_to(std::filesystem::path base) {
  return [base = std::move(base)](const std::string& name, std::string_view field) {
    if (name.empty()) refuse(field, "a file name must not be empty");
    std::filesystem::path p(name);
    return p.is_relative() ? base / p : p;
  };
}

PathResolver confined_to(std::filesystem::path workspace) {
  std::error_code ec;
  std::filesystem::path root = std::filesystem::weakly_canonical(workspace, ec);
  if (ec) root = workspace.lexically_normal();
  return [root = std::move(root)](const std::string& name, std::string_view field) {
    if (name.empty()) refuse(field, "a file name must not be empty");
    const std::filesystem::path p(name);
    if (!p.is_relative() || p.has_root_name()) refuse(field, "\"" + name + "\" is not a relative file name");
    // weakly_canonical resolves the symbolic links of the existing prefix and normalises the rest.
    std::error_code error;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(root / p, error);
    if (error) refuse(field, "\"" + name + "\" cannot be resolved inside the workspace");
    const std::filesystem::path inside = resolved.lexically_relative(root);
    if (inside.empty() || *inside.begin() == "..") refuse(field, "\"" + name + "\" leaves the workspace");
    if (inside == ".") refuse(field, "\"" + name + "\" is the workspace itself, not a file");
    return resolved;
  };
}

}  // namespace hula::io
