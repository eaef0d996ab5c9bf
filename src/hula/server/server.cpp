// SPDX-License-Identifier: MIT
// The Boost.Beast server (server.hpp). One Session per connection, on its own
// strand: read the header (under the request deadline), run the security
// middleware on it, then read the body (Beast enforces the body limit while
// reading, the middleware refuses a too-large Content-Length before), route,
// write, and go on reading while the client keeps the connection alive. A
// route that answers with an EventLog turns the connection into an SSE
// stream fed by EventLog wake-ups, without a thread of its own. A route that
// runs on the request workers (Runs::Worker) is handed to them with the
// request; its response comes back to the connection's strand to be written.
#include "hula/server/server.hpp"

#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <mutex>
#include <new>
#include <thread>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/server/documents.hpp"
#include "hula/server/events.hpp"
#include "hula/server/jobs.hpp"
#include "hula/server/router.hpp"
#include "hula/server/routes/routes.hpp"
#include "hula/server/security.hpp"
#include "hula/server/static_files.hpp"

namespace hula::server {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = net::ip::tcp;

namespace {

// A response write (or one SSE batch) that takes longer than this drops the client.
constexpr std::chrono::seconds kWriteTimeout{30};
// On stop, event streams get this long to deliver their final events before the I/O threads end.
constexpr std::chrono::seconds kDrainTime{2};

void require(bool ok, const char* field, const std::string& message) {
  if (!ok) throw Error(Errc::InvalidOption, std::string(field) + " " + message, ErrorWhere{.field = field});
}

std::string_view view(beast::string_view s) noexcept { return {s.data(), s.size()}; }

std::optional<std::string_view> header(const http::request<http::string_body>& req, http::field f) {
  const auto it = req.find(f);
  if (it == req.end()) return std::nullopt;
  return view(it->value());
}

}  // namespace

void ServerOptions::validate() const {
  require(!token.empty(), "token", "must not be empty");
  require(port <= 65535, "port", "= " + std::to_string(port) + " is not in [0, 65535]");
  require(jobs >= 1, "jobs", "must be at least 1");
  require(queue_limit >= 1, "queue_limit", "must be at least 1");
  require(io_threads >= 1, "io_threads", "must be at least 1");
  require(request_workers >= 1, "request_workers", "must be at least 1");
  require(max_connections >= 1, "max_connections", "must be at least 1");
  require(max_body >= 1, "max_body", "must be at least 1 byte");
  require(max_header >= 1024, "max_header", "must be at least 1024 bytes");
  require(max_target >= 256, "max_target", "must be at least 256 bytes");
  require(json_depth >= 2, "json_depth", "must be at least 2");
  require(std::isfinite(read_timeout) && read_timeout > 0 && read_timeout <= 3600, "read_timeout",
          "= " + format_number(read_timeout) + " seconds is not in (0, 3600]");
  std::error_code ec;
  require(std::filesystem::is_directory(workspace, ec), "workspace", "'" + workspace.string() + "' is not a directory");
}

struct Server::Impl {
  ServerOptions options;
  // Declared before the I/O context: sessions, destroyed with it or with the jobs' event logs,
  // still count themselves out and may log.
  std::atomic<std::size_t> connections{0};
  std::atomic<std::size_t> streaming{0};
  std::mutex log_mutex;
  std::once_flag stopped;
  net::io_context ioc;
  tcp::acceptor acceptor{ioc};
  net::signal_set signals{ioc, SIGINT, SIGTERM};
  net::steady_timer accept_retry{ioc};
  SecurityPolicy policy;
  JobPool jobs;
  DocumentRegistry documents;
  Router router;
  net::steady_timer drain{ioc};
  // Declared last: destroyed (stopped and joined) first, while the routes its threads run still exist.
  net::thread_pool workers;

  explicit Impl(ServerOptions o)
      : options(std::move(o)),
        jobs(JobPoolOptions{.workers = options.jobs, .queue_limit = options.queue_limit}),
        documents(options.workspace),
        workers(options.request_workers) {}

