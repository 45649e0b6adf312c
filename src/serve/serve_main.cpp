// ncurve-serve: `ncurve serve`, which ncurve starts in its place (app/serve_exec.hpp), its
// arguments parsed by the same definitions.
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/cli.hpp"
#include "app/guarded_main.hpp"
#include "serve/serve_command.hpp"

int main(int argc, char** argv) {
  using namespace ncurve;
  return app::guarded_main([&] {
    CLI::App app{app::kDescription};
    app::Commands c;
    app::add_commands(app, c);
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      const int code = app.exit(e);
      return code == 0 ? 0 : 2;
    }
    if (!c.serve.command->parsed()) {
      std::cerr << "ncurve-serve: runs `ncurve serve` only: ncurve-serve serve [FILE...] [options]\n";
      return 2;
    }
    return serve::serve_command(c.serve);
  });
}
