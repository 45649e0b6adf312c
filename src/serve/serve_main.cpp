// ncurve-serve: `ncurve serve`, which ncurve starts in its place (app/serve_exec.hpp), its
// arguments parsed by the same definitions.
#include <CLI/CLI.hpp>

#include <iostream>
#include <new>

#include "app/cli.hpp"
#include "io/output_file.hpp"
#include "serve/serve_command.hpp"

int main(int argc, char** argv) {
  using namespace ncurve;
  try {
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
    const int status = serve::serve_command(c.serve);
    io::check_stdout();
    return status;
  } catch (const io::OutputError& e) {
    std::cerr << "ncurve: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "ncurve: error: out of memory (the machine ran out of memory for this job; try a smaller one)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ncurve: internal error: " << e.what() << "\n";
    return 3;
  }
}
