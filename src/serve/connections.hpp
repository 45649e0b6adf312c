// How `ncurve serve` holds its connections (over cpp-httplib): a thread for each connection up to
// a bound, a deadline for reading each request and one for writing its answer, a bound on the
// bytes of a request, and the work of a request cancelled when its client goes or the server stops.
#pragma once
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <set>
#include <thread>

namespace ncurve::serve {

struct ConnectionLimits {
  std::chrono::milliseconds request_time{30'000};  // to read a request whole; again to write its answer
  std::size_t request_bytes = 65u << 20;            // the most read of one request (line, headers, body)
  std::size_t connections = 256;                    // served at once; more wait for a free thread
};

// A connection being served, on its own thread.
struct Connection {
  socket_t sock;
  std::atomic<bool> cancel{false};  // the client has gone, or the server is stopping
  bool close = false;               // close once this answer is written (its body was not read)
};

class HttpServer final : public httplib::Server {
public:
  explicit HttpServer(ConnectionLimits limits);
  ~HttpServer() override;
  // The connection the calling thread serves (nullptr outside a request).
  static Connection* current();
  // Once bound: a queue of connections not yet accepted as long as the system allows (httplib
  // asks for 5, and a burst of more waits a second for the client to try again).
  void widen_backlog();
  // Stops listening, cancels the work under way and ends every connection: listen returns.
  void shut_down();
  bool stopping() const { return stopping_; }

private:
  bool process_and_close_socket(socket_t sock) override;
  bool wait_for_request(socket_t sock) const;
  void watch();  // sets `cancel` of each connection whose client has closed it

  ConnectionLimits limits_;
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::set<Connection*> connections_;
  std::thread watcher_;
};

}  // namespace ncurve::serve
