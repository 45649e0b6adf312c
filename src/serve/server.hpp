// The HTTP server of `ncurve serve` (cpp-httplib): routes to the API, errors as JSON, a request
// body limit; each request runs on one of httplib's pool threads with interpreters of its own.
#pragma once
#include <memory>
#include <string>

#include "serve/api.hpp"

namespace httplib {
class Server;
}

namespace ncurve::serve {

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
  void stop();
  bool running() const;

private:
  ServeConfig config_;
  std::unique_ptr<httplib::Server> http_;
};

}  // namespace ncurve::serve
