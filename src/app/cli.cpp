#include "app/cli.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "app/cli_checks.hpp"
#include "app/cli_docs.hpp"
#include "app/run_html.hpp"
#include "app/run_plot.hpp"

namespace ncurve::app {

void add_commands(CLI::App& app, Commands& c) {
  app.require_subcommand(1);
  RunArgs& a = c.run;
  CLI::App* run = app.add_subcommand("run", "execute a part program as a FANUC control would and report the tool path");
  add_run_inputs(run, a.in, true, true);
  run->add_option("--format", a.format, "output: summary (default), jsonl, csv or gcode")
      ->check(CLI::IsMember({"summary", "jsonl", "csv", "gcode"}));
  run->add_option("--arc-tol", a.arc_tol, "csv: chord error allowed when arcs are written as points, mm")
      ->check(positive_mm());
  run->add_option("-o,--output", a.output, "write the output to this file (the summary then goes to the terminal)");
  run->add_flag("--json", a.json, "summary as JSON");
  run->add_flag("--stream", a.in.stream,
                "read the program block by block as the run reaches it, in little memory however long it is "
                "(files of 8 MB and more always are)");
  run->add_option("--dprnt", a.dprnt, "write what POPEN, DPRNT, BPRNT and PCLOS send to this file, byte for byte");
  add_plot_options(run, a.plot, a.view);
  add_html_option(run, a.html);
  add_verify_options(run, a.verify);
  c.run_command = run;
  add_gen_command(app, c.gen);
  add_helicoid_command(app, c.helicoid);
  add_analyze_command(app, c.analyze);
  add_serve_command(app, c.serve);
  c.completion = app.add_subcommand("completion", "print the bash completion script: source <(ncurve completion)");
  c.man = app.add_subcommand("man", "print the manual page (roff)")->group("");
}

std::string not_a_command(CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2 || argv[1][0] == '-') return {};
  std::vector<std::string> known;
  for (const auto* c : app.get_subcommands([](const CLI::App*) { return true; })) known.push_back(c->get_name());
  if (std::find(known.begin(), known.end(), argv[1]) != known.end()) return {};
  const std::string near = nearest(argv[1], known);
  return fmt::format("ncurve: '{}' is not a command{}; the commands are run, gen, analyze, helicoid, serve and completion "
                     "(ncurve --help)\n",
                     argv[1], near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near));
}

}  // namespace ncurve::app
