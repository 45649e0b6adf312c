#include "serve/server.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <httplib.h>

#include <algorithm>
#include <cctype>
#include <new>
#include <optional>
#include <thread>

#include "serve/connections.hpp"

namespace ncurve::serve {

namespace {

void send(httplib::Response& res, Answer a) {
  res.status = a.status;
  // httplib gzips a JSON answer for a browser, which takes a minute for the 40 MB of a
  // million moves: a big answer goes uncompressed (httplib leaves a type it does not know)
  const bool big = a.body.size() > (1u << 20) && a.content_type == "application/json";
  res.set_header("Content-Type", big ? "application/json; charset=utf-8" : a.content_type);
  res.body = std::move(a.body);
}

// The answer of an endpoint, or the JSON error of whatever stopped it.
template <class F>
void answer(httplib::Response& res, F endpoint) {
  try {
    send(res, endpoint());
  } catch (const ApiError& e) {
    send(res, error_answer(e.status, e.what()));
  } catch (const std::bad_alloc&) {
    send(res, error_answer(507, "out of memory: the request needs more memory than the machine has; try a smaller one"));
  } catch (const std::exception& e) {
    send(res, error_answer(500, fmt::format("internal error: {}", e.what())));
  }
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// name:port as a Host header gives it (an IPv6 address in brackets)
std::string host_port(const std::string& name, int port) {
  const bool v6 = name.find(':') != std::string::npos && !name.starts_with('[');
  return fmt::format("{}{}{}:{}", v6 ? "[" : "", lower(name), v6 ? "]" : "", port);
}

// "application/json" of "Application/JSON; charset=utf-8"
std::string media_type(const std::string& content_type) {
  const std::string m = lower(content_type.substr(0, content_type.find(';')));
  const auto first = m.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : m.substr(first, m.find_last_not_of(" \t") - first + 1);
}

bool is_api_post(const std::string& path) { return path == "/api/run" || path == "/api/analyze" || path == "/api/gen"; }

const char* reason(int status) {
  switch (status) {
    case 400: return "bad request";
    case 404: return "no such page or endpoint (the API: POST /api/run, /api/analyze, /api/gen; GET /api/profiles, "
                     "/api/curves, /api/libs, /api/files)";
    case 405: return "method not allowed";
    case 413: return "the request body is too large";
    default: return "the request failed";
  }
}

}  // namespace

Server::Server(ServeConfig config)
    : config_(std::move(config)),
      runs_(std::max<std::ptrdiff_t>(8, std::thread::hardware_concurrency())),
      http_(std::make_unique<HttpServer>(ConnectionLimits{
          std::chrono::milliseconds(static_cast<long long>(config_.request_seconds * 1000)),
          config_.max_body + (1u << 20), 256})) {
  httplib::Server& s = *http_;
  const ServeConfig& c = config_;
  s.set_payload_max_length(c.max_body);
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a second server binds the
  // same port and the two share its connections
  s.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  // Another site's page may send requests here (a form, a fetch without preflight) or reach this
  // port under its own name (DNS rebinding): a request naming another host or coming from another
  // origin is refused, and a body must be JSON, which a page of another site cannot send without
  // a preflight this server does not answer. Refused before the body is read; the connection closes.
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    std::optional<Answer> refusal = refuse(req);
    if (!refusal) return httplib::Server::HandlerResponse::Unhandled;
    send(res, std::move(*refusal));
    res.set_header("Connection", "close");
    if (Connection* connection = HttpServer::current()) connection->close = true;
    return httplib::Server::HandlerResponse::Handled;
  });
  s.Get("/", [](const httplib::Request&, httplib::Response& res) { answer(res, [] { return page(); }); });
  s.Get(R"(/assets/([A-Za-z0-9._-]+))", [](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] { return asset(req.matches[1]); });
  });
  s.Post("/api/run", [this, &c](const httplib::Request& req, httplib::Response& res) {
    work(res, [&](const std::atomic<bool>* cancel) { return api_run(c, req.body, cancel); });
  });
  s.Post("/api/analyze", [this, &c](const httplib::Request& req, httplib::Response& res) {
    work(res, [&](const std::atomic<bool>* cancel) { return api_analyze(c, req.body, cancel); });
  });
  s.Post("/api/gen", [this, &c](const httplib::Request& req, httplib::Response& res) {
    work(res, [&](const std::atomic<bool>*) { return api_gen(c, req.body); });
  });
  s.Get("/api/profiles", [&c](const httplib::Request&, httplib::Response& res) {
    answer(res, [&] { return api_profiles(c); });
  });
  s.Get("/api/curves", [](const httplib::Request&, httplib::Response& res) { answer(res, [] { return api_curves(); }); });
  s.Get("/api/libs", [&c](const httplib::Request&, httplib::Response& res) {
    answer(res, [&] { return api_libs(c); });
  });
  s.Get("/api/files", [&c](const httplib::Request&, httplib::Response& res) {
    answer(res, [&] { return api_files(c); });
  });
  s.Get(R"(/api/files/([^/]+))", [&c](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] { return api_file(c, req.matches[1]); });
  });
  // an endpoint asked with another method: 405, the methods it takes in Allow, and a JSON error
  auto refuse = [](const char* allow) {
    return [allow](const httplib::Request& req, httplib::Response& res) {
      res.set_header("Allow", allow);
      send(res, error_answer(405, fmt::format("{} {}: the method is not allowed here ({} only)", req.method, req.path,
                                              allow)));
    };
  };
  for (const char* path : {"/api/run", "/api/analyze", "/api/gen"}) {
    s.Get(path, refuse("POST"));
    s.Put(path, refuse("POST"));
    s.Patch(path, refuse("POST"));
    s.Delete(path, refuse("POST"));
  }
  for (const char* path : {"/", R"(/assets/([A-Za-z0-9._-]+))", "/api/profiles", "/api/curves", "/api/libs", "/api/files",
                           R"(/api/files/([^/]+))"}) {
    s.Post(path, refuse("GET, HEAD"));
    s.Put(path, refuse("GET, HEAD"));
    s.Patch(path, refuse("GET, HEAD"));
    s.Delete(path, refuse("GET, HEAD"));
  }
  // httplib's own refusals (no route, a body over the limit) get a JSON body too
  s.set_error_handler([&c](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;
    std::string message = reason(res.status);
    if (res.status == 413) message = fmt::format("{} (at most {} bytes: serve --max-body)", message, c.max_body);
    send(res, error_answer(res.status, message));
  });
}

