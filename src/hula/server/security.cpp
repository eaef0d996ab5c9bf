// SPDX-License-Identifier: MIT
// The request middleware and its pieces (security.hpp).
#include "hula/server/security.hpp"

#include <sys/random.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>

#include "hula/io/atomic_file.hpp"

namespace hula::server {

namespace {

constexpr std::string_view kApiPrefix = "/api/";
constexpr std::string_view kDocumentsPrefix = "/api/documents/";
constexpr std::size_t kMinTokenLength = 32;

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r' || s.front() == '\n'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

// The value of the token cookie in a Cookie header ("a=1; hula_token=...; b=2").
std::optional<std::string_view> cookie_token(std::string_view header) noexcept {
  while (!header.empty()) {
    const std::size_t semi = header.find(';');
    const std::string_view pair = trim(header.substr(0, semi));
    const std::size_t eq = pair.find('=');
    if (eq != std::string_view::npos && pair.substr(0, eq) == kTokenCookie) return pair.substr(eq + 1);
    if (semi == std::string_view::npos) break;
    header.remove_prefix(semi + 1);
  }
  return std::nullopt;
}

bool host_allowed(std::string_view host, const SecurityPolicy& policy) noexcept {
  for (const std::string& h : policy.allowed_hosts)
    if (host.size() == h.size() && std::equal(host.begin(), host.end(), h.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
        }))
      return true;
  return false;
}

bool origin_allowed(std::string_view origin, const SecurityPolicy& policy) noexcept {
  constexpr std::string_view kScheme = "http://";
  if (!origin.starts_with(kScheme)) return false;
  return host_allowed(origin.substr(kScheme.size()), policy);
}

// The credentials of "Authorization: Bearer TOKEN": the scheme is case-insensitive (RFC 7235 2.1) and
// separated from the token by one or more spaces.
std::optional<std::string_view> bearer_token(std::string_view header) noexcept {
  constexpr std::string_view kBearer = "bearer";
  if (header.size() <= kBearer.size() || header[kBearer.size()] != ' ') return std::nullopt;
  for (std::size_t i = 0; i < kBearer.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(header[i])) != kBearer[i]) return std::nullopt;
  return trim(header.substr(kBearer.size()));
}

bool has_token(const RequestHead& head, const SecurityPolicy& policy) noexcept {
  if (head.authorization)
    if (const auto token = bearer_token(*head.authorization)) return constant_time_equal(*token, policy.token);
  if (head.cookie)
    if (const auto value = cookie_token(*head.cookie)) return constant_time_equal(*value, policy.token);
  return false;
}

}  // namespace

std::vector<std::string> allowed_hosts(std::string_view bound_host, unsigned port) {
  const std::string p = ":" + std::to_string(port);
  std::vector<std::string> hosts = {"127.0.0.1" + p, "localhost" + p, "[::1]" + p};
  if (bound_host != "127.0.0.1" && bound_host != "::1" && bound_host != "localhost" && !bound_host.empty()) {
    const bool v6 = bound_host.find(':') != std::string_view::npos;
    hosts.push_back(v6 ? "[" + std::string(bound_host) + "]" + p : std::string(bound_host) + p);
  }
  return hosts;
}

bool constant_time_equal(std::string_view a, std::string_view b) noexcept {
  // Every byte of the longer string is visited; the result is folded without branches.
  const std::size_t n = std::max(a.size(), b.size());
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char x = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const unsigned char y = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    diff = static_cast<unsigned char>(diff | (x ^ y));
  }
  return diff == 0;
}

bool token_matches(std::string_view candidate, const SecurityPolicy& policy) noexcept {
  return constant_time_equal(candidate, policy.token);
}

std::optional<HttpError> check_request(const RequestHead& head, const SecurityPolicy& policy) {
  if (head.target.size() > policy.max_target)
    return HttpError(414, "UriTooLong",
                     "the request target has " + std::to_string(head.target.size()) +
                         " bytes, more than the limit of " + std::to_string(policy.max_target));
  // RFC 7230 5.4: a request with more than one Host header is answered 400 (which one is "the" host
  // is ambiguous between proxies and this server).
  if (head.host_count > 1)
    return HttpError(400, "BadRequest",
                     "the request has " + std::to_string(head.host_count) + " Host headers (exactly one is allowed)");
  if (!head.host || !host_allowed(*head.host, policy))
    return HttpError(403, "ForbiddenHost",
                     head.host ? "Host '" + std::string(*head.host) + "' is not this server (DNS rebinding guard)"
                               : std::string("the request has no Host header"));
  if (head.origin && !origin_allowed(*head.origin, policy))
    return HttpError(403, "ForbiddenOrigin",
                     "Origin '" + std::string(*head.origin) + "' is not this server (cross-site requests are refused)");
  if (head.content_length && *head.content_length > policy.max_body)
    return HttpError(413, "PayloadTooLarge",
                     "the request body declares " + std::to_string(*head.content_length) +
                         " bytes, more than the limit of " + std::to_string(policy.max_body));
  const std::string_view path = head.target.substr(0, head.target.find('?'));
  if (path.starts_with(kApiPrefix) && !(head.method == "GET" && path == "/api/health") && !has_token(head, policy))
    return HttpError(401, "Unauthorized",
                     "missing or wrong token: send 'Authorization: Bearer TOKEN' or open the server's URL with "
                     "?token=TOKEN first");
  if (path.starts_with(kDocumentsPrefix)) {
    std::string_view rest = path.substr(kDocumentsPrefix.size());
    rest = rest.substr(0, rest.find('/'));
    try {
      validate_document_name(percent_decode(rest));
    } catch (const Error& e) {
      Json where = Json::object();
      where["field"] = "name";
      return HttpError(400, std::string(errc_name(e.code())), e.message(), where);
    }
  }
  return std::nullopt;
}

