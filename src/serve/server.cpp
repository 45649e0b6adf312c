#include "serve/server.hpp"

#include <fmt/format.h>
#include <httplib.h>

#include <new>

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

const char* reason(int status) {
  switch (status) {
    case 400: return "bad request";
    case 404: return "no such page or endpoint (the API: POST /api/run, /api/analyze, /api/gen; GET /api/profiles, "
                     "/api/curves, /api/files)";
    case 405: return "method not allowed";
    case 413: return "the request body is too large";
    default: return "the request failed";
  }
}

}  // namespace

Server::Server(ServeConfig config) : config_(std::move(config)), http_(std::make_unique<httplib::Server>()) {
  httplib::Server& s = *http_;
  const ServeConfig& c = config_;
  s.set_payload_max_length(c.max_body);
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a second server binds the
  // same port and the two share its connections
  s.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  s.Get("/", [](const httplib::Request&, httplib::Response& res) { answer(res, [] { return page(); }); });
  s.Get(R"(/assets/([A-Za-z0-9._-]+))", [](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] { return asset(req.matches[1]); });
  });
  s.Post("/api/run", [&c](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] { return api_run(c, req.body); });
  });
  s.Post("/api/analyze", [&c](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] { return api_analyze(c, req.body); });
  });
  s.Post("/api/gen", [&c](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] { return api_gen(c, req.body); });
  });
  s.Get("/api/profiles", [&c](const httplib::Request&, httplib::Response& res) {
    answer(res, [&] { return api_profiles(c); });
  });
  s.Get("/api/curves", [](const httplib::Request&, httplib::Response& res) { answer(res, [] { return api_curves(); }); });
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
  for (const char* path : {"/", R"(/assets/([A-Za-z0-9._-]+))", "/api/profiles", "/api/curves", "/api/files",
                           R"(/api/files/([^/]+))"}) {
    s.Post(path, refuse("GET, HEAD"));
    s.Put(path, refuse("GET, HEAD"));
    s.Patch(path, refuse("GET, HEAD"));
    s.Delete(path, refuse("GET, HEAD"));
  }
  // httplib's own refusals (no route, a body over the limit) get a JSON body too
  s.set_error_handler([&c](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    std::string message = reason(res.status);
    // httplib reads a form-encoded body (curl -d's default type) only up to 8192 bytes
    if (res.status == 413 && req.get_header_value("Content-Type").starts_with("application/x-www-form-urlencoded"))
      message = fmt::format("{}: a body sent as a form (Content-Type application/x-www-form-urlencoded, curl -d's) is "
                            "read up to {} bytes; send it as JSON (curl -H 'Content-Type: application/json' "
                            "--data-binary @FILE), up to {} bytes",
                            message, CPPHTTPLIB_FORM_URL_ENCODED_PAYLOAD_MAX_LENGTH, c.max_body);
    else if (res.status == 413) message = fmt::format("{} (at most {} bytes)", message, c.max_body);
    send(res, error_answer(res.status, message));
  });
}

Server::~Server() = default;

int Server::bind(const std::string& host, int port) {
  const int bound = port == 0 ? http_->bind_to_any_port(host) : (http_->bind_to_port(host, port) ? port : -1);
  if (bound <= 0)
    throw std::runtime_error(fmt::format("cannot listen on {}:{} (in use, or not an address of this machine)", host,
                                         port));
  return bound;
}

bool Server::listen() { return http_->listen_after_bind(); }

void Server::stop() { http_->stop(); }

bool Server::running() const { return http_->is_running(); }

}  // namespace ncurve::serve
