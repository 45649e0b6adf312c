#include "serve/serve_command.hpp"

#include <fmt/format.h>

#include <pthread.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <set>
#include <thread>

#include "serve/server.hpp"

namespace ncurve::serve {

namespace {
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
  c.allow_hosts = a.allow_hosts;
  std::set<std::string> names;
  for (const auto& f : c.files) {
    struct stat st {};
    if (::stat(f.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {  // a FIFO or device would block its reader
      std::cerr << "ncurve serve: " << f << " is not a regular file (a FIFO, a device or a folder cannot be served)\n";
      return 2;
    }
    if (!names.insert(std::filesystem::path(f).filename().string()).second) {
      std::cerr << "ncurve serve: two files named " << std::filesystem::path(f).filename().string()
                << ": the page opens files by name\n";
      return 2;
    }
  }
  // a program's setup beside it (NAME.setup.toml) is offered too: the page's Part cuts its stock
  for (std::size_t i = 0, n = c.files.size(); i < n; ++i) {
    const std::filesystem::path p(c.files[i]);
    if (p.extension() != ".nc") continue;
    const std::filesystem::path setup = p.parent_path() / (p.stem().string() + ".setup.toml");
    std::error_code ec;
    if (std::filesystem::is_regular_file(setup, ec) && names.insert(setup.filename().string()).second)
      c.files.push_back(setup.string());
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