  void accept();
  void stop();
  void stop_when_drained(std::chrono::steady_clock::time_point deadline);
  void log(std::string_view method, std::string_view route, unsigned status, double ms);
  // A static file or the ?token= redirect (the paths outside /api/).
  Response handle_static(Request& request, std::string& route);
};

namespace {

// What a request gets from `produce`, its errors turned into error responses.
template <class F>
Response answer(F&& produce) {
  try {
    return produce();
  } catch (const HttpError& e) {
    return error_response(e);
  } catch (const Error& e) {
    return error_response(e);
  } catch (const std::bad_alloc& e) {
    return error_response(out_of_memory_error(e));
  } catch (const std::exception& e) {
    return error_response(HttpError(500, "InternalError", e.what()));
  }
}

}  // namespace

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket&& socket, Server::Impl& server) : stream_(std::move(socket)), server_(server) {
    ++server_.connections;
  }
  ~Session() {
    if (streaming_ && !closed_) --server_.streaming;
    --server_.connections;
  }

  void start() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->read(); });
  }

  // Answers 503 to a connection over the limit and closes it.
  void refuse_overloaded() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] {
      self->started_ = std::chrono::steady_clock::now();
      self->method_ = "-";
      self->respond(error_response(HttpError(503, "ServiceUnavailable",
                                             "too many open connections (limit " +
                                                 std::to_string(self->server_.options.max_connections) + ")")),
                    false, "");
    });
  }

 private:
  beast::tcp_stream stream_;
  Server::Impl& server_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::chrono::steady_clock::time_point started_;
  std::string method_;
  std::shared_ptr<EventLog> events_;
  std::size_t next_event_ = 0;
  std::string pending_;
  bool streaming_ = false;
  bool closed_ = false;

  void read() {
    parser_.emplace();
    parser_->header_limit(static_cast<std::uint32_t>(server_.options.max_header));
    parser_->body_limit(server_.options.max_body);
    // One deadline for the whole request, header and body: a client that trickles bytes is cut off
    // when it runs out, however often it sends.
    stream_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(server_.options.read_timeout)));
    http::async_read_header(stream_, buffer_, *parser_,
                            [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
  }

  void refuse(const HttpError& e) { respond(error_response(e), false, ""); }

  void on_header(beast::error_code ec) {
    started_ = std::chrono::steady_clock::now();
    // Beast refuses a declared Content-Length over the body limit while reading the header: the
    // body has not been read, and will not be.
    if (ec == http::error::body_limit)
      return refuse(
          HttpError(413, "PayloadTooLarge",
                    "the request body exceeds the limit of " + std::to_string(server_.options.max_body) + " bytes"));
    if (ec == http::error::header_limit)
      return refuse(
          HttpError(431, "HeaderTooLarge",
                    "the request line and headers exceed " + std::to_string(server_.options.max_header) + " bytes"));
    if (ec == http::error::end_of_stream || ec == beast::error::timeout || ec == net::error::operation_aborted ||
        ec == net::error::connection_reset || ec == net::error::eof)
      return close();
    if (ec) return refuse(HttpError(400, "BadRequest", "malformed HTTP request: " + ec.message()));
    const auto& req = parser_->get();
    method_ = std::string(view(req.method_string()));
    RequestHead head;
    head.method = view(req.method_string());
    head.target = view(req.target());
    head.host = header(req, http::field::host);
    head.host_count = req.count(http::field::host);
    head.origin = header(req, http::field::origin);
    head.authorization = header(req, http::field::authorization);
    head.cookie = header(req, http::field::cookie);
    if (const auto n = parser_->content_length()) head.content_length = *n;
    try {
      if (auto refusal = check_request(head, server_.policy)) return refuse(*refusal);
    } catch (const HttpError& e) {
      return refuse(e);
    }
    if (parser_->is_done()) return on_body({});
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code e, std::size_t) { self->on_body(e); });
  }

  void on_body(beast::error_code ec) {
    if (ec == http::error::body_limit)
      return refuse(
          HttpError(413, "PayloadTooLarge",
                    "the request body exceeds the limit of " + std::to_string(server_.options.max_body) + " bytes"));
    if (ec == beast::error::timeout || ec == http::error::end_of_stream || ec == net::error::eof ||
        ec == net::error::connection_reset || ec == net::error::operation_aborted)
      return close();
    if (ec) return refuse(HttpError(400, "BadRequest", "malformed HTTP request body: " + ec.message()));
    http::request<http::string_body> req = parser_->release();
    Request r;
    r.method = std::string(view(req.method_string()));
    const std::string_view target = view(req.target());
    const std::size_t q = target.find('?');
    r.path = std::string(target.substr(0, q));
    r.body = std::move(req.body());
    r.json_depth_limit = server_.options.json_depth;
    const bool keep_alive = req.keep_alive();
    std::string route;
    const Handler* offloaded = nullptr;
    Response response = answer([&] {
      if (q != std::string_view::npos) r.query = parse_query(target.substr(q + 1));
      if (!r.path.starts_with("/api/")) return server_.handle_static(r, route);
      const Router::Match m = server_.router.match(r, route);
      if (m.runs == Runs::Worker) {
        offloaded = m.handler;
        return Response{};
      }
      return (*m.handler)(r);
    });
    if (offloaded != nullptr) return hand_to_workers(std::move(r), *offloaded, std::move(route), keep_alive);
    finish(std::move(response), keep_alive, std::move(route), r.path);
  }

  // Runs a Worker route's handler on the request workers; its response is written from this connection's strand.
  void hand_to_workers(Request request, const Handler& handler, std::string route, bool keep_alive) {
    stream_.expires_never();  // the request is read; the write sets its own deadline
    net::post(server_.workers, [self = shared_from_this(), request = std::move(request), &handler,
                                route = std::move(route), keep_alive]() mutable {
      Response response = answer([&] { return handler(request); });
      net::post(self->stream_.get_executor(),
                [self, response = std::move(response), route = std::move(route), path = std::move(request.path),
                 keep_alive]() mutable { self->finish(std::move(response), keep_alive, std::move(route), path); });
    });
  }

  void finish(Response response, bool keep_alive, std::string route, const std::string& path) {
    if (route.empty()) route = path.starts_with("/api/") ? std::string("-") : std::string("static");
    if (response.events) {
      next_event_ = response.events_from;
      return start_events(std::move(response.events), route);
    }
    respond(std::move(response), keep_alive, route);
  }

  void respond(Response response, bool keep_alive, std::string_view route) {
    auto res = std::make_shared<http::response<http::string_body>>(static_cast<http::status>(response.status), 11);
    res->set(http::field::server, "hula");
    res->set(http::field::content_type, response.content_type);
    res->set(http::field::cache_control, "no-store");
    res->set("X-Content-Type-Options", "nosniff");
    for (const auto& [name, value] : response.headers) res->insert(beast::string_view(name), value);
    res->keep_alive(keep_alive);
    res->body() = std::move(response.body);
    res->prepare_payload();
    log(response.status, route);
    stream_.expires_after(kWriteTimeout);
    http::async_write(stream_, *res, [self = shared_from_this(), res](beast::error_code ec, std::size_t) {
      if (ec || !res->keep_alive()) return self->close();
      self->read();
    });
  }

  void log(unsigned status, std::string_view route) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_).count();
    server_.log(method_, route, status, ms);
  }

  void start_events(std::shared_ptr<EventLog> events, std::string_view route) {
    events_ = std::move(events);
    streaming_ = true;
    ++server_.streaming;
    auto res = std::make_shared<http::response<http::empty_body>>(http::status::ok, 11);
    res->set(http::field::server, "hula");
    res->set(http::field::content_type, "text/event-stream");
    res->set(http::field::cache_control, "no-store");
    res->set("X-Content-Type-Options", "nosniff");
    // The stream ends when the server closes the connection (no length, no chunking).
    res->keep_alive(false);
    log(200, route);
    stream_.expires_after(kWriteTimeout);
    http::async_write(stream_, *res, [self = shared_from_this(), res](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      self->watch_client();
      self->next_events();
    });
  }

  // A stream's client sends nothing after its request: readability means it left (EOF) or broke
  // the protocol, either way the stream ends instead of waiting for the next event.
  void watch_client() {
    stream_.socket().async_wait(tcp::socket::wait_read,
                                [self = shared_from_this()](beast::error_code) { self->close(); });
  }

  void next_events() {
    auto self = shared_from_this();
    EventLog::Batch batch = events_->next(
        next_event_, [self] { net::post(self->stream_.get_executor(), [self] { self->next_events(); }); });
    if (batch.count == 0) {
      if (batch.closed) return close();
      stream_.expires_never();  // waiting for the producer, not for the client
      return;
    }
    next_event_ += batch.count;
    pending_ = std::move(batch.text);
    stream_.expires_after(kWriteTimeout);
    net::async_write(stream_, net::buffer(pending_), [self](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      self->next_events();
    });
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    if (streaming_) --server_.streaming;
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
    stream_.close();
  }
};

