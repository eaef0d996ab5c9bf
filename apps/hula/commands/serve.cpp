// SPDX-License-Identifier: MIT
// `hula serve --workspace DIR`: the local HTTP JSON API (server/server.hpp,
// docs/server.md). Prints one JSON line on stdout once listening,
// {"url": "http://127.0.0.1:PORT/?token=TOKEN", "port", "token", "workspace"},
// then logs requests as JSON lines on stderr until SIGINT or SIGTERM, when
// running jobs are cancelled with their best so far kept and the command
// exits 0.
#include <malloc.h>
#include <sys/resource.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/server/security.hpp"
#include "hula/server/server.hpp"

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace hula::cli {

namespace {

struct ServeArgs {
  std::string workspace;
  std::string host = "127.0.0.1";
  unsigned port = 0;
  std::string token_file;
  std::optional<std::size_t> jobs;
  std::size_t queue = 16;
  std::string static_dir;
  std::size_t max_connections = 16384;
  double read_timeout = 10.0;
  std::size_t max_body_mib = 64;
  std::size_t io_threads = 2;
};

bool is_loopback(const std::string& host) { return host == "127.0.0.1" || host == "::1"; }

// The workbench's files: --static, else share/hulahoops/web beside the installed binary, else the
// source tree's web/dist (a build-tree binary).
std::optional<std::filesystem::path> static_directory(const std::string& given) {
  if (!given.empty()) return std::filesystem::path(given);
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "hulahoops" / "web";
    if (std::filesystem::is_directory(installed, ec)) return installed;
  }
#ifdef HULA_SOURCE_WEB_DIST
  const std::filesystem::path dist = HULA_SOURCE_WEB_DIST;
  if (std::filesystem::is_directory(dist, ec)) return dist;
#endif
  return std::nullopt;
}

// Thousands of idle or streaming clients need as many descriptors: lift the soft limit to the hard one.
void raise_descriptor_limit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur < limit.rlim_max) {
    limit.rlim_cur = limit.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &limit);
  }
}

// Every request allocates and frees its body, JSON and response (tens of kB) on an I/O thread.
// By default glibc hands free memory back to the kernel as soon as 128 kB of it sit at the top of
// a heap (brk on the main heap, madvise on a thread's arena), and each hand-back in a threaded
// process flushes the TLB of every core: a quarter of a PATCH request's CPU time in a perf profile
// (docs/benchmarks.md). Keeping up to 64 MiB free, and blocks up to 4 MiB on the heap rather than
// in their own mappings, lets requests reuse the same memory instead.
void keep_freed_memory() {
  ::mallopt(M_TRIM_THRESHOLD, 64 * 1024 * 1024);
  ::mallopt(M_MMAP_THRESHOLD, 4 * 1024 * 1024);
}

int run_serve(const ServeArgs& a) {
  server::ServerOptions o;
  o.host = a.host;
  o.port = a.port;
  o.workspace = std::filesystem::absolute(a.workspace);
  o.token = a.token_file.empty() ? server::generate_token() : server::read_token_file(a.token_file);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  o.jobs = a.jobs.value_or(cores > 1 ? cores - 1 : 1);
  o.queue_limit = a.queue;
  o.static_dir = static_directory(a.static_dir);
  o.max_connections = a.max_connections;
  o.read_timeout = a.read_timeout;
  o.max_body = static_cast<std::uint64_t>(a.max_body_mib) * 1024 * 1024;
  o.io_threads = a.io_threads;
  o.version = HULA_VERSION;
  raise_descriptor_limit();
  keep_freed_memory();
  server::Server server(o);
  const std::string host = o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host;
  Json start = Json::object();
  start["url"] = "http://" + host + ":" + std::to_string(server.port()) + "/?token=" + o.token;
  start["port"] = server.port();
  start["token"] = o.token;
  start["workspace"] = o.workspace.string();
  std::cout << start.dump() << std::endl;
  if (!is_loopback(o.host)) {
    Json warning = Json::object();
    warning["warning"] = "listening on " + o.host +
                         ", not loopback: any machine that reaches it and knows the "
                         "token can use the API, unencrypted";
    std::cerr << warning.dump() << std::endl;
  }
  if (const std::string failed = server.job_priority_error(); !failed.empty()) {
    Json warning = Json::object();
    warning["warning"] = "job threads run at the normal scheduling priority and compete with requests: " + failed;
    std::cerr << warning.dump() << std::endl;
  }
  server.run();
  return kExitOk;
}

}  // namespace

Command add_serve(CLI::App& app) {
  auto a = std::make_shared<ServeArgs>();
  CLI::App* sub = app.add_subcommand("serve", "Serve the local HTTP JSON API and the workbench (docs/server.md)");
  sub->add_option("--workspace", a->workspace, "Directory of the documents (must exist)")
      ->required()
      ->check(CLI::ExistingDirectory);
  sub->add_option("--host", a->host, "Address to listen on (default 127.0.0.1; another address prints a warning)");
  sub->add_option("--port", a->port, "TCP port, 0 for a free one (default 0)")->check(CLI::Range(0, 65535));
  sub->add_option("--token-file", a->token_file,
                  "Read the access token from this file's first line (default: 256 random bits per start)");
  sub->add_option("--jobs", a->jobs, "Job worker threads (default: cores - 1, at least 1)")->check(CLI::Range(1, 1024));
  sub->add_option("--queue", a->queue, "Jobs allowed to wait for a worker; more are refused with 429 (default 16)")
      ->check(CLI::Range(1, 100000));
  sub->add_option("--static", a->static_dir,
                  "Directory of the workbench's files (default: <prefix>/share/hulahoops/web, or web/dist in a build "
                  "tree)")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--max-connections", a->max_connections,
                  "Open connections at most; more are answered 503 (default 16384)")
      ->check(CLI::Range(1, 1000000));
  sub->add_option("--read-timeout", a->read_timeout,
                  "Seconds a client has to send a whole request (and to stay idle between requests), in (0, 3600] "
                  "(default 10)");
  sub->add_option("--max-body", a->max_body_mib, "Largest request body in MiB (default 64)")
      ->check(CLI::Range(1, 4096));
  sub->add_option("--io-threads", a->io_threads,
                  "Threads serving HTTP requests, each request on one to its end (default 2)")
      ->check(CLI::Range(1, 256));
  return {sub, [a] { return run_serve(*a); }};
}

}  // namespace hula::cli
