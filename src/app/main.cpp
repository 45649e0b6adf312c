// The ncurve command: argument parsing and output only; the work is done by libncurve.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <memory>
#include <optional>
#include <thread>

#include "app/gen_command.hpp"
#include "app/helicoid_command.hpp"
#include "app/analyze_command.hpp"
#include "app/run_html.hpp"
#include "app/run_batch.hpp"
#include "app/run_plot.hpp"
#include "app/run_setup.hpp"
#include "app/cli.hpp"
#include "app/cli_checks.hpp"
#include "app/cli_docs.hpp"
#include "app/shipped.hpp"
#include "io/output_file.hpp"
#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/background_sink.hpp"
#include "report/path_plot.hpp"
#include "report/summary.hpp"
#include "report/verify_report.hpp"
#include "report/writers.hpp"
#include "app/guarded_main.hpp"
#include "app/serve_exec.hpp"

namespace {

using namespace ncurve;

std::string version_text() {
  auto dir = app::shipped_dir();
  return fmt::format("ncurve {}\nprofiles, macros, examples: {}", NCURVE_VERSION,
                     dir ? *dir : std::string("not found beside the binary"));
}

// `ncurve run A.nc B.nc ...` or `ncurve run FOLDER`: the table of results.
int batch_command(const app::RunArgs& a, const std::vector<std::string>& arguments) {
  const char* single = !a.output.empty() && a.output != "-" ? "-o"
                       : a.format != "summary"              ? "--format"
                       : !a.plot.empty()                    ? "--plot"
                       : !a.html.empty()                    ? "--html"
                       : !a.dprnt.empty()                   ? "--dprnt"
                       : a.verify.on()                      ? "--verify, --setup, --part or --curve"
                                                            : nullptr;
  if (single) {
    std::cerr << "ncurve run: " << single
              << " is for one program; with several (or a folder) each is run on its own and a table of the results "
                 "is written (--json for scripts)\n";
    return 2;
  }
  std::vector<std::string> programs;
  try {
    programs = app::batch_programs(arguments);
  } catch (const std::exception& e) {
    std::cerr << "ncurve run: " << nc::escape_controls(e.what()) << "\n";
    return 2;
  }
  if (programs.empty()) {
    std::cerr << "ncurve run: no program files in " << nc::escape_controls(arguments.front())
              << " (.nc, .cnc, .tap, .txt, .ncc, .iso, .eia, .ptp, .prg, .gcode, or O and a number)\n";
    return 2;
  }
  if (std::find(programs.begin(), programs.end(), "-") != programs.end()) {
    std::cerr << "ncurve run: standard input (-) is one program; name the files of a table\n";
    return 2;
  }
  const std::vector<app::BatchRow> rows = app::run_batch(a.in, programs);
  std::cout << (a.json ? app::batch_json(rows) : app::batch_text(rows));
  return app::batch_status(rows);
}

int run_command(const app::RunArgs& a) {
  // without --curve the extra words are more programs (or folders): each run on its own, a table of
  // the results; a word that is neither is an error
  std::vector<std::string> programs{a.in.program};
  std::error_code ec;
  if (a.verify.curve.name.empty())
    for (const std::string& word : a.verify.curve_extras) {
      if (word.rfind("-", 0) == 0) {
        const auto near = word.rfind("--", 0) == 0 ? app::nearest_name(word.substr(2), a.verify.curve.options)
                                                   : std::nullopt;
        std::cerr << "ncurve run: unexpected argument '" << nc::escape_controls(word) << "'"
                  << (near ? " (did you mean --" + *near + "?)" : "") << "\n";
        return 2;
      }
      if (!std::filesystem::exists(word, ec)) {
        std::cerr << "ncurve run: no file '" << nc::escape_controls(word) << "'\n";
        return 2;
      }
      programs.push_back(word);
    }
  if (programs.size() > 1 || std::filesystem::is_directory(a.in.program, ec)) return batch_command(a, programs);
  app::RunSetup setup;
  try {
    setup = app::prepare_run_of_any_size(a.in);
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    std::cerr << "ncurve run: " << nc::escape_controls(e.what()) << "\n";
    return 2;
  }
  const machine::MachineProfile& profile = setup.profile;
  machine::ProgramLibrary& lib = *setup.lib;
  if (const std::string why = app::plot_view_problem(profile, a.view); !why.empty()) {
    std::cerr << "ncurve run: " << why;
    return 2;
  }

  // "-o -" is the default: the output to standard output, an alarm to the terminal
  const std::string output = a.output == "-" ? std::string() : a.output;
  const bool plot_out = a.plot == "-" && output.empty();  // the drawing takes standard output
  if (plot_out && a.format != "summary") {
    std::cerr << "ncurve run: --plot - and --format " << a.format
              << " both write to standard output; write one of them to a file (-o FILE)\n";
    return 2;
  }
  if (!a.dprnt.empty() && (a.dprnt == "-" || a.dprnt == output || a.dprnt == a.html || a.dprnt == a.plot)) {
    std::cerr << "ncurve run: --dprnt needs a file of its own (not standard output, not another output's file)\n";
    return 2;
  }
  const bool html_out = a.html == "-";  // the page takes standard output
  if (html_out && (a.plot == "-" || (a.format != "summary" && output.empty()))) {
    std::cerr << "ncurve run: --html - and " << (a.plot == "-" ? "--plot -" : "--format " + a.format)
              << " both write to standard output; write one of them to a file\n";
    return 2;
  }
  if (!a.verify.part.empty() && (a.verify.part == "-" || a.verify.part == output || a.verify.part == a.html ||
                                 a.verify.part == a.plot || a.verify.part == a.dprnt)) {
    std::cerr << "ncurve run: --part needs a file of its own (not standard output, not another output's file)\n";
    return 2;
  }
  if (!a.verify.setup.empty()) setup.inputs.push_back(a.verify.setup);  // never an output
  std::optional<app::RunVerification> verify;
  if (a.verify.on()) {
    try {
      verify.emplace(a.verify, profile, lib, setup.options);
      for (const std::string& f : verify->stl_files()) setup.inputs.push_back(f);  // never an output
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      std::cerr << "ncurve run: " << nc::escape_controls(e.what()) << "\n";
      return 2;
    }
  }
  std::optional<io::OutputFile> file;
  if (!output.empty()) {
    try {
      file.emplace(output, setup.inputs);
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve run: error: " << nc::escape_controls(e.what()) << "\n";
      return 2;
    }
  }
  std::ostream& out = file ? file->stream() : std::cout;

  std::unique_ptr<machine::MoveSink> sink;
  report::GcodeWriter* gcode = nullptr;
  if (a.format == "jsonl") sink = std::make_unique<report::JsonlWriter>(out, profile);
  else if (a.format == "csv") sink = std::make_unique<report::CsvWriter>(out, profile, a.arc_tol);
  else if (a.format == "gcode") {
    auto g = std::make_unique<report::GcodeWriter>(out, profile, a.in.program == "-" ? "<stdin>" : a.in.program);
    gcode = g.get();
    sink = std::move(g);
  } else sink = std::make_unique<machine::NullSink>();
  // a file's writing on the second core, beside the run
  std::optional<report::BackgroundSink> background;
  if (a.format != "summary" && std::thread::hardware_concurrency() > 1) background.emplace(*sink);
  machine::MoveSink& written = background ? static_cast<machine::MoveSink&>(*background) : *sink;

  std::optional<report::PathPlot> plot;
  std::optional<report::TeeSink> tee;
  if (!a.plot.empty()) {
    plot.emplace(profile);
    tee.emplace(written, *plot);
  }
  std::optional<report::BackplotData> html;
  std::optional<report::TeeSink> html_tee;
  if (!a.html.empty()) {
    html.emplace(profile);
    html_tee.emplace(tee ? static_cast<machine::MoveSink&>(*tee) : written, *html);
  }
  machine::MoveSink& shown = html_tee ? static_cast<machine::MoveSink&>(*html_tee)
                             : tee    ? static_cast<machine::MoveSink&>(*tee)
                                      : written;
  std::optional<report::TeeSink> verify_tee;
  if (verify && verify->sink()) verify_tee.emplace(shown, *verify->sink());
  machine::MoveSink& target = verify_tee ? static_cast<machine::MoveSink&>(*verify_tee) : shown;
  setup.options.path_tolerance = a.arc_tol;  // G12.1/G07.1 paths as the CSV's arcs
  machine::Interpreter interp(profile, lib, setup.options);
  if (html && !setup.options.nose_centre) html->follow_nose_tip([&interp] { return interp.nose_tip_now(); });
  machine::RunResult result = interp.run(target);
  if (result.alarm) target.stopped(*result.alarm);  // a cut-off path says so at its end
  if (background) background->finish();
  if (gcode) gcode->finish();
  if (lib.streamed()) app::complete_problems(setup);  // the file is read to its end
  if (verify) {
    verify->finish(result);
    if (plot && verify->map()) plot->set_part(sim::part_grid(*verify->map()));
    if (plot && verify->section()) plot->set_section(verify->section()->polygons());
    if (html && verify->map()) {
      html->set_part(sim::part_grid(*verify->map()));
      if (verify->report().curve) html->set_deviation(report::deviation_json(*verify->report().curve));
    }
    if (html && verify->section()) html->set_part(report::lathe_part(*verify->section()));
    try {
      verify->write_part(setup.inputs);
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve run: error: " << nc::escape_controls(e.what()) << "\n";
      return 2;
    }
  }
  if (!a.dprnt.empty()) {  // what the control sent up to the end or the alarm
    try {
      io::write_file(a.dprnt, result.output.bytes, setup.inputs);
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve run: error: " << nc::escape_controls(e.what()) << "\n";
      return 2;
    }
  }

  report::RunReport rep = app::run_report(setup, a.in.program == "-" ? "<stdin>" : a.in.program, result,
                                          verify ? &verify->report() : nullptr);
  std::string summary = a.json ? report::summary_json(rep) : report::summary_text(rep);
  if (plot && !app::save_plot(a.plot, a.view, *plot, interp, rep.source, setup.inputs)) return 2;
  if (html && !app::save_html(a.html, *html, interp.variable(4006).number() == 20, rep.source,
                              a.json ? summary : report::summary_json(rep), setup.inputs))
    return 2;
  if (a.format == "summary") (plot_out || (html_out && !file) ? std::cerr : out) << summary;
  if (file) {
    try {
      file->commit();
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve run: error: " << nc::escape_controls(e.what()) << "\n";
      return 2;
    }
  }
  if (a.format == "summary") {
  } else if (file) (html_out ? std::cerr : std::cout) << summary;
  else if (!result.ok()) std::cerr << nc::format(*result.alarm) << "\n";
  return result.ok() ? 0 : 1;
}

}  // namespace

int ncurve_main(int argc, char** argv) {
  CLI::App app{app::kDescription};
  app.set_version_flag("--version", version_text());
  app::Commands c;
  app::add_commands(app, c);
  if (const std::string why = app::not_a_command(app, argc, argv); !why.empty()) {
    std::cerr << why;
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (c.completion->parsed()) {
    std::cout << app::bash_completion(app);
    return 0;
  }
  if (c.man->parsed()) {
    std::cout << app::man_page(app, NCURVE_VERSION);
    return 0;
  }
  if (c.run_command->parsed()) {
    c.run.verify.curve_extras = c.run_command->remaining();
    c.run.verify.curve.command = "ncurve run";
    c.run.verify.curve.options = app::long_options(*c.run_command);
    return run_command(c.run);
  }
  if (c.gen.command->parsed()) return app::gen_command(c.gen);
  if (c.helicoid.command->parsed()) return app::helicoid_command(c.helicoid);
  if (c.analyze.command->parsed()) return app::analyze_command(c.analyze);
  if (c.serve.command->parsed()) return app::exec_serve(argv);
  return 2;
}

int main(int argc, char** argv) { return app::guarded_main([&] { return ncurve_main(argc, argv); }); }
