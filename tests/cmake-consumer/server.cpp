// SPDX-License-Identifier: MIT
// HulaHoops::server alone (Boost and Threads reached through the package): a server on a free port
// answers GET /api/health with the version it was given, and refuses a document listing without
// the token (401), over a plain socket.
#include "hula/server/server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

namespace {
// One request on a new connection; returns the response once its headers and Content-Length bytes of
// body are in (the server may keep the connection open).
std::string get(unsigned port, const std::string& target) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string response;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0) {
    const std::string request =
        "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nConnection: close\r\n\r\n";
    if (::send(fd, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size())) {
      char buffer[4096];
      for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) {
        response.append(buffer, static_cast<std::size_t>(n));
        const std::size_t head = response.find("\r\n\r\n");
        const std::size_t length = response.find("Content-Length: ");
        if (head != std::string::npos && length != std::string::npos && length < head &&
            response.size() >= head + 4 + std::stoul(response.substr(length + 16)))
          break;
      }
    }
  }
  ::close(fd);
  return response;
}
}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path workspace =
      std::filesystem::path(argc > 2 ? argv[2] : std::filesystem::temp_directory_path()) / "consumer-workspace";
  std::filesystem::create_directories(workspace);
  hula::server::Server server({.token = "consumer-token", .workspace = workspace, .version = "consumer-1"});
  std::thread serving([&] { server.run(); });
  const std::string health = get(server.port(), "/api/health");
  const std::string refused = get(server.port(), "/api/documents");
  server.stop();
  serving.join();
  const bool ok = health.starts_with("HTTP/1.1 200") && health.find("\"consumer-1\"") != std::string::npos &&
                  refused.starts_with("HTTP/1.1 401");
  std::printf("server: health -> %s; no token -> %s\n", health.substr(0, health.find('\r')).c_str(),
              refused.substr(0, refused.find('\r')).c_str());
  return ok ? 0 : 1;
}
