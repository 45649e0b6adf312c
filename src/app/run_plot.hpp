// ncurve run --plot / --view: the options and the writing of the drawing.
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "app/save.hpp"
#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/path_plot.hpp"

namespace ncurve::app {

inline void add_plot_options(CLI::App* run, std::string& plot, std::string& view) {
  run->add_option("--plot", plot,
                  "draw the tool path as SVG to this file (- for standard output): the machine plane, the two other "
                  "projections and an isometric view (a lathe: the ZX plane)");
  run->add_option("--view", view, "--plot: one view only: xy, xz (zx), yz or iso; a lathe without a Y axis: zx only")
      ->check(CLI::IsMember({"xy", "xz", "zx", "yz", "iso"}));
}

// Empty if --view suits the machine, else why not: a lathe without a Y axis has one plane, ZX.
inline std::string plot_view_problem(const machine::MachineProfile& profile, const std::string& view) {
  if (view.empty() || report::view_fits(profile, *report::plot_view(view))) return {};
  return "--view " + view + ": a lathe without a Y axis moves in one plane, ZX; its view is --view zx (the default), "
         "the others would draw Y, always 0\n";
}

// Writes the drawing; false, with the reason printed, if it failed.
inline bool save_plot(const std::string& path, const std::string& view, const report::PathPlot& plot,
                      machine::Interpreter& interp, const std::string& source,
                      const std::vector<std::string>& inputs) {
  report::PathPlotOptions o;
  if (!view.empty()) o.views = {*report::plot_view(view)};
  o.title = source;
  o.inch = interp.variable(4006).number() == 20;  // the program's units as it ended (G20/G21)
  return save(path, plot.svg(o), inputs);
}

}  // namespace ncurve::app
