// The `ncurve serve` command's options (the server itself is in src/serve).
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "machine/interpreter.hpp"

namespace ncurve::app {

struct ServeArgs {
  int port = 8080;
  std::string host = "127.0.0.1";  // loopback only unless --host says otherwise
  std::vector<std::string> allow_hosts;  // names a request's Host may give besides --host
  std::string machine;
  std::vector<std::string> libs;
  std::vector<std::string> files;
  std::uint64_t max_steps = machine::RunOptions{}.max_steps;
  double max_seconds = machine::RunOptions{}.max_seconds;
  double max_body_mb = 64;
  long max_moves = 5'000'000;
  CLI::App* command = nullptr;
};

void add_serve_command(CLI::App& app, ServeArgs& args);

}  // namespace ncurve::app
