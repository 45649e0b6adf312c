#include "serve/serve_command.hpp"

#include <fmt/format.h>

#include <pthread.h>

#include <csignal>
#include <iostream>
#include <thread>

#include "serve/served_files.hpp"
#include "serve/server.hpp"

namespace ncurve::serve {

namespace {
bool loopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }
}  // namespace

int serve_command(const app::ServeArgs& a) {
  ServeConfig c;
  c.machine = a.machine;
  c.libs = a.libs;
  c.max_steps = a.max_steps;
  c.max_seconds = a.max_seconds;
  c.max_body = static_cast<std::size_t>(a.max_body_mb * (1 << 20));
  c.max_moves = static_cast<std::size_t>(a.max_moves);
  c.allow_hosts = a.allow_hosts;
  try {
    c.files = served_files(a.files);
  } catch (const std::runtime_error& e) {
    std::cerr << "ncurve serve: " << e.what() << "\n";
    return 2;
  }
  // SIGINT and SIGTERM are taken by a thread of their own, which stops the server (a handler
  // could not: stopping takes a lock); every other thread starts with them blocked
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  Server server(c);
  int port = 0;
  try {
    port = server.bind(a.host, a.port);
  } catch (const std::exception& e) {
    std::cerr << "ncurve serve: " << e.what() << "\n";
    return 2;
  }
  if (!loopback(a.host))
    std::cerr << fmt::format("ncurve serve: warning: listening on {}: any machine that can reach this one can run "
                             "programs here\n",
                             a.host);
  std::cout << fmt::format("ncurve serve: http://{}:{}/ (Ctrl-C stops it)\n",
                           a.host.find(':') != std::string::npos ? "[" + a.host + "]" : a.host, port)
            << std::flush;
  std::thread stopper([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    server.stop();
  });
  const bool ok = server.listen();
  if (!ok) pthread_kill(stopper.native_handle(), SIGTERM);  // not stopped by a signal: end the stopper
  stopper.join();
  return ok ? 0 : 2;
}

}  // namespace ncurve::serve
