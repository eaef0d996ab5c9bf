// SPDX-License-Identifier: MIT
// `hula serve`: the local HTTP JSON API (docs/server.md). Boost.Beast over
// Boost.Asio: a few I/O threads serve every connection asynchronously, so
// thousands of idle or streaming (SSE) connections cost sockets and buffers,
// not threads, and interrogation requests stay fast while optimisation jobs
// run on their own bounded pool (jobs.hpp) and imports, exports and
// intersections on the request workers. Every request passes the
// security middleware (security.hpp) before any route; requests are logged
// as JSON lines on stderr.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace hula::server {

struct ServerOptions {
  /// Address to listen on; loopback by default. Another address exposes the server to the network.
  std::string host = "127.0.0.1";
  /// TCP port; 0 picks a free one (read it back with Server::port()).
  unsigned port = 0;
  /// The access token (see security.hpp); must not be empty.
  std::string token{};
  /// The directory holding the documents; must exist.
  std::filesystem::path workspace{};
  /// Directory of the workbench's static files; unset or missing: non-API paths answer 404.
  std::optional<std::filesystem::path> static_dir{};
  /// Job worker threads, ≥ 1 (the command's default is cores − 1, at least 1).
  std::size_t jobs = 1;
  /// Jobs allowed to wait for a worker; one more gets 429. ≥ 1.
  std::size_t queue_limit = 16;
  /// Threads serving HTTP, ≥ 1; each request runs on one to its end. Two on a 2-core machine: four did not shorten
  /// the fairing ghost's wait (docs/benchmarks.md, "Fairing ghost before the page's own catching up").
  std::size_t io_threads = 2;
  /// Threads running the routes that can take seconds (imports and exports, which wait for the exchange
  /// helper; intersections of curves of any size: Runs::Worker in router.hpp), so the I/O threads stay free
  /// for every other request. ≥ 1; more requests of that kind wait for one.
  std::size_t request_workers = 4;
  /// Open connections at most; one more is answered 503 and closed. ≥ 1.
  std::size_t max_connections = 16384;
  /// Largest request body in bytes (413 past it, refused before the body is read).
  std::uint64_t max_body = 64ull * 1024 * 1024;
  /// Largest request line plus headers in bytes (431 past it).
  std::size_t max_header = 16 * 1024;
  /// Longest request target in bytes (414 past it).
  std::size_t max_target = 8 * 1024;
  /// Deepest nesting of a JSON body (400 past it).
  std::size_t json_depth = 64;
  /// Seconds a client has to send a whole request, from its first byte wait on (also the idle
  /// keep-alive limit); a slower client is disconnected (slowloris guard). In (0, 3600].
  double read_timeout = 10.0;
  /// Version reported by GET /api/health.
  std::string version = "unknown";

  /// @throws hula::Error(Errc::InvalidOption) naming the field out of range
  void validate() const;
};

class Server {
 public:
  /// Binds the listening socket (so port() is known) and starts the job workers.
  /// @throws hula::Error(Errc::InvalidOption) from options.validate()
  /// @throws hula::Error(Errc::IoError) if the address cannot be bound, naming host and port
  explicit Server(ServerOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The bound port.
  [[nodiscard]] unsigned port() const noexcept;

  /// Serves until stop() or SIGINT/SIGTERM: then refuses new connections, cancels the jobs (each
  /// keeps its best so far), waits for them and returns.
  void run();

  /// Asks run() to return; safe from any thread.
  void stop();

  /// Why the job threads could not take the lowest scheduling priority, or "" (JobPool::priority_error).
  [[nodiscard]] std::string job_priority_error() const;

  /// The implementation (server.cpp), named here so the connection sessions can reach it.
  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace hula::server
