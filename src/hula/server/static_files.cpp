// SPDX-License-Identifier: MIT
// Static files (static_files.hpp).
#include "hula/server/static_files.hpp"

#include "hula/io/atomic_file.hpp"

namespace hula::server {

namespace {

std::string_view content_type(const std::filesystem::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json" || ext == ".map") return "application/json";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".ico") return "image/x-icon";
  if (ext == ".woff2") return "font/woff2";
  if (ext == ".wasm") return "application/wasm";
  if (ext == ".txt") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

[[noreturn]] void not_found(std::string_view path) {
  throw HttpError(404, "NotFound", "no file at " + std::string(path));
}

}  // namespace

Response static_file(const std::filesystem::path& root, std::string_view path) {
  if (root.empty()) not_found(path);
  std::string rel = percent_decode(path);
  if (rel.empty() || rel.back() == '/') rel += "index.html";
  std::filesystem::path p;
  std::string_view rest = rel;
  while (!rest.empty()) {
    const std::size_t slash = rest.find('/');
    const std::string_view segment = rest.substr(0, slash);
    if (!segment.empty()) {
      if (segment.front() == '.' || segment.find('\\') != std::string_view::npos) not_found(path);
      p /= std::string(segment);
    }
    if (slash == std::string_view::npos) break;
    rest.remove_prefix(slash + 1);
  }
  std::error_code ec;
  const std::filesystem::path base = std::filesystem::canonical(root, ec);
  if (ec) not_found(path);
  const std::filesystem::path full = std::filesystem::canonical(base / p, ec);
  if (ec || !std::filesystem::is_regular_file(full, ec)) not_found(path);
  // A symbolic link inside the directory must not lead out of it.
  const std::string b = base.string() + "/";
  if (full.string().compare(0, b.size(), b) != 0) not_found(path);
  Response r;
  try {
    r.body = io::read_text_file(full);
  } catch (const Error&) {
    not_found(path);
  }
  r.content_type = content_type(full);
  return r;
}

}  // namespace hula::server