std::optional<Answer> Server::refuse(const httplib::Request& req) const {
  // the connection's own address is its Host too (a server bound to 0.0.0.0, reached by an address)
  const std::string local = req.local_port > 0 ? host_port(req.local_addr, req.local_port) : std::string();
  auto ours = [&](const std::string& host) {
    const std::string h = lower(host);
    const bool local_host = !local.empty() && (h == local || (req.local_port == 80 && h + ":80" == local));
    return local_host || std::find(hosts_.begin(), hosts_.end(), h) != hosts_.end();
  };
  const std::string host = req.get_header_value("Host");
  if (!ours(host))
    return error_answer(403, fmt::format("refused: the request's Host \"{}\" is not this server's ({}); a name that "
                                         "reaches it is allowed by serve --allow-host NAME",
                                         host, fmt::join(hosts_, ", ")));
  if (req.has_header("Origin")) {
    const std::string origin = req.get_header_value("Origin");
    if (!(lower(origin).starts_with("http://") && ours(origin.substr(7))))
      return error_answer(403, fmt::format("refused: a page of another site (Origin \"{}\") may not use this server",
                                           origin));
  }
  if (req.method == "POST" && is_api_post(req.path)) {
    const std::string type = req.get_header_value("Content-Type");
    if (media_type(type) != "application/json")
      return error_answer(415, fmt::format("{} takes a JSON body sent as Content-Type: application/json (curl -H "
                                           "'Content-Type: application/json' --data-binary @FILE), not \"{}\"",
                                           req.path, type));
  }
  return std::nullopt;
}

template <class F>
void Server::work(httplib::Response& res, F endpoint) {
  Connection* connection = HttpServer::current();
  const std::atomic<bool>* cancel = connection ? &connection->cancel : nullptr;
  while (!runs_.try_acquire_for(std::chrono::milliseconds(50)))
    if (http_->stopping() || (cancel && *cancel)) {
      send(res, error_answer(503, "the server is stopping, or the request's client has gone"));
      return;
    }
  struct Release {
    std::counting_semaphore<>& runs;
    ~Release() { runs.release(); }
  } release{runs_};
  answer(res, [&] { return endpoint(cancel); });
}

Server::~Server() = default;

int Server::bind(const std::string& host, int port) {
  const int bound = port == 0 ? http_->bind_to_any_port(host) : (http_->bind_to_port(host, port) ? port : -1);
  if (bound <= 0)
    throw std::runtime_error(fmt::format("cannot listen on {}:{} (in use, or not an address of this machine)", host,
                                         port));
  http_->widen_backlog();
  hosts_.clear();
  std::vector<std::string> names{"127.0.0.1", "localhost", "::1", host};
  names.insert(names.end(), config_.allow_hosts.begin(), config_.allow_hosts.end());
  auto add = [&](std::string h) {
    if (std::find(hosts_.begin(), hosts_.end(), h) == hosts_.end()) hosts_.push_back(std::move(h));
  };
  for (const std::string& name : names) {
    const std::string h = host_port(name, bound);
    add(h);
    if (bound == 80) add(h.substr(0, h.rfind(':')));  // a browser leaves out the default port
  }
  return bound;
}

bool Server::listen() { return http_->listen_after_bind(); }

void Server::stop() { http_->shut_down(); }

bool Server::running() const { return http_->is_running(); }

}  // namespace ncurve::serve
