#include "app/serve_args.hpp"

#include "app/cli_checks.hpp"
#include "app/shipped.hpp"

namespace ncurve::app {

void add_serve_command(CLI::App& app, ServeArgs& a) {
  CLI::App* cmd = app.add_subcommand("serve", "the local web workbench and its JSON API (http://127.0.0.1:8080)");
  cmd->add_option("files", a.files, "part programs the page can open (GET /api/files), or folders of them")
      ->check(CLI::ExistingPath);
  cmd->add_option("--port", a.port, "TCP port (default 8080; 0: any free port, printed)")->check(whole(0, 65535));
  cmd->add_option("--host", a.host,
                  "address to listen on (default 127.0.0.1, this machine only; 0.0.0.0 lets any machine that can "
                  "reach this one run programs here)");
  cmd->add_option("--allow-host", a.allow_hosts,
                  "a name this server is reached by besides --host and the loopback names (the Host header of "
                  "a request; others are refused); may be repeated")
      ->allow_extra_args(false);
  cmd->add_option("--machine", a.machine,
                  "the profile of a request that names none (TOML file, or a shipped one by name); default: as run, "
                  "FANUC 3-axis mill, factory parameters")
      ->transform(profile_path());
  cmd->add_option("--lib", a.libs, "folder of macro programs for every run, or `macros`; may be repeated")
      ->transform(folder_path())
      ->allow_extra_args(false);
  cmd->add_option("--max-steps", a.max_steps, "the most steps a run may take (a request may ask for fewer)")
      ->check(whole(1, 1'000'000'000'000'000L));
  cmd->add_option("--max-seconds", a.max_seconds,
                  "the most seconds a run may take (default 60; 0: no limit; a request may ask for less)")
      ->check(non_negative("a time", "s"));
  cmd->add_option("--max-body", a.max_body_mb, "the largest request body, MB (default 64)")
      ->check(non_negative("a size", "MB"));
  cmd->add_option("--max-moves", a.max_moves, "the most moves one answer carries (default 5000000)")
      ->check(whole(1, 100'000'000));
  a.command = cmd;
}

}  // namespace ncurve::app
