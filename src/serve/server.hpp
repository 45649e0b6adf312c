// The HTTP server of `ncurve serve` (cpp-httplib): routes to the API, errors as JSON, requests
// from other sites refused, a request body limit; each connection is served on a thread of its
// own (serve/connections.hpp) and each run has interpreters of its own.
#pragma once
#include <memory>
#include <optional>
#include <semaphore>
#include <string>
#include <vector>

#include "serve/api.hpp"

namespace httplib {
struct Request;
struct Response;
}  // namespace httplib

namespace ncurve::serve {

class HttpServer;

class Server {
public:
  explicit Server(ServeConfig config);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;
  // Binds host:port (port 0: a free one) and returns the port; throws std::runtime_error if it cannot.
  int bind(const std::string& host, int port);
  // Serves until stop(); false if it could not.
  bool listen();
  // Stops listening and cancels the runs under way; listen() returns within moments.
  void stop();
  bool running() const;
  // The Host header values this server answers (bind: the bound address and port, and the
  // loopback names and --allow-host names with the port).
  const std::vector<std::string>& hosts() const { return hosts_; }

private:
  // 403 for another host or origin, 415 for a body that is not JSON; nothing for a request of ours
  std::optional<Answer> refuse(const httplib::Request& req) const;
  // a run, analysis or generation, when one of runs_ is free (or 503 when the client goes first)
  template <class F>
  void work(httplib::Response& res, F endpoint);

  ServeConfig config_;
  std::vector<std::string> hosts_;
  std::counting_semaphore<> runs_;  // runs, analyses and generations at once
  std::unique_ptr<HttpServer> http_;
};

}  // namespace ncurve::serve
