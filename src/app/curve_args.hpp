// A curve named on the command line (`ncurve gen`, `ncurve analyze --curve`): a catalogue name or
// expr with --x/--y/--z/--t, and its parameters as --NAME VALUE pairs.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "geom/curve.hpp"
#include "machine/profile.hpp"

namespace ncurve::app {

struct CurveArgs {
  std::string name;  // catalogue name or "expr"
  std::string x, y, z, t_range;
  std::optional<double> from, to;
  // for messages: the command ("ncurve gen") and its long options (to suggest for a misspelt one);
  // empty: the extras are curve parameters only
  std::string command;
  std::vector<std::string> options;
};

// --curve NAME (described as `what`) and the expression's --x, --y, --z, --t, --from, --to; the
// command must allow extras (the curve's parameters as --NAME VALUE).
void add_curve_options(CLI::App* cmd, CurveArgs& a, const std::string& what);

// extras: the --NAME VALUE pairs the option parser left over: each must name a parameter of the
// curve (for expr: a name its expressions use, each of which needs a value) and give a finite
// number. Throws std::runtime_error saying what is wrong and, where one is near, what was meant.
geom::Curve build_curve(const CurveArgs& a, const std::vector<std::string>& extras,
                        const machine::MachineProfile& profile);

}  // namespace ncurve::app
