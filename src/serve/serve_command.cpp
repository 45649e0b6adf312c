#include "serve/serve_command.hpp"

#include <fmt/format.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <set>

#include "serve/server.hpp"

namespace ncurve::serve {

namespace {
Server* running = nullptr;
extern "C" void on_signal(int) {
  if (running) running->stop();
}
bool loopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }
}  // namespace

int serve_command(const app::ServeArgs& a) {
  ServeConfig c;
  c.machine = a.machine;
  c.libs = a.libs;
  c.files = a.files;
  c.max_steps = a.max_steps;
  c.max_seconds = a.max_seconds;
  c.max_body = static_cast<std::size_t>(a.max_body_mb * (1 << 20));
  c.max_moves = static_cast<std::size_t>(a.max_moves);
  std::set<std::string> names;
  for (const auto& f : c.files)
    if (!names.insert(std::filesystem::path(f).filename().string()).second) {
      std::cerr << "ncurve serve: two files named " << std::filesystem::path(f).filename().string()
                << ": the page opens files by name\n";
      return 2;
    }
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
  running = &server;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  const bool ok = server.listen();
  running = nullptr;
  return ok ? 0 : 2;
}

}  // namespace ncurve::serve