void Server::Impl::log(std::string_view method, std::string_view route, unsigned status, double ms) {
  Json line = Json::object();
  line["method"] = method;
  line["route"] = route;
  line["status"] = status;
  line["ms"] = std::round(ms * 1000.0) / 1000.0;
  const std::string text = line.dump() + "\n";
  std::lock_guard lock(log_mutex);
  std::cerr << text;
  std::cerr.flush();
}

Response Server::Impl::handle_static(Request& request, std::string& route) {
  if (request.method != "GET" && request.method != "HEAD")
    throw HttpError(405, "MethodNotAllowed", request.method + " is not allowed on static files");
  route = "static";
  // Opening the page with ?token= stores the token in an HttpOnly, SameSite=Strict cookie and
  // sends the browser to the same path without it (the token leaves the address bar and history).
  if (const auto it = request.query.find("token"); it != request.query.end()) {
    if (!token_matches(it->second, policy)) throw HttpError(401, "Unauthorized", "wrong token in ?token=");
    Response r;
    r.status = 303;
    r.content_type = "text/plain; charset=utf-8";
    r.headers.emplace_back("Set-Cookie",
                           std::string(kTokenCookie) + "=" + policy.token + "; Path=/; HttpOnly; SameSite=Strict");
    r.headers.emplace_back("Location", request.path.empty() ? std::string("/") : request.path);
    return r;
  }
  return static_file(options.static_dir.value_or(std::filesystem::path()), request.path);
}

