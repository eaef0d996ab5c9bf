// SPDX-License-Identifier: MIT
// The security layer of `hula serve`, run on every request before any route
// (docs/server.md "Threat model"). A local server is reachable by every page
// the user's browser opens, so the threats are DNS rebinding (a foreign
// page's host name resolving to 127.0.0.1: refused by the Host allow-list),
// cross-site requests (refused by the Origin check and by the token, which a
// foreign page cannot read: it is sent as a Bearer header or an HttpOnly
// SameSite=Strict cookie) and resource exhaustion (size, depth, time and
// connection caps, in server.cpp and http.cpp). Document names are confined
// to the workspace by document_path().
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hula/server/http.hpp"

namespace hula::server {

/// Name of the cookie that carries the token.
inline constexpr std::string_view kTokenCookie = "hula_token";

/// What the middleware checks a request against.
struct SecurityPolicy {
  /// The access token (64 hex digits when generated).
  std::string token{};
  /// Host header values accepted: "127.0.0.1:PORT", "localhost:PORT", "[::1]:PORT" and, when the
  /// server binds another address, that address with the port.
  std::vector<std::string> allowed_hosts{};
  /// Longest request target (path and query) in bytes; longer → 414.
  std::size_t max_target = 8 * 1024;
  /// Largest request body in bytes; a larger Content-Length → 413 before the body is read.
  std::uint64_t max_body = 64ull * 1024 * 1024;
};

/// The request line and the headers the middleware reads.
struct RequestHead {
  std::string_view method{};
  std::string_view target{};
  std::optional<std::string_view> host{};
  /// How many Host headers the request has (more than one is refused, 400).
  std::size_t host_count = 1;
  std::optional<std::string_view> origin{};
  std::optional<std::string_view> authorization{};
  std::optional<std::string_view> cookie{};
  std::optional<std::uint64_t> content_length{};
};

/// The allowed Host values for a server listening on `port` (and on `bound_host` when it is not a
/// loopback address).
[[nodiscard]] std::vector<std::string> allowed_hosts(std::string_view bound_host, unsigned port);

/// Checks a request head in this order: target length (414), a duplicate Host header (400), Host
/// (403), Origin (403), body
/// length (413), token on /api/ routes other than GET /api/health (401), and the document name in
/// /api/documents/{name} paths (400).
/// @returns the refusal, or nothing when the request may reach the router
[[nodiscard]] std::optional<HttpError> check_request(const RequestHead& head, const SecurityPolicy& policy);

/// True when the token of `?token=` in the target equals the policy's (used by GET /?token=).
[[nodiscard]] bool token_matches(std::string_view candidate, const SecurityPolicy& policy) noexcept;

/// Compares two strings in time that depends only on their lengths.
[[nodiscard]] bool constant_time_equal(std::string_view a, std::string_view b) noexcept;

/// 256 random bits from the kernel (getrandom), as 64 lower-case hex digits.
/// @throws hula::Error(Errc::IoError) if the kernel has no randomness to give
[[nodiscard]] std::string generate_token();

/// Largest token file read (a token is one line of tens of characters).
inline constexpr std::size_t kMaxTokenFileBytes = 4096;

/// Reads a token from the first line of a file (surrounding white space removed).
/// @throws hula::Error(Errc::IoError) if the file cannot be read, is not a regular file (a FIFO or a
///   device such as /dev/zero is refused without reading it) or is longer than kMaxTokenFileBytes
/// @throws hula::Error(Errc::InvalidArgument) if the token has fewer than 32 characters or holds
///   characters outside printable ASCII without spaces and ';', ',' (which would break the cookie)
[[nodiscard]] std::string read_token_file(const std::filesystem::path& path);

/// Refuses a document name that is not a plain file name: empty, longer than 255 bytes, ".", "..",
/// starting with '.', holding '/', '\\', a control character, or not ending in ".hula".
/// @throws hula::Error(Errc::InvalidArgument) naming the document and the rule, field "name"
void validate_document_name(std::string_view name);

/// The path of a document inside the workspace, after validate_document_name, refusing a name that
/// is a symbolic link (it could lead out of the workspace).
/// @throws hula::Error(Errc::InvalidArgument) as validate_document_name, or for a symbolic link
[[nodiscard]] std::filesystem::path document_path(const std::filesystem::path& workspace, std::string_view name);

/// The path of a file the API reads from the workspace (an import): a plain file name as for
/// documents (no separators, no "..", not hidden, not absolute), any extension, not a symbolic link.
/// @throws hula::Error(Errc::InvalidArgument) naming the file and the rule, with where.field = field
[[nodiscard]] std::filesystem::path workspace_file_path(const std::filesystem::path& workspace, std::string_view name,
                                                        const char* field);

}  // namespace hula::server