std::string generate_token() {
  std::array<unsigned char, 32> bytes{};
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    const ssize_t n = ::getrandom(bytes.data() + filled, bytes.size() - filled, 0);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw Error(Errc::IoError, std::string("cannot draw a random token: getrandom failed: ") + std::strerror(errno));
    }
    filled += static_cast<std::size_t>(n);
  }
  constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const unsigned char b : bytes) {
    out.push_back(kHex[b >> 4]);
    out.push_back(kHex[b & 15]);
  }
  return out;
}

std::string read_token_file(const std::filesystem::path& path) {
  // A regular file (or -) of at most kMaxTokenFileBytes: a FIFO or device is refused before it can
  // block or stream without end (io::read_text_file).
  std::string text;
  try {
    text = io::read_text_file(path, kMaxTokenFileBytes);
  } catch (const Error& e) {
    throw Error(Errc::IoError, "the token file: " + e.message(), ErrorWhere{.field = "token-file"});
  }
  const std::string token(trim(std::string_view(text).substr(0, text.find('\n'))));
  if (token.size() < kMinTokenLength)
    throw Error(Errc::InvalidArgument,
                "the token in '" + path.string() + "' has " + std::to_string(token.size()) +
                    " characters, fewer than " + std::to_string(kMinTokenLength),
                ErrorWhere{.field = "token-file"});
  for (std::size_t i = 0; i < token.size(); ++i) {
    const char c = token[i];
    if (c <= ' ' || c > '~' || c == ';' || c == ',')
      throw Error(Errc::InvalidArgument,
                  "the token in '" + path.string() + "' has a space, control, ';' or ',' character at offset " +
                      std::to_string(i),
                  ErrorWhere{.field = "token-file", .index = i});
  }
  return token;
}

namespace {

// The plain-file-name rules shared by documents and workspace files; refuse(why) throws.
template <class Refuse>
void check_plain_name(std::string_view name, const Refuse& refuse) {
  if (name.empty()) refuse("is empty");
  if (name.size() > 255) refuse("is longer than 255 bytes");
  if (name.front() == '/') refuse("is an absolute path: give a plain file name inside the workspace");
  if (name == "." || name == "..") refuse("is not a file name");
  if (name.find("..") != std::string_view::npos) refuse("holds '..': documents live directly in the workspace");
  for (const char c : name) {
    if (c == '/' || c == '\\') refuse("holds a path separator: give a plain file name inside the workspace");
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) refuse("holds a control character");
  }
  if (name.front() == '.') refuse("starts with '.' (hidden files are not documents)");
}

}  // namespace

void validate_document_name(std::string_view name) {
  const auto refuse = [&](const std::string& why) {
    throw Error(Errc::InvalidArgument, "document name '" + std::string(name) + "' " + why, ErrorWhere{.field = "name"});
  };
  check_plain_name(name, refuse);
  if (!name.ends_with(".hula") || name.size() == 5) refuse("does not end in '.hula'");
}

std::filesystem::path workspace_file_path(const std::filesystem::path& workspace, std::string_view name,
                                          const char* field) {
  const auto refuse = [&](const std::string& why) {
    throw Error(Errc::InvalidArgument, "file name '" + std::string(name) + "' " + why, ErrorWhere{.field = field});
  };
  check_plain_name(name, refuse);
  std::filesystem::path p = workspace / std::string(name);
  std::error_code ec;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec)))
    refuse("is a symbolic link (it could lead out of the workspace)");
  return p;
}

std::filesystem::path document_path(const std::filesystem::path& workspace, std::string_view name) {
  validate_document_name(name);
  std::filesystem::path p = workspace / std::string(name);
  std::error_code ec;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec)))
    throw Error(Errc::InvalidArgument,
                "document name '" + std::string(name) + "' is a symbolic link (it could lead out of the workspace)",
                ErrorWhere{.field = "name"});
  return p;
}

}  // namespace hula::server