void Server::Impl::accept() {
  acceptor.async_accept(net::make_strand(ioc), [this](beast::error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted || !acceptor.is_open()) return;
    if (ec) {
      // Out of descriptors or a transient failure: wait a little instead of spinning.
      accept_retry.expires_after(std::chrono::milliseconds(20));
      accept_retry.async_wait([this](beast::error_code e) {
        if (!e) accept();
      });
      return;
    }
    const bool over = connections.load() >= options.max_connections;
    auto session = std::make_shared<Session>(std::move(socket), *this);
    if (over)
      session->refuse_overloaded();
    else
      session->start();
    accept();
  });
}

void Server::Impl::stop() {
  std::call_once(stopped, [this] {
    net::post(ioc, [this] {
      beast::error_code ec;
      acceptor.close(ec);
      signals.cancel(ec);
      accept_retry.cancel();
    });
    // Running jobs stop at their next generation and store their best so far; their final events
    // go to the subscribers, which close their streams once those are written.
    jobs.shutdown();
    documents.close_all();
    net::post(ioc, [this] { stop_when_drained(std::chrono::steady_clock::now() + kDrainTime); });
  });
}

void Server::Impl::stop_when_drained(std::chrono::steady_clock::time_point deadline) {
  if (streaming.load() == 0 || std::chrono::steady_clock::now() >= deadline) {
    ioc.stop();
    return;
  }
  drain.expires_after(std::chrono::milliseconds(10));
  drain.async_wait([this, deadline](beast::error_code) { stop_when_drained(deadline); });
}

Server::Server(ServerOptions options) {
  options.validate();
  impl_ = std::make_unique<Impl>(std::move(options));
  Impl& s = *impl_;
  beast::error_code ec;
  const net::ip::address address = net::ip::make_address(s.options.host, ec);
  if (ec)
    throw Error(Errc::InvalidOption, "host '" + s.options.host + "' is not an IP address (" + ec.message() + ")",
                ErrorWhere{.field = "host"});
  const tcp::endpoint endpoint(address, static_cast<unsigned short>(s.options.port));
  const auto fail = [&](const char* what) {
    throw Error(Errc::IoError,
                std::string("cannot ") + what + " " + s.options.host + ":" + std::to_string(s.options.port) + ": " +
                    ec.message(),
                ErrorWhere{.field = "port"});
  };
  s.acceptor.open(endpoint.protocol(), ec);
  if (ec) fail("open a socket for");
  s.acceptor.set_option(net::socket_base::reuse_address(true), ec);
  s.acceptor.bind(endpoint, ec);
  if (ec) fail("bind");
  s.acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) fail("listen on");
  s.policy.token = s.options.token;
  s.policy.allowed_hosts = allowed_hosts(s.options.host, port());
  s.policy.max_target = s.options.max_target;
  s.policy.max_body = s.options.max_body;
  const routes::Context context{s.options.version, s.options.workspace, s.jobs, s.documents};
  routes::add_health(s.router, context);
  routes::add_openapi(s.router, context);
  routes::add_law(s.router, context);
  routes::add_reconstruct(s.router, context);
  routes::add_intersect(s.router, context);
  routes::add_constructions(s.router, context);
  routes::add_joins(s.router, context);
  routes::add_clothoid(s.router, context);
  routes::add_curve_edits(s.router, context);
  routes::add_jobs(s.router, context);
  routes::add_documents(s.router, context);
  routes::add_entities(s.router, context);
  routes::add_study_seed(s.router, context);
}

Server::~Server() {
  if (impl_) impl_->jobs.shutdown();
}

unsigned Server::port() const noexcept { return impl_->acceptor.local_endpoint().port(); }

void Server::run() {
  Impl& s = *impl_;
  s.signals.async_wait([this](beast::error_code ec, int) {
    // On an I/O thread: the others keep serving while the jobs wind down (one generation at most).
    if (!ec) stop();
  });
  s.accept();
  std::vector<std::thread> threads;
  for (std::size_t i = 1; i < s.options.io_threads; ++i) threads.emplace_back([&s] { s.ioc.run(); });
  s.ioc.run();
  for (std::thread& t : threads) t.join();
  s.jobs.shutdown();
}

void Server::stop() { impl_->stop(); }

std::string Server::job_priority_error() const { return impl_->jobs.priority_error(); }

}  // namespace hula::server
